#include <periarlequin/base/gather.h>
#include <periarlequin/fe/contact_checks.h>
#include <periarlequin/fe/fe_zone.h>
#include <periarlequin/fe/particle_face_contact.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace PeriArlequin
{
  namespace
  {
    const std::string prefix = "Contact/PD against FE/";
  } // namespace

  template <int dim>
  void
  ParticleFaceContact<dim>::entries(ParameterEntries &entries)
  {
    entries.add("Boundary ids",
                boundary_id_list,
                Patterns::List(Patterns::Integer(0), 0),
                "The boundaries of the FE cells whose faces PD particles may touch (a mesh "
                "file's physical tags; a box's faces are 0 to 2 dim - 1); empty: every "
                "boundary face of the FE cells.");
  }

  template <int dim>
  void
  ParticleFaceContact<dim>::declare_parameters(ParameterHandler &prm)
  {
    ParameterEntries::declare_here<ParticleFaceContact<dim>>(prm);
  }

  template <int dim>
  void
  ParticleFaceContact<dim>::parse_parameters(ParameterHandler &prm)
  {
    ParameterEntries::parse_here(prm, *this, prefix);
    boundary_ids = std::set<unsigned int>(boundary_id_list.begin(), boundary_id_list.end());
  }

  template <int dim>
  void
  ParticleFaceContact<dim>::initialize(const FEZone<dim> &zone)
  {
    this->communicator = zone.get_dof_handler().get_communicator();
    internal::check_linear_elements(zone, "PD against FE");
    const auto boundary = all_boundary_faces(zone, boundary_ids, prefix + "Boundary ids");
    AssertThrow(!boundary.empty(),
                ExcMessage("Invalid input: '" + prefix + "Boundary ids' = '" +
                           internal::prm_list(boundary_ids) +
                           "' selects no FE boundary face; allowed: ids of boundaries that carry "
                           "FE cells."));

    // The faces' vertices once each, sorted by position: the same list on every rank.
    std::map<types::global_dof_index, BoundaryVertex<dim>> vertices;
    for (const auto &face : boundary)
      for (const auto &vertex : face.vertices)
        vertices[vertex.dofs[0]] = vertex;
    std::vector<BoundaryVertex<dim>> unique;
    for (const auto &entry : vertices)
      unique.push_back(entry.second);
    this->set_nodes(std::move(unique), zone);
    faces.clear();
    smallest_face = std::numeric_limits<double>::max();
    largest_face  = 0;
    for (const auto &boundary_face : boundary)
      {
        Face face;
        for (unsigned int v = 0; v < face.nodes.size(); ++v)
          {
            face.nodes[v]         = this->node_index(boundary_face.vertices[v].dofs[0]);
            const Point<dim> &x_v = boundary_face.vertices[v].position;
            if (v > 0)
              smallest_face =
                std::min(smallest_face, x_v.distance(boundary_face.vertices[0].position));
            for (unsigned int w = 0; w < v; ++w)
              largest_face =
                std::max(largest_face, x_v.distance(boundary_face.vertices[w].position));
          }
        face.outward = boundary_face.outward;
        faces.push_back(face);
      }

    // Which components of the owned nodes are prescribed.
    std::set<unsigned int> prescribed;
    for (const auto &dof : zone.get_prescribed_dofs())
      prescribed.insert(dof.local_index);
    owned_prescribed.clear();
    for (const auto &local : owned_dofs)
      {
        std::array<bool, dim> fixed;
        for (unsigned int d = 0; d < dim; ++d)
          fixed[d] = prescribed.count(local[d]) > 0;
        owned_prescribed.push_back(fixed);
      }

    const auto &s    = zone.get_state();
    const auto state = gather_state(zone.lumped_mass(), s.displacement, s.velocity, s.acceleration);
    node_position.resize(nodes.size());
    for (unsigned int k = 0; k < nodes.size(); ++k)
      for (unsigned int d = 0; d < dim; ++d)
        node_position[k][d] = nodes[k].position[d] + state[k * 4 * dim + d];
    node_travel = largest_face;
    binned_position.clear();
    fe_acceleration = nullptr;
  }

  template <int dim>
  std::vector<double>
  ParticleFaceContact<dim>::gather_state(const typename Contact<dim>::VectorType &mass,
                                         const typename Contact<dim>::VectorType &u,
                                         const typename Contact<dim>::VectorType &v,
                                         const typename Contact<dim>::VectorType &a) const
  {
    const unsigned int  width = 4 * dim;
    std::vector<double> mine;
    mine.reserve(owned_nodes.size() * width);
    for (unsigned int k = 0; k < owned_nodes.size(); ++k)
      {
        for (const auto *vector : {&u, &v, &a})
          for (unsigned int d = 0; d < dim; ++d)
            mine.push_back(vector->local_element(owned_dofs[k][d]));
        for (unsigned int d = 0; d < dim; ++d)
          mine.push_back(owned_prescribed[k][d] ? 0. : 1. / mass.local_element(owned_dofs[k][d]));
      }
    return this->gather_node_values(mine, width);
  }

  template <int dim>
  void
  ParticleFaceContact<dim>::enforce(const double,
                                    const typename Contact<dim>::VectorType &mass,
                                    const typename Contact<dim>::VectorType &u,
                                    const typename Contact<dim>::VectorType &v,
                                    typename Contact<dim>::VectorType       &a,
                                    typename Contact<dim>::VectorType       &applied_force)
  {
    fe_mass         = &mass;
    fe_displacement = &u;
    fe_velocity     = &v;
    fe_acceleration = &a;
    fe_applied      = &applied_force;
  }

  template <int dim>
  bool
  ParticleFaceContact<dim>::acts_on_particles() const
  {
    return true;
  }

  template <int dim>
  bool
  ParticleFaceContact<dim>::needs_particles() const
  {
    return true;
  }

  template <int dim>
  std::array<long long, dim>
  ParticleFaceContact<dim>::bin_of(const Point<dim> &x) const
  {
    std::array<long long, dim> bin;
    for (unsigned int d = 0; d < dim; ++d)
      bin[d] = static_cast<long long>(std::floor(x[d] / bin_size));
    return bin;
  }

  template <int dim>
  void
  ParticleFaceContact<dim>::bin_faces(const std::vector<Point<dim>> &x_nodes, const double within)
  {
    // The bins hold each face where it lies within the reach and a skin; they are rebuilt
    // only when the reach grew or a node has moved by more than the skin since.
    const double skin = 0.25 * largest_face;
    bool         keep = !binned_position.empty() && within <= binned_within;
    for (unsigned int k = 0; k < x_nodes.size() && keep; ++k)
      keep = x_nodes[k].distance(binned_position[k]) <= skin;
    if (keep)
      return;
    binned_position    = x_nodes;
    binned_within      = within;
    const double reach = within + skin;
    // Bins of about a face: a face's box widened by the reach spans a few of them.
    bin_size = largest_face + 2. * reach;
    bins.clear();
    for (unsigned int f = 0; f < faces.size(); ++f)
      {
        Point<dim> lower = x_nodes[faces[f].nodes[0]], upper = lower;
        for (const unsigned int k : faces[f].nodes)
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] = std::min(lower[d], x_nodes[k][d] - reach);
              upper[d] = std::max(upper[d], x_nodes[k][d] + reach);
            }
        const auto                 first = bin_of(lower), last = bin_of(upper);
        std::array<long long, dim> bin = first;
        while (true)
          {
            bins[bin].push_back(f);
            unsigned int d = 0;
            for (; d < dim; ++d)
              {
                if (++bin[d] <= last[d])
                  break;
                bin[d] = first[d];
              }
            if (d == dim)
              break;
          }
      }
  }

  template <int dim>
  typename ParticleFaceContact<dim>::NearestFace
  ParticleFaceContact<dim>::nearest_face(const Point<dim>              &x,
                                         const std::vector<Point<dim>> &x_nodes,
                                         const double                   within) const
  {
    NearestFace nearest;
    const auto  bin = bins.find(bin_of(x));
    if (bin == bins.end())
      return nearest;
    std::array<Point<dim>, GeometryInfo<dim>::vertices_per_face> vertices;
    for (const unsigned int f : bin->second)
      {
        // A point farther than @p within from the face's box has no foot near enough.
        bool beyond = false;
        for (unsigned int d = 0; d < dim && !beyond; ++d)
          {
            double lower = x_nodes[faces[f].nodes[0]][d], upper = lower;
            for (const unsigned int k : faces[f].nodes)
              {
                lower = std::min(lower, x_nodes[k][d]);
                upper = std::max(upper, x_nodes[k][d]);
              }
            beyond = x[d] < lower - within || x[d] > upper + within;
          }
        if (beyond)
          continue;
        for (unsigned int v = 0; v < vertices.size(); ++v)
          vertices[v] = x_nodes[faces[f].nodes[v]];
        const auto foot = internal::foot_on_face(vertices, x, faces[f].outward);
        // Behind the face by more than half a face: another side of the body is nearer.
        if (!foot || foot->distance > within || !(foot->distance > -0.5 * smallest_face))
          continue;
        if (nearest.face == numbers::invalid_unsigned_int ||
            std::abs(foot->distance) < std::abs(nearest.distance))
          {
            static_cast<internal::FaceFoot<dim> &>(nearest) = *foot;
            nearest.face                                    = f;
          }
      }
    return nearest;
  }

  template <int dim>
  void
  ParticleFaceContact<dim>::check_particles(const MPI_Comm                 communicator,
                                            const double                   radius,
                                            const std::vector<Point<dim>> &positions)
  {
    AssertThrow(!nodes.empty(),
                ExcMessage("Invalid input: 'Contact/Model' = PD against FE needs FE cells with "
                           "boundary faces (Peridynamics/Region covers the whole mesh); allowed: "
                           "a case with FE and PD cells, or 'rigid projectile' in pure PD."));
    bin_faces(node_position, radius);
    double     deepest = 0;
    Point<dim> where;
    for (const Point<dim> &x : positions)
      {
        const NearestFace foot = nearest_face(x, node_position, radius);
        if (foot.face != numbers::invalid_unsigned_int && foot.distance - radius < deepest)
          {
            deepest = foot.distance - radius;
            where   = x;
          }
      }
    const double least = Utilities::MPI::min(deepest, communicator);
    if (!(least < -1e-9 * smallest_face))
      return;
    std::ostringstream allowed;
    allowed << "FE faces with every PD particle at least half a lattice spacing (its contact "
            << "radius) in front of them at t = 0 (mesh the PD body and the FE body that "
            << "apart); a particle lies " << -least << " m too close";
    if (deepest == least)
      allowed << " (at " << where << ")";
    throw_invalid_parameter(prefix + "Boundary ids",
                            boundary_ids.empty() ? "(all)" : internal::prm_list(boundary_ids),
                            allowed.str());
  }

  template <int dim>
  BoundingBox<dim>
  ParticleFaceContact<dim>::reach(const double time_step, const double radius) const
  {
    if (node_position.empty())
      return Contact<dim>::reach(time_step, radius);
    // A particle is paired within two radii of a face's next position, which lies within two
    // steps' travel of the positions of the last step (a face's size before the first); a
    // tenth of the smallest face more for a travel that grows from one step to the next.
    Point<dim> lower = node_position[0], upper = lower;
    for (const Point<dim> &x : node_position)
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = std::min(lower[d], x[d]);
          upper[d] = std::max(upper[d], x[d]);
        }
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] -= 2. * radius + 3. * node_travel + 0.1 * smallest_face;
        upper[d] += 2. * radius + 3. * node_travel + 0.1 * smallest_face;
      }
    return BoundingBox<dim>({lower, upper});
  }

  template <int dim>
  void
  ParticleFaceContact<dim>::push_particles(const double                   dt,
                                           const double                   radius,
                                           const std::vector<Point<dim>> &next_position,
                                           const std::vector<double>     &mass,
                                           std::vector<Tensor<1, dim>>   &push)
  {
    AssertThrow(fe_acceleration != nullptr,
                ExcMessage("ParticleFaceContact: the FE zone must compute its accelerations "
                           "(enforce()) before the PD zone pushes its particles."));
    const unsigned int        width = 4 * dim;
    const std::vector<double> state =
      gather_state(*fe_mass, *fe_displacement, *fe_velocity, *fe_acceleration);
    std::vector<Point<dim>>     x_nodes(nodes.size());
    std::vector<Tensor<1, dim>> inverse_mass(nodes.size());
    node_travel = 0;
    for (unsigned int k = 0; k < nodes.size(); ++k)
      {
        const double *s = &state[k * width];
        for (unsigned int d = 0; d < dim; ++d)
          {
            node_position[k][d] = nodes[k].position[d] + s[d];
            x_nodes[k][d]       = node_position[k][d] + dt * s[dim + d] + dt * dt * s[2 * dim + d];
            inverse_mass[k][d]  = s[3 * dim + d];
          }
        node_travel = std::max(node_travel, x_nodes[k].distance(node_position[k]));
      }

    // This rank's particles in front of a face, within a radius of touching; then every
    // rank's, on all ranks.
    const unsigned int n_face_vertices = GeometryInfo<dim>::vertices_per_face;
    const unsigned int pair_width      = 2 * dim + n_face_vertices + 4;
    bin_faces(x_nodes, 2. * radius);
    const unsigned int  my_rank = Utilities::MPI::this_mpi_process(this->communicator);
    std::vector<double> mine;
    for (unsigned int p = 0; p < next_position.size(); ++p)
      {
        const NearestFace foot = nearest_face(next_position[p], x_nodes, 2. * radius);
        if (foot.face == numbers::invalid_unsigned_int)
          continue;
        for (unsigned int d = 0; d < dim; ++d)
          mine.push_back(next_position[p][d]);
        mine.push_back(mass[p]);
        mine.push_back(my_rank);
        mine.push_back(p);
        mine.push_back(foot.face);
        mine.insert(mine.end(), foot.weights.begin(), foot.weights.end());
        for (unsigned int d = 0; d < dim; ++d)
          mine.push_back(foot.normal[d]);
      }
    struct Pair
    {
      Point<dim>                                               x;
      double                                                   inverse_mass;
      unsigned int                                             rank, particle, face;
      std::array<double, GeometryInfo<dim>::vertices_per_face> weights;
      Tensor<1, dim>                                           normal;
    };
    std::vector<Pair>         pairs;
    const std::vector<double> all = gather_values(mine, this->communicator);
    for (unsigned int at = 0; at + pair_width <= all.size(); at += pair_width)
      {
        const double *data = &all[at];
        Pair          pair;
        for (unsigned int d = 0; d < dim; ++d)
          pair.x[d] = data[d];
        pair.inverse_mass = 1. / data[dim];
        pair.rank         = static_cast<unsigned int>(data[dim + 1]);
        pair.particle     = static_cast<unsigned int>(data[dim + 2]);
        pair.face         = static_cast<unsigned int>(data[dim + 3]);
        std::copy(data + dim + 4, data + dim + 4 + n_face_vertices, pair.weights.begin());
        for (unsigned int d = 0; d < dim; ++d)
          pair.normal[d] = data[dim + 4 + n_face_vertices + d];
        pairs.push_back(pair);
      }
    std::sort(pairs.begin(), pairs.end(), [](const Pair &a, const Pair &b) {
      return internal::position_before(a.x, b.x);
    });

    // Gauss-Seidel over the pairs. The moves, dt^2 lambda n / m_p for a particle and dt^2 f / m
    // for a node under its contact force f, are kept apart from the positions (their
    // difference of positions would lose digits).
    std::vector<Tensor<1, dim>> node_force(nodes.size());
    std::vector<double>         compliance(pairs.size()), lambda(pairs.size(), 0.);
    const auto                  node_move = [&](const unsigned int k) {
      Tensor<1, dim> move;
      for (unsigned int d = 0; d < dim; ++d)
        move[d] = dt * dt * node_force[k][d] * inverse_mass[k][d];
      return move;
    };
    for (unsigned int q = 0; q < pairs.size(); ++q)
      {
        compliance[q] = pairs[q].inverse_mass;
        for (unsigned int j = 0; j < n_face_vertices; ++j)
          for (unsigned int d = 0; d < dim; ++d)
            compliance[q] += pairs[q].weights[j] * pairs[q].weights[j] * pairs[q].normal[d] *
                             pairs[q].normal[d] * inverse_mass[faces[pairs[q].face].nodes[j]][d];
      }
    const auto gap = [&](const unsigned int q) {
      const Pair    &pair = pairs[q];
      Tensor<1, dim> g =
        (pair.x - Point<dim>()) + dt * dt * pair.inverse_mass * lambda[q] * pair.normal;
      for (unsigned int j = 0; j < n_face_vertices; ++j)
        {
          const unsigned int k = faces[pair.face].nodes[j];
          g -= pair.weights[j] * ((x_nodes[k] - Point<dim>()) + node_move(k));
        }
      return g * pair.normal - radius;
    };
    for (unsigned int sweep = 0; sweep < 100; ++sweep)
      {
        double largest = 0;
        for (unsigned int q = 0; q < pairs.size(); ++q)
          {
            const double change = std::max(-lambda[q], -gap(q) / (dt * dt * compliance[q]));
            if (change == 0)
              continue;
            lambda[q] += change;
            for (unsigned int j = 0; j < n_face_vertices; ++j)
              node_force[faces[pairs[q].face].nodes[j]] -=
                pairs[q].weights[j] * change * pairs[q].normal;
            largest = std::max(largest, std::abs(change) * dt * dt * compliance[q]);
          }
        if (largest <= 1e-12 * smallest_face)
          break;
      }

    // This rank's particles, and its FE nodes: a free component moves, a prescribed one's
    // support takes the force (its reaction, M a + F_int - F_interface, less the contact force).
    push.assign(next_position.size(), Tensor<1, dim>());
    this->local_force    = Tensor<1, dim>();
    this->local_touching = 0;
    for (unsigned int q = 0; q < pairs.size(); ++q)
      if (pairs[q].rank == my_rank)
        {
          push[pairs[q].particle] = pairs[q].inverse_mass * lambda[q] * pairs[q].normal;
          if (lambda[q] > 0)
            {
              this->local_force += lambda[q] * pairs[q].normal;
              ++this->local_touching;
            }
        }
    for (unsigned int n = 0; n < owned_nodes.size(); ++n)
      for (unsigned int d = 0; d < dim; ++d)
        {
          const unsigned int k = owned_nodes[n], i = owned_dofs[n][d];
          if (owned_prescribed[n][d])
            fe_applied->local_element(i) -= node_force[k][d];
          else
            fe_acceleration->local_element(i) += node_force[k][d] * inverse_mass[k][d];
        }
    fe_acceleration = nullptr;
  }

  template class ParticleFaceContact<2>;
  template class ParticleFaceContact<3>;

  PERIARLEQUIN_REGISTER_CONTACT(ParticleFaceContact,
                                "PD against FE",
                                "frictionless unilateral contact between PD particles and FE "
                                "boundary faces of the mesh, enforced kinematically, "
                                "momentum-conserving")
} // namespace PeriArlequin
