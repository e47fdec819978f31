#include <deal.II/base/mpi.h>

#include <periarlequin/base/parameters.h>
#include <periarlequin/fe/contact.h>
#include <periarlequin/fe/fe_zone.h>

#include <cmath>
#include <map>
#include <sstream>

namespace PeriArlequin
{
  template <int dim>
  void
  Contact<dim>::parse_parameters(ParameterHandler &)
  {}

  template <int dim>
  void
  RigidWallContact<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Point",
                      dim == 2 ? "0, 0" : "0, 0, 0",
                      Patterns::List(Patterns::Double(), dim, dim),
                      "A point of the wall plane [m].");
    prm.declare_entry("Normal",
                      dim == 2 ? "-1, 0" : "-1, 0, 0",
                      Patterns::List(Patterns::Double(), dim, dim),
                      "The wall's normal, pointing to the side where the body is (not "
                      "necessarily of unit length) [-].");
    prm.declare_entry("Boundary ids",
                      "",
                      Patterns::List(Patterns::Integer(0), 0),
                      "The boundaries whose nodes may touch the wall; empty: all.");
  }

  template <int dim>
  void
  RigidWallContact<dim>::parse_parameters(ParameterHandler &prm)
  {
    point_text       = prm.get("Point");
    const auto point = Utilities::string_to_double(Utilities::split_string_list(point_text));
    const auto n = Utilities::string_to_double(Utilities::split_string_list(prm.get("Normal")));
    for (unsigned int d = 0; d < dim; ++d)
      {
        wall_point[d] = point[d];
        normal[d]     = n[d];
      }
    if (!(normal.norm() > 0))
      throw_invalid_parameter("Contact/rigid wall/Normal",
                              prm.get("Normal"),
                              "a non-zero vector pointing to the body's side of the wall");
    normal /= normal.norm();
    boundary_ids.clear();
    for (const int id : Utilities::string_to_int(Utilities::split_string_list(prm.get("Boundary ids"))))
      boundary_ids.insert(id);
  }

  template <int dim>
  void
  RigidWallContact<dim>::initialize(const FEZone<dim> &zone)
  {
    communicator = zone.get_dof_handler().get_communicator();
    const unsigned int n_faces = 2 * dim;
    for (const unsigned int id : boundary_ids)
      if (id >= n_faces)
        throw_invalid_parameter("Contact/rigid wall/Boundary ids",
                                std::to_string(id),
                                "ids of the box's faces, 0 to " + std::to_string(n_faces - 1) +
                                  " (x faces 0/1, y 2/3, z 4/5), or empty for all");

    // The owned boundary nodes: a vertex's dim DoFs, one per component (FE_Q(1)^dim), found
    // from the vertex itself so that the grouping is exact.
    const IndexSet &owned = zone.get_dof_handler().locally_owned_dofs();
    std::map<types::global_dof_index, Node> found;
    for (const auto &cell : zone.get_dof_handler().active_cell_iterators())
      {
        if (!cell->is_locally_owned() || cell->get_fe().n_dofs_per_cell() == 0 ||
            !cell->at_boundary())
          continue;
        AssertThrow(cell->get_fe().degree == 1,
                    ExcMessage("Invalid input: 'Contact/Model' = rigid wall needs 'Finite "
                               "elements/Polynomial degree' = 1 (lumped vertex masses)."));
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->at_boundary(f) ||
                (!boundary_ids.empty() && boundary_ids.count(cell->face(f)->boundary_id()) == 0))
              continue;
            for (const unsigned int v : cell->face(f)->vertex_indices())
              {
                const auto first = cell->face(f)->vertex_dof_index(v, 0, cell->active_fe_index());
                if (!owned.is_element(first))
                  continue;
                Node node;
                node.position = cell->face(f)->vertex(v);
                for (unsigned int d = 0; d < dim; ++d)
                  node.dofs[d] = owned.index_within_set(
                    cell->face(f)->vertex_dof_index(v, d, cell->active_fe_index()));
                found[first] = node;
              }
          }
      }
    nodes.clear();
    for (const auto &entry : found)
      nodes.push_back(entry.second);

    AssertThrow(Utilities::MPI::sum(nodes.size(), communicator) > 0,
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
    const auto least = Utilities::MPI::min_max_avg(gap, communicator).min;
    if (least < -1e-12 * std::max(std::abs(wall_point * normal), 1e-3))
      {
        std::ostringstream where;
        where << "a wall through the point given, with every boundary node at t = 0 on the "
              << "side the Normal points to; a node lies " << -least
              << " m beyond the wall";
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
    local_force    = Tensor<1, dim>();
    local_touching = 0;
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
        ++local_touching;
        const double push = -gap / (dt * dt);
        for (unsigned int d = 0; d < dim; ++d)
          {
            const unsigned int i = node.dofs[d];
            a.local_element(i) += push * normal[d];
            applied_force.local_element(i) += mass.local_element(i) * push * normal[d];
            local_force[d] += mass.local_element(i) * push * normal[d];
          }
      }
  }

  template <int dim>
  Tensor<1, dim>
  RigidWallContact<dim>::total_force() const
  {
    return Utilities::MPI::sum(local_force, communicator);
  }

  template <int dim>
  unsigned int
  RigidWallContact<dim>::n_touching_nodes() const
  {
    return Utilities::MPI::sum(local_touching, communicator);
  }

  template class Contact<2>;
  template class Contact<3>;
  template class RigidWallContact<2>;
  template class RigidWallContact<3>;
  template class PluginRegistry<Contact<2>>;
  template class PluginRegistry<Contact<3>>;

  PERIARLEQUIN_REGISTER_CONTACT(RigidWallContact,
                                "rigid wall",
                                "frictionless unilateral contact of FE boundary nodes with a "
                                "fixed plane, enforced kinematically")
} // namespace PeriArlequin
