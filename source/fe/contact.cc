#include <periarlequin/base/gather.h>
#include <periarlequin/base/parameters.h>
#include <periarlequin/fe/contact.h>
#include <periarlequin/fe/contact_checks.h>
#include <periarlequin/fe/fe_zone.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace PeriArlequin
{
  template <int dim>
  void
  Contact<dim>::parse_parameters(ParameterHandler &)
  {}

  template <int dim>
  bool
  Contact<dim>::acts_on_particles() const
  {
    return false;
  }

  template <int dim>
  bool
  Contact<dim>::needs_particles() const
  {
    return false;
  }

  template <int dim>
  void
  Contact<dim>::check_particles(const MPI_Comm, const double, const std::vector<Point<dim>> &)
  {}

  template <int dim>
  void
  Contact<dim>::push_particles(const double,
                               const double,
                               const std::vector<Point<dim>> &next_position,
                               const std::vector<double> &,
                               std::vector<Tensor<1, dim>> &push)
  {
    push.assign(next_position.size(), Tensor<1, dim>());
  }

  template <int dim>
  BoundingBox<dim>
  Contact<dim>::reach(const double, const double) const
  {
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = -std::numeric_limits<double>::max();
        upper[d] = std::numeric_limits<double>::max();
      }
    return BoundingBox<dim>({lower, upper});
  }

  template <int dim>
  void
  Contact<dim>::check_time_step(const double) const
  {}

  template <int dim>
  double
  Contact<dim>::obstacle_kinetic_energy() const
  {
    return 0.;
  }

  template <int dim>
  std::vector<std::pair<std::string, double>>
  Contact<dim>::history_columns() const
  {
    return {};
  }

  template <int dim>
  std::string
  Contact<dim>::save_state() const
  {
    return {};
  }

  template <int dim>
  void
  Contact<dim>::load_state(const std::string &)
  {}

  template <int dim>
  Tensor<1, dim>
  Contact<dim>::total_force() const
  {
    return Utilities::MPI::sum(local_force, communicator);
  }

  template <int dim>
  unsigned int
  Contact<dim>::n_touching_nodes() const
  {
    return Utilities::MPI::sum(local_touching, communicator);
  }

  template <int dim>
  void
  RigidWallContact<dim>::entries(ParameterEntries &entries)
  {
    entries.add("Point",
                point_text,
                Patterns::List(Patterns::Double(), dim, dim),
                "A point of the wall plane [m].");
    entries.add("Normal",
                normal_text,
                Patterns::List(Patterns::Double(), dim, dim),
                "The wall's normal, pointing to the side where the body is (not necessarily "
                "of unit length) [-].");
    entries.add("Boundary ids",
                boundary_id_list,
                Patterns::List(Patterns::Integer(0), 0),
                "The boundaries whose nodes may touch the wall; empty: all.");
  }

  template <int dim>
  void
  RigidWallContact<dim>::declare_parameters(ParameterHandler &prm)
  {
    ParameterEntries::declare_here<RigidWallContact<dim>>(prm);
  }

  template <int dim>
  void
  RigidWallContact<dim>::parse_parameters(ParameterHandler &prm)
  {
    ParameterEntries::parse_here(prm, *this, "Contact/rigid wall/");
    const auto point = Utilities::string_to_double(Utilities::split_string_list(point_text));
    const auto n     = Utilities::string_to_double(Utilities::split_string_list(normal_text));
    for (unsigned int d = 0; d < dim; ++d)
      {
        wall_point[d] = point[d];
        normal[d]     = n[d];
      }
    if (!(normal.norm() > 0))
      throw_invalid_parameter("Contact/rigid wall/Normal",
                              normal_text,
                              "a non-zero vector pointing to the body's side of the wall");
    normal /= normal.norm();
    boundary_ids = std::set<unsigned int>(boundary_id_list.begin(), boundary_id_list.end());
  }


  template <int dim>
  std::map<types::global_dof_index, BoundaryVertex<dim>>
  boundary_vertices(const FEZone<dim>            &zone,
                    const std::set<unsigned int> &boundary_ids,
                    const std::string            &parameter)
  {
    internal::check_boundary_ids(zone, boundary_ids, parameter);
    // Ghost cells too: a vertex's owner may see its boundary face only as a ghost.
    std::map<types::global_dof_index, BoundaryVertex<dim>> found;
    for (const auto &cell : zone.get_dof_handler().active_cell_iterators())
      {
        if (cell->is_artificial() || cell->get_fe().n_dofs_per_cell() == 0 || !cell->at_boundary())
          continue;
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->at_boundary(f) ||
                (!boundary_ids.empty() && boundary_ids.count(cell->face(f)->boundary_id()) == 0))
              continue;
            for (const unsigned int v : cell->face(f)->vertex_indices())
              {
                BoundaryVertex<dim> vertex;
                vertex.position = cell->face(f)->vertex(v);
                for (unsigned int d = 0; d < dim; ++d)
                  vertex.dofs[d] = cell->face(f)->vertex_dof_index(v, d, cell->active_fe_index());
                found[vertex.dofs[0]] = vertex;
              }
          }
      }
    return found;
  }

  template <int dim>
  std::vector<BoundaryFace<dim>>
  all_boundary_faces(const FEZone<dim>            &zone,
                     const std::set<unsigned int> &boundary_ids,
                     const std::string            &parameter)
  {
    internal::check_boundary_ids(zone, boundary_ids, parameter);
    // Each boundary face belongs to one owned cell: its first DoFs and positions, then the
    // outward direction, as numbers to gather.
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_face;
    std::vector<double>    mine;
    for (const auto &cell : zone.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0 && cell->at_boundary())
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f) &&
              (boundary_ids.empty() || boundary_ids.count(cell->face(f)->boundary_id())))
            {
              for (unsigned int v = 0; v < n_vertices; ++v)
                {
                  for (unsigned int d = 0; d < dim; ++d)
                    mine.push_back(cell->face(f)->vertex_dof_index(v, d, cell->active_fe_index()));
                  for (unsigned int d = 0; d < dim; ++d)
                    mine.push_back(cell->face(f)->vertex(v)[d]);
                }
              const Tensor<1, dim> outward = cell->face(f)->center() - cell->center();
              for (unsigned int d = 0; d < dim; ++d)
                mine.push_back(outward[d]);
            }
    const unsigned int vertex_width = 2 * dim, face_width = n_vertices * vertex_width + dim;
    std::vector<BoundaryFace<dim>> faces;
    for (const auto &part :
         Utilities::MPI::all_gather(zone.get_dof_handler().get_communicator(), mine))
      for (unsigned int at = 0; at + face_width <= part.size(); at += face_width)
        {
          BoundaryFace<dim> face;
          face.vertices.resize(n_vertices);
          for (unsigned int v = 0; v < n_vertices; ++v)
            for (unsigned int d = 0; d < dim; ++d)
              {
                face.vertices[v].dofs[d] =
                  static_cast<types::global_dof_index>(part[at + v * vertex_width + d]);
                face.vertices[v].position[d] = part[at + v * vertex_width + dim + d];
              }
          for (unsigned int d = 0; d < dim; ++d)
            face.outward[d] = part[at + n_vertices * vertex_width + d];
          faces.push_back(face);
        }
    return faces;
  }

  template <int dim>
  void
  GatheredBoundaryNodes<dim>::set_nodes(std::vector<BoundaryVertex<dim>> vertices,
                                        const FEZone<dim>               &zone)
  {
    node_communicator = zone.get_dof_handler().get_communicator();
    nodes             = std::move(vertices);
    std::sort(nodes.begin(), nodes.end(), [](const auto &a, const auto &b) {
      return internal::position_before(a.position, b.position);
    });
    node_of.clear();
    for (unsigned int k = 0; k < nodes.size(); ++k)
      node_of[nodes[k].dofs[0]] = k;
    const IndexSet &owned = zone.get_dof_handler().locally_owned_dofs();
    owned_nodes.clear();
    owned_dofs.clear();
    for (unsigned int k = 0; k < nodes.size(); ++k)
      if (owned.is_element(nodes[k].dofs[0]))
        {
          owned_nodes.push_back(k);
          std::array<unsigned int, dim> local;
          for (unsigned int d = 0; d < dim; ++d)
            local[d] = owned.index_within_set(nodes[k].dofs[d]);
          owned_dofs.push_back(local);
        }
    nodes_of_rank = Utilities::MPI::all_gather(node_communicator, owned_nodes);
  }

  template <int dim>
  unsigned int
  GatheredBoundaryNodes<dim>::node_index(const types::global_dof_index first_dof) const
  {
    return node_of.at(first_dof);
  }

  template <int dim>
  std::vector<double>
  GatheredBoundaryNodes<dim>::gather_node_values(const std::vector<double> &mine,
                                                 const unsigned int         width) const
  {
    const std::vector<double> all = gather_values(mine, node_communicator);
    std::vector<double>       values(nodes.size() * width, 0.);
    auto                      from = all.begin();
    for (const auto &owned : nodes_of_rank)
      for (const unsigned int k : owned)
        {
          std::copy(from, from + width, values.begin() + k * width);
          from += width;
        }
    return values;
  }

  template <int dim>
  void
  RigidWallContact<dim>::initialize(const FEZone<dim> &zone)
  {
    this->communicator = zone.get_dof_handler().get_communicator();
    internal::check_linear_elements(zone, "rigid wall");
    const IndexSet &owned = zone.get_dof_handler().locally_owned_dofs();
    nodes.clear();
    for (const auto &[first, vertex] :
         boundary_vertices(zone, boundary_ids, "Contact/rigid wall/Boundary ids"))
      if (owned.is_element(first))
        {
          Node node;
          node.position = vertex.position;
          for (unsigned int d = 0; d < dim; ++d)
            node.dofs[d] = owned.index_within_set(vertex.dofs[d]);
          nodes.push_back(node);
        }

    AssertThrow(Utilities::MPI::sum(nodes.size(), this->communicator) > 0,
                ExcMessage("Invalid input: 'Contact/rigid wall/Boundary ids' selects no FE "
                           "boundary node; allowed: ids of boundaries that carry FE cells."));

    // The body must start on the allowed side.
    const auto &u   = zone.get_state().displacement;
    double      gap = std::numeric_limits<double>::max();
    Point<dim>  worst;
    for (const auto &node : nodes)
      {
        Point<dim> x = node.position;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] += u.local_element(node.dofs[d]);
        const double g = (x - wall_point) * normal;
        if (g < gap)
          {
            gap   = g;
            worst = x;
          }
      }
    const auto least = Utilities::MPI::min_max_avg(gap, this->communicator).min;
    if (least < -1e-12 * std::max(std::abs(wall_point * normal), 1e-3))
      {
        std::ostringstream where;
        where << "a wall through the point given, with every boundary node at t = 0 on the "
              << "side the Normal points to; a node lies " << -least << " m beyond the wall";
        if (gap == least)
          where << " (at " << worst << ")";
        throw_invalid_parameter("Contact/rigid wall/Point", point_text, where.str());
      }
  }

  template <int dim>
  void
  RigidWallContact<dim>::enforce(const double                             dt,
                                 const typename Contact<dim>::VectorType &mass,
                                 const typename Contact<dim>::VectorType &u,
                                 const typename Contact<dim>::VectorType &v,
                                 typename Contact<dim>::VectorType       &a,
                                 typename Contact<dim>::VectorType       &applied_force)
  {
    this->local_force    = Tensor<1, dim>();
    this->local_touching = 0;
    for (const auto &node : nodes)
      {
        double gap = (node.position - wall_point) * normal;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const unsigned int i = node.dofs[d];
            gap += (u.local_element(i) + dt * v.local_element(i) + dt * dt * a.local_element(i)) *
                   normal[d];
          }
        if (gap >= 0)
          continue;
        ++this->local_touching;
        const double push = -gap / (dt * dt);
        for (unsigned int d = 0; d < dim; ++d)
          {
            const unsigned int i = node.dofs[d];
            a.local_element(i) += push * normal[d];
            applied_force.local_element(i) += mass.local_element(i) * push * normal[d];
            this->local_force[d] += mass.local_element(i) * push * normal[d];
          }
      }
  }

  template class Contact<2>;
  template class Contact<3>;
  template class GatheredBoundaryNodes<2>;
  template class GatheredBoundaryNodes<3>;
  template class RigidWallContact<2>;
  template class RigidWallContact<3>;
  template std::map<types::global_dof_index, BoundaryVertex<2>>
  boundary_vertices(const FEZone<2> &, const std::set<unsigned int> &, const std::string &);
  template std::map<types::global_dof_index, BoundaryVertex<3>>
  boundary_vertices(const FEZone<3> &, const std::set<unsigned int> &, const std::string &);
  template std::vector<BoundaryFace<2>>
  all_boundary_faces(const FEZone<2> &, const std::set<unsigned int> &, const std::string &);
  template std::vector<BoundaryFace<3>>
  all_boundary_faces(const FEZone<3> &, const std::set<unsigned int> &, const std::string &);
  template class PluginRegistry<Contact<2>>;
  template class PluginRegistry<Contact<3>>;

  PERIARLEQUIN_REGISTER_CONTACT(RigidWallContact,
                                "rigid wall",
                                "frictionless unilateral contact of FE boundary nodes with a "
                                "fixed plane, enforced kinematically")
} // namespace PeriArlequin
