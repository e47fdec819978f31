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

  template <int dim>
  void
  ElasticTargetContact<dim>::initialize(const FEZone<dim> &zone)
  {
    this->communicator = zone.get_dof_handler().get_communicator();
    internal::check_linear_elements(zone, "elastic target");
    const IndexSet    &owned           = zone.get_dof_handler().locally_owned_dofs();
    const unsigned int n_face_vertices = GeometryInfo<dim>::vertices_per_face;

    // Every rank's owned striker vertices, gathered on all ranks, and the target's faces.
    std::vector<double> mine;
    for (const auto &[first, vertex] :
         boundary_vertices(zone, striker_ids, "Contact/elastic target/Striker boundary ids"))
      if (owned.is_element(first))
        {
          for (unsigned int d = 0; d < dim; ++d)
            mine.push_back(vertex.dofs[d]);
          for (unsigned int d = 0; d < dim; ++d)
            mine.push_back(vertex.position[d]);
        }
    std::map<types::global_dof_index, BoundaryVertex<dim>> striker, target;
    for (const auto &part : Utilities::MPI::all_gather(this->communicator, mine))
      for (unsigned int at = 0; at + 2 * dim <= part.size(); at += 2 * dim)
        {
          BoundaryVertex<dim> vertex;
          for (unsigned int d = 0; d < dim; ++d)
            {
              vertex.dofs[d]     = static_cast<types::global_dof_index>(part[at + d]);
              vertex.position[d] = part[at + dim + d];
            }
          striker[vertex.dofs[0]] = vertex;
        }
    struct Face
    {
      std::vector<types::global_dof_index> first_dofs;
      std::vector<Point<dim>>              vertices;
      Tensor<1, dim>                       outward;
    };
    std::vector<Face> target_faces;
    for (const auto &boundary_face :
         all_boundary_faces(zone, target_ids, "Contact/elastic target/Target boundary ids"))
      {
        Face face;
        for (const auto &vertex : boundary_face.vertices)
          {
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
        face.outward = boundary_face.outward;
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

    std::vector<BoundaryVertex<dim>> involved;
    for (const auto *set : {&striker, &target})
      for (const auto &entry : *set)
        involved.push_back(entry.second);
    this->set_nodes(std::move(involved), zone);

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
            const auto foot =
              internal::foot_on_face(face.vertices, nodes[k].position, face.outward);
            if (!foot)
              continue;
            const double distance = foot->distance;
            if (std::abs(distance) < std::abs(best))
              {
                best         = distance;
                pair.striker = k;
                pair.normal  = foot->normal;
                pair.face_nodes.clear();
                for (const auto first : face.first_dofs)
                  pair.face_nodes.push_back(this->node_index(first));
                pair.weights.assign(foot->weights.begin(), foot->weights.end());
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
    state = this->gather_node_values(mine, width);
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
