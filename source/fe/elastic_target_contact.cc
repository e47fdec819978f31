#include <periarlequin/fe/contact.h>
#include <periarlequin/fe/contact_checks.h>
#include <periarlequin/fe/fe_zone.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace PeriArlequin
{
  template <int dim>
  void
  ElasticTargetContact<dim>::entries(ParameterEntries &entries)
  {
    entries.add("Striker boundary ids",
                striker_id_list,
                Patterns::List(Patterns::Integer(0), 0),
                "The boundaries of the moving body whose vertices may touch the target (a "
                "mesh file's physical tags; a box's faces are 0 to 2 dim - 1).");
    entries.add("Target boundary ids",
                target_id_list,
                Patterns::List(Patterns::Integer(0), 0),
                "The boundaries of the target whose faces the striker may touch; they must "
                "belong to another body than the striker's (no shared vertex).");
  }

  template <int dim>
  void
  ElasticTargetContact<dim>::declare_parameters(ParameterHandler &prm)
  {
    ParameterEntries::declare_here<ElasticTargetContact<dim>>(prm);
  }

  template <int dim>
  void
  ElasticTargetContact<dim>::parse_parameters(ParameterHandler &prm)
  {
    ParameterEntries::parse_here(prm, *this, "Contact/elastic target/");
    const auto as_set = [](const std::string &name, const std::vector<unsigned int> &list) {
      if (list.empty())
        throw_invalid_parameter("Contact/elastic target/" + name,
                                "",
                                "a non-empty list of boundary ids");
      return std::set<unsigned int>(list.begin(), list.end());
    };
    striker_ids = as_set("Striker boundary ids", striker_id_list);
    target_ids  = as_set("Target boundary ids", target_id_list);
    for (const unsigned int id : striker_ids)
      if (target_ids.count(id))
        throw_invalid_parameter("Contact/elastic target/Target boundary ids",
                                std::to_string(id),
                                "ids other than the striker's (the two bodies' contact "
                                "boundaries must differ)");
  }

  namespace
  {
    /** Positions in lexicographic order (x first), to sort nodes the same on every partition. */
    template <int dim>
    bool
    position_before(const Point<dim> &a, const Point<dim> &b)
    {
      for (int d = dim - 1; d >= 0; --d)
        if (a[d] != b[d])
          return a[d] < b[d];
      return false;
    }

    /** The shape values of a Q1 face (2 or 4 vertices, deal.II's order) at @p xi. */
    template <int dim>
    std::vector<double>
    face_shape_values(const std::array<double, 2> &xi)
    {
      if (dim == 2)
        return {1 - xi[0], xi[0]};
      return {(1 - xi[0]) * (1 - xi[1]), xi[0] * (1 - xi[1]), (1 - xi[0]) * xi[1], xi[0] * xi[1]};
    }

    /**
     * The closest point of a Q1 face (@p x its vertices) to @p p: its face coordinates,
     * found by Gauss-Newton (exact in one step on a parallelogram), and the face's unit
     * normal there, oriented along @p outward.
     */
    template <int dim>
    std::pair<std::array<double, 2>, Tensor<1, dim>>
    project_onto_face(const std::vector<Point<dim>> &x,
                      const Point<dim>              &p,
                      const Tensor<1, dim>          &outward)
    {
      std::array<double, 2>         xi = {{0.5, 0.5}};
      std::array<Tensor<1, dim>, 2> tangent;
      for (unsigned int iteration = 0; iteration < 20; ++iteration)
        {
          Point<dim> position;
          const auto N = face_shape_values<dim>(xi);
          for (unsigned int j = 0; j < x.size(); ++j)
            position += N[j] * Tensor<1, dim>(x[j]);
          if (dim == 2)
            tangent[0] = x[1] - x[0];
          else
            {
              tangent[0] = (1 - xi[1]) * (x[1] - x[0]) + xi[1] * (x[3] - x[2]);
              tangent[1] = (1 - xi[0]) * (x[2] - x[0]) + xi[0] * (x[3] - x[1]);
            }
          const Tensor<1, dim>  r    = p - position;
          std::array<double, 2> step = {{0, 0}};
          if (dim == 2)
            step[0] = (r * tangent[0]) / (tangent[0] * tangent[0]);
          else
            {
              const double a = tangent[0] * tangent[0], b = tangent[0] * tangent[1],
                           c = tangent[1] * tangent[1], det = a * c - b * b;
              const double r0 = r * tangent[0], r1 = r * tangent[1];
              step[0] = (c * r0 - b * r1) / det;
              step[1] = (a * r1 - b * r0) / det;
            }
          xi[0] += step[0];
          xi[1] += step[1];
          if (std::abs(step[0]) + std::abs(step[1]) < 1e-14)
            break;
        }
      Tensor<1, dim> normal;
      if constexpr (dim == 2)
        normal = Tensor<1, dim>({tangent[0][1], -tangent[0][0]});
      else
        normal = cross_product_3d(tangent[0], tangent[1]);
      normal /= normal.norm();
      if (normal * outward < 0)
        normal *= -1;
      return {xi, normal};
    }
  } // namespace

  template <int dim>
  void
  ElasticTargetContact<dim>::initialize(const FEZone<dim> &zone)
  {
    this->communicator = zone.get_dof_handler().get_communicator();
    internal::check_linear_elements(zone, "elastic target");
    const IndexSet    &owned           = zone.get_dof_handler().locally_owned_dofs();
    const unsigned int n_face_vertices = GeometryInfo<dim>::vertices_per_face;

    // Every rank's owned striker vertices and owned target faces (each boundary face belongs
    // to one owned cell), gathered on all ranks.
    std::vector<double> mine;
    const auto          add_vertex = [&](const BoundaryVertex<dim> &vertex) {
      for (unsigned int d = 0; d < dim; ++d)
        mine.push_back(vertex.dofs[d]);
      for (unsigned int d = 0; d < dim; ++d)
        mine.push_back(vertex.position[d]);
    };
    for (const auto &[first, vertex] :
         boundary_vertices(zone, striker_ids, "Contact/elastic target/Striker boundary ids"))
      if (owned.is_element(first))
        add_vertex(vertex);
    std::vector<double> faces;
    internal::check_boundary_ids(zone, target_ids, "Contact/elastic target/Target boundary ids");
    for (const auto &cell : zone.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0 && cell->at_boundary())
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f) && target_ids.count(cell->face(f)->boundary_id()))
            {
              for (unsigned int v = 0; v < n_face_vertices; ++v)
                {
                  for (unsigned int d = 0; d < dim; ++d)
                    faces.push_back(cell->face(f)->vertex_dof_index(v, d, cell->active_fe_index()));
                  for (unsigned int d = 0; d < dim; ++d)
                    faces.push_back(cell->face(f)->vertex(v)[d]);
                }
              const Tensor<1, dim> outward = cell->face(f)->center() - cell->center();
              for (unsigned int d = 0; d < dim; ++d)
                faces.push_back(outward[d]);
            }
    const auto all_striker = Utilities::MPI::all_gather(this->communicator, mine);
    const auto all_faces   = Utilities::MPI::all_gather(this->communicator, faces);

    // The striker vertices, then the target's vertices, as one sorted list of nodes.
    const unsigned int vertex_width = 2 * dim, face_width = n_face_vertices * vertex_width + dim;
    const auto         read_vertex = [&](const std::vector<double> &data, const unsigned int at) {
      BoundaryVertex<dim> vertex;
      for (unsigned int d = 0; d < dim; ++d)
        {
          vertex.dofs[d]     = static_cast<types::global_dof_index>(data[at + d]);
          vertex.position[d] = data[at + dim + d];
        }
      return vertex;
    };
    std::map<types::global_dof_index, BoundaryVertex<dim>> striker, target;
    for (const auto &part : all_striker)
      for (unsigned int at = 0; at + vertex_width <= part.size(); at += vertex_width)
        {
          const auto vertex       = read_vertex(part, at);
          striker[vertex.dofs[0]] = vertex;
        }
    struct Face
    {
      std::vector<types::global_dof_index> first_dofs;
      std::vector<Point<dim>>              vertices;
      Tensor<1, dim>                       outward;
    };
    std::vector<Face> target_faces;
    for (const auto &part : all_faces)
      for (unsigned int at = 0; at + face_width <= part.size(); at += face_width)
        {
          Face face;
          for (unsigned int v = 0; v < n_face_vertices; ++v)
            {
              const auto vertex = read_vertex(part, at + v * vertex_width);
              if (striker.count(vertex.dofs[0]))
                throw_invalid_parameter("Contact/elastic target/Target boundary ids",
                                        internal::prm_list(target_ids),
                                        "boundaries of another body than the striker's: "
                                        "the target shares a vertex with the striker's "
                                        "boundary (mesh the two bodies apart)");
              target[vertex.dofs[0]] = vertex;
              face.first_dofs.push_back(vertex.dofs[0]);
              face.vertices.push_back(vertex.position);
            }
          for (unsigned int d = 0; d < dim; ++d)
            face.outward[d] = part[at + n_face_vertices * vertex_width + d];
          target_faces.push_back(face);
        }
    AssertThrow(!striker.empty(),
                ExcMessage("Invalid input: 'Contact/elastic target/Striker boundary ids' "
                           "selects no FE boundary vertex; allowed: ids of boundaries that "
                           "carry FE cells."));
    AssertThrow(!target_faces.empty(),
                ExcMessage("Invalid input: 'Contact/elastic target/Target boundary ids' "
                           "selects no FE boundary face; allowed: ids of boundaries that "
                           "carry FE cells."));

    nodes.clear();
    for (const auto *set : {&striker, &target})
      for (const auto &entry : *set)
        nodes.push_back(entry.second);
    std::sort(nodes.begin(), nodes.end(), [](const auto &a, const auto &b) {
      return position_before(a.position, b.position);
    });
    std::map<types::global_dof_index, unsigned int> node_of;
    for (unsigned int k = 0; k < nodes.size(); ++k)
      node_of[nodes[k].dofs[0]] = k;

    // Pair each striker vertex with the face it projects onto, the nearest if several.
    face_size = std::numeric_limits<double>::max();
    for (const auto &face : target_faces)
      for (unsigned int v = 1; v < n_face_vertices; ++v)
        face_size = std::min(face_size, face.vertices[v].distance(face.vertices[0]));
    pairs.clear();
    for (unsigned int k = 0; k < nodes.size(); ++k)
      {
        if (!striker.count(nodes[k].dofs[0]))
          continue;
        double best = std::numeric_limits<double>::max();
        Pair   pair;
        for (const auto &face : target_faces)
          {
            const auto [xi, normal] =
              project_onto_face(face.vertices, nodes[k].position, face.outward);
            const double tolerance = 1e-10;
            if (xi[0] < -tolerance || xi[0] > 1 + tolerance ||
                (dim == 3 && (xi[1] < -tolerance || xi[1] > 1 + tolerance)))
              continue;
            const auto N = face_shape_values<dim>(xi);
            Point<dim> foot;
            for (unsigned int j = 0; j < n_face_vertices; ++j)
              foot += N[j] * Tensor<1, dim>(face.vertices[j]);
            const double distance = (nodes[k].position - foot) * normal;
            if (std::abs(distance) < std::abs(best))
              {
                best         = distance;
                pair.striker = k;
                pair.normal  = normal;
                pair.face_nodes.clear();
                for (const auto first : face.first_dofs)
                  pair.face_nodes.push_back(node_of[first]);
                pair.weights = N;
              }
          }
        if (best != std::numeric_limits<double>::max())
          pairs.push_back(pair);
      }
    AssertThrow(!pairs.empty(),
                ExcMessage("Invalid input: no vertex of 'Contact/elastic target/Striker "
                           "boundary ids' lies in front of a face of 'Target boundary ids' "
                           "(contact pairs a striker vertex with the target face it projects "
                           "onto, in the reference configuration); allowed: boundaries that "
                           "face each other."));

    // Which nodes this rank owns, and every rank's list, in the order of the gathered values.
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
    nodes_of_rank = Utilities::MPI::all_gather(this->communicator, owned_nodes);
    striker_owned_here.assign(nodes.size(), false);
    for (const unsigned int k : owned_nodes)
      striker_owned_here[k] = striker.count(nodes[k].dofs[0]) > 0;

    // The bodies must start apart.
    std::vector<double> state;
    const auto         &s = zone.get_state();
    gather_state(zone.lumped_mass(), s.displacement, s.velocity, s.acceleration, state);
    const std::vector<Point<dim>> x = positions(state, 0.);
    for (const auto &pair : pairs)
      {
        const double gap = pair_gap(pair, x);
        if (gap < -1e-9 * face_size)
          {
            std::ostringstream where;
            where << "boundaries of two bodies that are apart at t = 0: the striker's vertex at "
                  << nodes[pair.striker].position << " lies " << -gap << " m inside the target";
            throw_invalid_parameter("Contact/elastic target/Striker boundary ids",
                                    internal::prm_list(striker_ids),
                                    where.str());
          }
      }
  }

  template <int dim>
  void
  ElasticTargetContact<dim>::gather_state(const typename Contact<dim>::VectorType &mass,
                                          const typename Contact<dim>::VectorType &u,
                                          const typename Contact<dim>::VectorType &v,
                                          const typename Contact<dim>::VectorType &a,
                                          std::vector<double>                     &state) const
  {
    const unsigned int  width = 3 * dim + 1;
    std::vector<double> mine;
    mine.reserve(owned_nodes.size() * width);
    for (const auto &local : owned_dofs)
      {
        for (const auto *vector : {&u, &v, &a})
          for (unsigned int d = 0; d < dim; ++d)
            mine.push_back(vector->local_element(local[d]));
        mine.push_back(mass.local_element(local[0]));
      }
    const auto all = Utilities::MPI::all_gather(this->communicator, mine);
    state.assign(nodes.size() * width, 0.);
    for (unsigned int rank = 0; rank < all.size(); ++rank)
      for (unsigned int k = 0; k < nodes_of_rank[rank].size(); ++k)
        std::copy(all[rank].begin() + k * width,
                  all[rank].begin() + (k + 1) * width,
                  state.begin() + nodes_of_rank[rank][k] * width);
  }

  template <int dim>
  std::vector<Point<dim>>
  ElasticTargetContact<dim>::positions(const std::vector<double> &state, const double dt) const
  {
    const unsigned int      width = 3 * dim + 1;
    std::vector<Point<dim>> x(nodes.size());
    for (unsigned int k = 0; k < nodes.size(); ++k)
      for (unsigned int d = 0; d < dim; ++d)
        x[k][d] = nodes[k].position[d] + state[k * width + d] + dt * state[k * width + dim + d] +
                  dt * dt * state[k * width + 2 * dim + d];
    return x;
  }

  template <int dim>
  double
  ElasticTargetContact<dim>::pair_gap(const Pair &pair, const std::vector<Point<dim>> &x) const
  {
    Tensor<1, dim> gap = x[pair.striker] - Point<dim>();
    for (unsigned int j = 0; j < pair.face_nodes.size(); ++j)
      gap -= pair.weights[j] * (x[pair.face_nodes[j]] - Point<dim>());
    return gap * pair.normal;
  }

  template <int dim>
  void
  ElasticTargetContact<dim>::enforce(const double                             dt,
                                     const typename Contact<dim>::VectorType &mass,
                                     const typename Contact<dim>::VectorType &u,
                                     const typename Contact<dim>::VectorType &v,
                                     typename Contact<dim>::VectorType       &a,
                                     typename Contact<dim>::VectorType       &applied_force)
  {
    std::vector<double> state;
    gather_state(mass, u, v, a, state);
    const auto mass_of = [&](const unsigned int k) { return state[k * (3 * dim + 1) + 3 * dim]; };
    // The next positions, moved by the contact forces as the sweeps find them, and the moves
    // themselves (kept apart: their difference of positions would lose digits).
    std::vector<Point<dim>>     x = positions(state, dt);
    std::vector<Tensor<1, dim>> shift(nodes.size());
    std::vector<double>         compliance(pairs.size());
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        compliance[p] = 1. / mass_of(pairs[p].striker);
        for (unsigned int j = 0; j < pairs[p].face_nodes.size(); ++j)
          compliance[p] +=
            pairs[p].weights[j] * pairs[p].weights[j] / mass_of(pairs[p].face_nodes[j]);
      }

    std::vector<double> lambda(pairs.size(), 0.);
    for (unsigned int sweep = 0; sweep < 100; ++sweep)
      {
        double largest = 0;
        for (unsigned int p = 0; p < pairs.size(); ++p)
          {
            const Pair  &pair = pairs[p];
            const double change =
              std::max(-lambda[p], -pair_gap(pair, x) / (dt * dt * compliance[p]));
            if (change == 0)
              continue;
            lambda[p] += change;
            const Tensor<1, dim> impulse = dt * dt * change * pair.normal;
            const auto           move    = [&](const unsigned int k, const Tensor<1, dim> &by) {
              x[k] += by;
              shift[k] += by;
            };
            move(pair.striker, impulse / mass_of(pair.striker));
            for (unsigned int j = 0; j < pair.face_nodes.size(); ++j)
              move(pair.face_nodes[j], -pair.weights[j] * impulse / mass_of(pair.face_nodes[j]));
            largest = std::max(largest, std::abs(change) * dt * dt * compliance[p]);
          }
        if (largest <= 1e-12 * face_size)
          break;
      }

    this->local_force    = Tensor<1, dim>();
    this->local_touching = 0;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      if (lambda[p] > 0 && striker_owned_here[pairs[p].striker])
        {
          this->local_force += lambda[p] * pairs[p].normal;
          ++this->local_touching;
        }
    for (unsigned int k = 0; k < owned_nodes.size(); ++k)
      {
        const Tensor<1, dim> &change = shift[owned_nodes[k]];
        for (unsigned int d = 0; d < dim; ++d)
          {
            const unsigned int i = owned_dofs[k][d];
            a.local_element(i) += change[d] / (dt * dt);
            applied_force.local_element(i) += mass.local_element(i) * change[d] / (dt * dt);
          }
      }
  }

  template class ElasticTargetContact<2>;
  template class ElasticTargetContact<3>;

  PERIARLEQUIN_REGISTER_CONTACT(ElasticTargetContact,
                                "elastic target",
                                "frictionless unilateral contact between two FE bodies of the "
                                "mesh (striker vertices against target faces), enforced "
                                "kinematically, momentum-conserving")
} // namespace PeriArlequin
