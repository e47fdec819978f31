#include <periarlequin/fe/contact_checks.h>
#include <periarlequin/fe/fe_zone.h>
#include <periarlequin/fe/rigid_projectile.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

namespace PeriArlequin
{
  namespace
  {
    template <int dim>
    const SelectionNames<typename RigidProjectile<dim>::Shape> shape_names = {
      {"sphere", RigidProjectile<dim>::Shape::sphere},
      {"cylinder", RigidProjectile<dim>::Shape::cylinder},
      {"flat punch", RigidProjectile<dim>::Shape::flat_punch}};

    const std::string prefix = "Contact/rigid projectile/";

    template <int dim>
    Tensor<1, dim>
    uniform(const double value)
    {
      Tensor<1, dim> t;
      for (unsigned int d = 0; d < dim; ++d)
        t[d] = value;
      return t;
    }

    /** A vector as a parameter file gives it: "x, y(, z)". */
    template <int dim>
    std::string
    as_entry(const Tensor<1, dim> &vector)
    {
      std::ostringstream text;
      for (unsigned int d = 0; d < dim; ++d)
        text << (d > 0 ? ", " : "") << vector[d];
      return text.str();
    }
  } // namespace

  template <int dim>
  RigidProjectile<dim>::RigidProjectile()
    : half_sizes(uniform<dim>(0.005))
  {
    axis[dim - 1] = 1;
  }

  template <int dim>
  void
  RigidProjectile<dim>::entries(ParameterEntries &entries)
  {
    entries.add("Shape",
                shape,
                shape_names<dim>,
                "sphere: a ball of the Radius (a disc in 2D); cylinder: a circular cylinder "
                "of the Radius along the Axis, unbounded in length (in 2D the same as a "
                "disc: the section of a cylinder in plane strain or stress); flat punch: a "
                "box of the Half sizes along x, y (, z), flat faces with sharp edges.");
    entries.add("Radius", radius, Patterns::Double(0), "Radius of a sphere or cylinder [m].");
    entries.add("Axis",
                axis,
                Patterns::List(Patterns::Double(), dim, dim),
                "Direction of a cylinder's axis in 3D (not necessarily of unit length; "
                "ignored in 2D) [-].");
    entries.add("Half sizes",
                half_sizes,
                Patterns::List(Patterns::Double(0), dim, dim),
                "Half the edge lengths of a flat punch along x, y (, z) [m].");
    entries.add("Mass",
                mass,
                Patterns::Double(0),
                "Mass of the projectile [kg; kg/m in 2D, per unit thickness like the bodies]. "
                "A very large mass drives it at its initial velocity whatever it meets.");
    entries.add("Position",
                position,
                Patterns::List(Patterns::Double(), dim, dim),
                "Centre at t = 0 [m]; every body must lie outside the projectile then.");
    entries.add("Velocity",
                velocity,
                Patterns::List(Patterns::Double(), dim, dim),
                "Velocity at t = 0 [m/s].");
    entries.add("Boundary ids",
                boundary_id_list,
                Patterns::List(Patterns::Integer(0), 0),
                "The FE boundaries whose nodes may touch the projectile; empty: all. PD "
                "particles of the pure PD part always may.");
  }

  template <int dim>
  void
  RigidProjectile<dim>::declare_parameters(ParameterHandler &prm)
  {
    ParameterEntries::declare_here<RigidProjectile<dim>>(prm);
  }

  template <int dim>
  void
  RigidProjectile<dim>::parse_parameters(ParameterHandler &prm)
  {
    ParameterEntries::parse_here(prm, *this, prefix);
    if (!(mass > 0))
      throw_invalid_parameter(prefix + "Mass", mass, "a positive mass");
    if (shape != Shape::flat_punch && !(radius > 0))
      throw_invalid_parameter(prefix + "Radius", radius, "a positive radius");
    if (shape == Shape::flat_punch)
      for (unsigned int d = 0; d < dim; ++d)
        if (!(half_sizes[d] > 0))
          throw_invalid_parameter(prefix + "Half sizes",
                                  half_sizes[d],
                                  "positive half sizes along every axis");
    if (shape == Shape::cylinder && dim == 3)
      {
        if (!(axis.norm() > 0))
          throw_invalid_parameter(prefix + "Axis", 0., "a non-zero direction");
        axis /= axis.norm();
      }
    boundary_ids = std::set<unsigned int>(boundary_id_list.begin(), boundary_id_list.end());
    acceleration = Tensor<1, dim>();
    started      = false;
  }

  template <int dim>
  double
  RigidProjectile<dim>::signed_distance(const Tensor<1, dim> &y, Tensor<1, dim> &normal) const
  {
    if (shape == Shape::flat_punch)
      {
        // Inside: the nearest face. Outside: the nearest point of the box.
        Tensor<1, dim> outside;
        double         deepest = -std::numeric_limits<double>::max();
        unsigned int   face    = 0;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double q = std::abs(y[d]) - half_sizes[d];
            outside[d]     = q > 0 ? std::copysign(q, y[d]) : 0.;
            if (q > deepest)
              {
                deepest = q;
                face    = d;
              }
          }
        if (deepest < 0)
          {
            normal       = Tensor<1, dim>();
            normal[face] = y[face] < 0 ? -1. : 1.;
            return deepest;
          }
        const double distance = outside.norm();
        normal                = outside / distance;
        return distance;
      }
    // A sphere, or a cylinder: the part of y across the axis.
    Tensor<1, dim> across = y;
    if (shape == Shape::cylinder && dim == 3)
      across -= (y * axis) * axis;
    const double r = across.norm();
    normal         = Tensor<1, dim>();
    if (r > 0)
      normal = across / r;
    else
      normal[0] = 1.;
    return r - radius;
  }

  template <int dim>
  bool
  RigidProjectile<dim>::push_out(const Tensor<1, dim> &y,
                                 const double          point_radius,
                                 const double          dt,
                                 Tensor<1, dim>       &push) const
  {
    Tensor<1, dim> n;
    const double   gap = signed_distance(y, n) - point_radius;
    if (gap >= 0)
      return false;
    push = (-gap / (dt * dt)) * n;
    return true;
  }

  template <int dim>
  Point<dim>
  RigidProjectile<dim>::next_centre(const double dt) const
  {
    return position + dt * velocity + (dt * dt) * acceleration;
  }

  template <int dim>
  void
  RigidProjectile<dim>::check_starts_outside(const std::vector<Point<dim>> &positions,
                                             const double                   particle_radius) const
  {
    double     deepest = 0;
    Point<dim> where;
    for (const Point<dim> &x : positions)
      {
        Tensor<1, dim> n;
        const double   g = signed_distance(x - position, n) - particle_radius;
        if (g < deepest)
          {
            deepest = g;
            where   = x;
          }
      }
    const double least = Utilities::MPI::min(deepest, this->communicator);
    const double scale = shape == Shape::flat_punch ? half_sizes.norm() : radius;
    if (!(least < -1e-12 * scale))
      return;
    std::ostringstream allowed;
    allowed << "a centre with every body outside the projectile at t = 0 (PD particles count "
            << "with half a lattice spacing around them); a point lies " << -least << " m inside";
    if (deepest == least)
      allowed << " (at " << where << ")";
    throw_invalid_parameter(prefix + "Position", as_entry(position), allowed.str());
  }

  template <int dim>
  void
  RigidProjectile<dim>::initialize(const FEZone<dim> &zone)
  {
    this->communicator = zone.get_dof_handler().get_communicator();
    internal::check_linear_elements(zone, "rigid projectile");
    const IndexSet &owned = zone.get_dof_handler().locally_owned_dofs();
    const auto     &u     = zone.get_state().displacement;
    nodes.clear();
    for (const auto &[first, vertex] :
         boundary_vertices(zone, boundary_ids, prefix + "Boundary ids"))
      if (owned.is_element(first))
        {
          std::array<unsigned int, dim> dofs;
          for (unsigned int d = 0; d < dim; ++d)
            dofs[d] = owned.index_within_set(vertex.dofs[d]);
          nodes.emplace_back(dofs, vertex.position);
        }
    if (started)
      return;
    // Every vertex of the FE bodies, not only those that may touch, at its position now:
    // a projectile inside a body (or a body inside it) is refused.
    std::vector<Point<dim>> vertices;
    for (const auto &cell : zone.get_dof_handler().active_cell_iterators())
      if (!cell->is_artificial() && cell->get_fe().n_dofs_per_cell() > 0)
        for (const unsigned int v : cell->vertex_indices())
          if (owned.is_element(cell->vertex_dof_index(v, 0, cell->active_fe_index())))
            {
              Point<dim> x = cell->vertex(v);
              for (unsigned int d = 0; d < dim; ++d)
                x[d] += u.local_element(
                  owned.index_within_set(cell->vertex_dof_index(v, d, cell->active_fe_index())));
              vertices.push_back(x);
            }
    check_starts_outside(vertices, 0.);
  }

  template <int dim>
  void
  RigidProjectile<dim>::enforce(const double                             dt,
                                const typename Contact<dim>::VectorType &mass_vector,
                                const typename Contact<dim>::VectorType &u,
                                const typename Contact<dim>::VectorType &v,
                                typename Contact<dim>::VectorType       &a,
                                typename Contact<dim>::VectorType &)
  {
    const Point<dim> centre = next_centre(dt);
    on_nodes                = Exerted();
    for (const auto &[dofs, reference] : nodes)
      {
        Point<dim> next = reference;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const unsigned int i = dofs[d];
            next[d] += u.local_element(i) + dt * v.local_element(i) + dt * dt * a.local_element(i);
          }
        Tensor<1, dim> push;
        if (!push_out(next - centre, 0., dt, push))
          continue;
        Tensor<1, dim> force;
        for (unsigned int d = 0; d < dim; ++d)
          {
            a.local_element(dofs[d]) += push[d];
            force[d] = mass_vector.local_element(dofs[d]) * push[d];
          }
        on_nodes.add(force, next - centre);
      }
  }

  template <int dim>
  Tensor<1, dim>
  RigidProjectile<dim>::total_force() const
  {
    return exerted_force;
  }

  template <int dim>
  unsigned int
  RigidProjectile<dim>::n_touching_nodes() const
  {
    return touching_points;
  }

  template <int dim>
  bool
  RigidProjectile<dim>::acts_on_particles() const
  {
    return true;
  }

  template <int dim>
  void
  RigidProjectile<dim>::check_particles(const MPI_Comm                 communicator,
                                        const double                   particle_radius,
                                        const std::vector<Point<dim>> &positions)
  {
    this->communicator = communicator;
    if (!started)
      check_starts_outside(positions, particle_radius);
  }

  template <int dim>
  void
  RigidProjectile<dim>::push_particles(const double                   dt,
                                       const double                   particle_radius,
                                       const std::vector<Point<dim>> &next_position,
                                       const std::vector<double>     &particle_mass,
                                       std::vector<Tensor<1, dim>>   &push)
  {
    const Point<dim> centre = next_centre(dt);
    push.assign(next_position.size(), Tensor<1, dim>());
    on_particles = Exerted();
    for (unsigned int k = 0; k < next_position.size(); ++k)
      {
        if (push_out(next_position[k] - centre, particle_radius, dt, push[k]))
          on_particles.add(particle_mass[k] * push[k], next_position[k] - centre);
      }
  }

  template <int dim>
  BoundingBox<dim>
  RigidProjectile<dim>::reach(const double dt, const double particle_radius) const
  {
    Tensor<1, dim> extent = shape == Shape::flat_punch ? half_sizes : uniform<dim>(radius);
    extent += uniform<dim>(particle_radius);
    if (shape == Shape::cylinder && dim == 3)
      for (unsigned int d = 0; d < dim; ++d)
        if (axis[d] != 0)
          extent[d] = std::numeric_limits<double>::max() / 4;
    const Point<dim> centre = next_centre(dt);
    return BoundingBox<dim>({centre - extent, centre + extent});
  }

  template <int dim>
  double
  RigidProjectile<dim>::obstacle_kinetic_energy() const
  {
    return kinetic_energy();
  }

  template <int dim>
  std::vector<std::pair<std::string, double>>
  RigidProjectile<dim>::history_columns() const
  {
    const char                                 *axes[3] = {"x", "y", "z"};
    std::vector<std::pair<std::string, double>> columns;
    for (unsigned int d = 0; d < dim; ++d)
      columns.emplace_back(std::string("projectile_") + axes[d], position[d]);
    for (unsigned int d = 0; d < dim; ++d)
      columns.emplace_back(std::string("projectile_velocity_") + axes[d], velocity[d]);
    columns.emplace_back("projectile_kinetic_energy", kinetic_energy());
    columns.emplace_back("projectile_contact_radius", contact_radius);
    return columns;
  }

  template <int dim>
  std::string
  RigidProjectile<dim>::save_state() const
  {
    // The doubles' bytes: the motion restored exactly.
    std::array<double, 3 * dim> values;
    for (unsigned int d = 0; d < dim; ++d)
      {
        values[d]           = position[d];
        values[dim + d]     = velocity[d];
        values[2 * dim + d] = acceleration[d];
      }
    return std::string(reinterpret_cast<const char *>(values.data()), sizeof(values));
  }

  template <int dim>
  void
  RigidProjectile<dim>::load_state(const std::string &state)
  {
    std::array<double, 3 * dim> values;
    AssertThrow(state.size() == sizeof(values),
                ExcMessage("The checkpoint holds no rigid projectile state."));
    std::memcpy(values.data(), state.data(), sizeof(values));
    for (unsigned int d = 0; d < dim; ++d)
      {
        position[d]     = values[d];
        velocity[d]     = values[dim + d];
        acceleration[d] = values[2 * dim + d];
      }
    started = true;
  }

  template <int dim>
  std::string
  RigidProjectile<dim>::name() const
  {
    return "projectile";
  }

  template <int dim>
  void
  RigidProjectile<dim>::predict(const double dt)
  {
    position += dt * velocity + (0.5 * dt * dt) * acceleration;
    velocity += (0.5 * dt) * acceleration;
    started = true;
  }

  template <int dim>
  void
  RigidProjectile<dim>::check_time_step(const double dt) const
  {
    // Faster, it could pass a point of a body between two steps without ever holding it.
    const double size = shape == Shape::flat_punch ?
                          *std::min_element(half_sizes.begin_raw(), half_sizes.end_raw()) :
                          radius;
    if (velocity.norm() * dt <= size)
      return;
    std::ostringstream allowed;
    allowed << "a speed that moves the projectile by less than its smallest half size or "
            << "radius (" << size << " m) in a time step (" << dt << " s): below " << size / dt
            << " m/s";
    throw_invalid_parameter(prefix + "Velocity", as_entry(velocity), allowed.str());
  }

  template <int dim>
  void
  RigidProjectile<dim>::impose_prescribed_motion(const double)
  {}

  template <int dim>
  void
  RigidProjectile<dim>::compute_forces(const double)
  {}

  template <int dim>
  void
  RigidProjectile<dim>::Exerted::add(const Tensor<1, dim> &f, const Tensor<1, dim> &r)
  {
    force += f;
    magnitude += f.norm();
    second_moment += f.norm() * outer_product(r, r);
    ++touching;
  }

  template <int dim>
  void
  RigidProjectile<dim>::compute_accelerations(const double)
  {
    // One sum over the ranks: force, magnitudes, touching points, second moment.
    constexpr unsigned int n_sums        = dim + 2 + dim * dim;
    double                 sums[n_sums]  = {};
    const unsigned int     moment_offset = dim + 2;
    for (const Exerted *exerted : {&on_nodes, &on_particles})
      {
        for (unsigned int d = 0; d < dim; ++d)
          sums[d] += exerted->force[d];
        sums[dim] += exerted->magnitude;
        sums[dim + 1] += exerted->touching;
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int e = 0; e < dim; ++e)
            sums[moment_offset + d * dim + e] += exerted->second_moment[d][e];
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, n_sums),
                        this->communicator,
                        ArrayView<double>(sums, n_sums));
    Tensor<1, dim> force;
    Tensor<2, dim> moment;
    for (unsigned int d = 0; d < dim; ++d)
      {
        force[d] = sums[d];
        for (unsigned int e = 0; e < dim; ++e)
          moment[d][e] = sums[moment_offset + d * dim + e];
      }
    exerted_force   = force;
    touching_points = static_cast<unsigned int>(sums[dim + 1]);
    acceleration    = -force / mass;
    contact_radius  = 0;
    if (sums[dim] > 0 && force.norm() > 0)
      {
        const Tensor<1, dim> along = force / force.norm();
        contact_radius =
          std::sqrt(std::max(trace(moment) - along * (moment * along), 0.) / sums[dim]);
      }
  }

  template <int dim>
  void
  RigidProjectile<dim>::correct(const double dt)
  {
    velocity += (0.5 * dt) * acceleration;
  }

  template <int dim>
  void
  RigidProjectile<dim>::start_work_interval(const bool)
  {}

  template <int dim>
  void
  RigidProjectile<dim>::account_work()
  {}

  template <int dim>
  double
  RigidProjectile<dim>::kinetic_energy() const
  {
    return 0.5 * mass * velocity.norm_square();
  }

  template <int dim>
  double
  RigidProjectile<dim>::strain_energy() const
  {
    return 0.;
  }

  template <int dim>
  double
  RigidProjectile<dim>::external_work() const
  {
    return 0.;
  }

  template <int dim>
  void
  RigidProjectile<dim>::scale_velocities(const double factor)
  {
    velocity *= factor;
  }

  template <int dim>
  void
  RigidProjectile<dim>::start_relaxation_step()
  {}

  template <int dim>
  std::pair<double, double>
  RigidProjectile<dim>::relaxation_step_sums() const
  {
    return {0., 0.};
  }

  template <int dim>
  std::pair<double, double>
  RigidProjectile<dim>::squared_force_norms() const
  {
    return {0., 0.};
  }

  template <int dim>
  void
  RigidProjectile<dim>::take_projected_residual(const double)
  {
    velocity = 0;
  }

  template <int dim>
  double
  RigidProjectile<dim>::squared_residual_norm() const
  {
    return 0.;
  }

  template <int dim>
  void
  RigidProjectile<dim>::update_search_direction(const double)
  {}

  template <int dim>
  void
  RigidProjectile<dim>::move_along_search_direction(const double)
  {}

  template <int dim>
  void
  RigidProjectile<dim>::extrapolate_relaxation_step(const double)
  {}

  template <int dim>
  const Point<dim> &
  RigidProjectile<dim>::get_position() const
  {
    return position;
  }

  template <int dim>
  const Tensor<1, dim> &
  RigidProjectile<dim>::get_velocity() const
  {
    return velocity;
  }

  template class RigidProjectile<2>;
  template class RigidProjectile<3>;

  PERIARLEQUIN_REGISTER_CONTACT(RigidProjectile,
                                "rigid projectile",
                                "a rigid sphere, cylinder or flat punch of given mass and "
                                "velocity striking FE boundary nodes and PD particles, enforced "
                                "kinematically")
} // namespace PeriArlequin
