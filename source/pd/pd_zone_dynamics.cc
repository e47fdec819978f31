#include <periarlequin/base/parallel_loops.h>
#include <periarlequin/fe/contact.h>
#include <periarlequin/pd/pd_zone.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace PeriArlequin
{
  namespace
  {
    /** Closes the bonds' window when an evaluation ends, also by an exception. */
    template <int dim>
    struct WindowCloser
    {
      BondFamilies<dim> &bonds;
      ~WindowCloser()
      {
        bonds.clear_window();
      }
    };
  } // namespace

  template <int dim>
  void
  PDZone<dim>::compute_internal_forces()
  {
    open_growth_window();
    const WindowCloser<dim> closer{bonds};
    update_ghost_displacements();
    evaluate_model();
  }

  template <int dim>
  void
  PDZone<dim>::open_growth_window()
  {
    bonds.clear_window();
    // Pending on every rank or on none (extend() and predict() are collective).
    if (!growth_window_pending)
      return;
    growth_window_pending  = false;
    evaluated_after_growth = ghosts.n_owned();
    const bool breaks_anywhere =
      fracture && !fracture_suspended && !(fracture->critical_stretch() > 0);
    if (contact || breaks_anywhere ||
        Utilities::MPI::min(growth_changes_known ? 1u : 0u, communicator) == 0)
      return;
    // The scalars change within a bond of a changed particle, the forces within a bond of a
    // changed scalar (a ghost's, from its owner).
    const unsigned int              n_owned = ghosts.n_owned(), n_total = ghosts.n_total();
    const std::vector<std::uint8_t> scalars_changed = bonds.owned_within_reach(changed_by_growth);
    std::vector<double>             flags(n_total, 0.);
    std::copy(scalars_changed.begin(), scalars_changed.end(), flags.begin());
    ghosts.update_ghosts(make_array_view(flags), 1);
    const std::vector<std::uint8_t> forces_changed =
      bonds.owned_within_reach(std::vector<bool>(flags.begin(), flags.end()));
    std::vector<std::uint8_t> window(n_total, 0);
    for (unsigned int i = 0; i < n_owned; ++i)
      window[i] = scalars_changed[i] | (forces_changed[i] << 1);
    evaluated_after_growth = std::count(forces_changed.begin(), forces_changed.end(), 1);
    bonds.restrict_to_window(std::move(window));
  }

  template <int dim>
  void
  PDZone<dim>::update_model_scalars()
  {
    model->compute_particle_scalars(bonds, state.displacements(), model_scalars);
    share_model_scalars();
  }

  template <int dim>
  void
  PDZone<dim>::share_model_scalars()
  {
    if (model->n_particle_scalars() > 0)
      ghosts.update_ghosts(make_array_view(model_scalars), model->n_particle_scalars());
  }

  template <int dim>
  void
  PDZone<dim>::evaluate_model(const bool scalars_current)
  {
    if (!scalars_current)
      update_model_scalars();
    model->compute_forces(bonds,
                          state.displacements(),
                          model_scalars,
                          state_weight,
                          force_density,
                          energy_density);
    if (contact)
      contact->add_forces(bonds,
                          ghosts.reference_positions(),
                          ghosts.ids(),
                          make_array_view(alpha),
                          state.displacements(),
                          particle_volume(),
                          force_density,
                          energy_density);
    for (const unsigned int i : unforced)
      {
        force_density[i]  = Tensor<1, dim>();
        energy_density[i] = 0.;
      }
  }

  template <int dim>
  void
  PDZone<dim>::impose_prescribed_motion(const double time)
  {
    prescribed.impose(time, time_step, state);
  }

  template <int dim>
  void
  PDZone<dim>::predict(const double dt)
  {
    // The particles move: what a growth carried over no longer holds.
    growth_window_pending = false;
    const auto u = state.displacements(), v = state.velocities();
    const auto a = state.accelerations();
    for_each_subrange(ghosts.n_owned(), [&](const unsigned int first, const unsigned int end) {
      for (unsigned int i = first; i < end; ++i)
        {
          u[i] += dt * v[i] + (0.5 * dt * dt) * a[i];
          v[i] += (0.5 * dt) * a[i];
        }
    });
  }

  template <int dim>
  Tensor<1, dim>
  PDZone<dim>::blended_load(const unsigned int i, const double time) const
  {
    return ((1. - alpha[i]) * particle_volume()) * load_density(i, time);
  }

  template <int dim>
  Tensor<1, dim>
  PDZone<dim>::load_density(const unsigned int i, const double time) const
  {
    const ProblemData<dim> &data = *problem_data;
    const Point<dim>       &x    = ghosts.reference_positions()[i];
    Tensor<1, dim>          density;
    const auto              add = [&](Function<dim> &load, const double scale) {
      load.set_time(time);
      load.vector_value(x, load_value);
      for (unsigned int d = 0; d < dim; ++d)
        density[d] += scale * load_value(d);
    };
    if (data.has_body_force)
      add(data.body_force, 1.);
    // A traction t on a face is carried by its first layer of particles: t dx^(dim-1) on a
    // particle of volume dx^dim.
    for (unsigned int b = 0; traction_faces[i] >> b; ++b)
      if (traction_faces[i] & (1u << b))
        add(*data.boundary_conditions[b].function, 1. / parameters.lattice_spacing);
    return density;
  }

  template <int dim>
  void
  PDZone<dim>::compute_forces(const double time)
  {
    open_growth_window();
    const WindowCloser<dim> closer{bonds};
    update_ghost_displacements();
    // A critical stretch is tested where the model forms the extensions for its scalars,
    // which then see the broken bonds; a criterion that reads the scalars gets them for these
    // displacements, and they stay current for the forces unless a bond broke on some rank
    // (a ghost's scalars change with bonds its own rank breaks).
    bool                    scalars_current = false;
    std::vector<StoredBond> broken;
    if (fracture && !fracture_suspended)
      {
        if (fracture->critical_stretch() > 0)
          {
            broken = model->compute_particle_scalars_breaking(bonds,
                                                              state.displacements(),
                                                              fracture->critical_stretch(),
                                                              model_scalars);
            share_model_scalars();
            scalars_current = true;
          }
        else
          {
            if (fracture->needs_particle_scalars())
              update_model_scalars();
            BreakableBonds<dim> breakable(bonds, state.displacements());
            fracture->break_bonds(breakable, make_array_view(model_scalars));
            broken = breakable.broken_bonds();
            if (!broken.empty())
              bonds.bonds_broke(broken);
            scalars_current = fracture->needs_particle_scalars() &&
                              !Utilities::MPI::logical_or(!broken.empty(), communicator);
          }
        new_damage.clear();
        const auto x = reference_positions();
        for (const StoredBond &bond : broken)
          {
            new_damage.push_back(x[bond.particle]);
            new_damage.push_back(x[bonds.neighbor(bond.particle, bond.index)]);
          }
      }
    if (checks_overlap)
      check_damage_near_overlap(time, broken);
    evaluate_model(scalars_current);
  }

  template <int dim>
  void
  PDZone<dim>::compute_accelerations(const double time)
  {
    const double rho = material.density, volume = particle_volume();
    const auto   a      = state.accelerations();
    const bool   loaded = problem_data->has_body_force || problem_data->has_tractions();
    if (!settling_force.empty() && !(time < latest_settling_start + settling_time))
      {
        settling_force.clear();
        settling_start.clear();
      }
    // The load Functions are evaluated on one thread (a user's Function need not be
    // thread-safe), at the particles they load (all under a body force, the layers under
    // loaded faces otherwise); the rest on the threads.
    const unsigned int n_owned   = ghosts.n_owned();
    const auto         is_loaded = [&](const unsigned int i) {
      return !slave[i] && (problem_data->has_body_force || traction_faces[i] != 0);
    };
    if (loaded)
      {
        load_values.resize(n_owned);
        const std::vector<unsigned int> loaded_particles = join_over_chunks<unsigned int>(
          n_owned,
          [&](const unsigned int first, const unsigned int end, std::vector<unsigned int> &list) {
            for (unsigned int i = first; i < end; ++i)
              if (is_loaded(i))
                list.push_back(i);
          });
        // Loads are blended like the mass, 1 - alpha (the FE zone takes alpha).
        for (const unsigned int i : loaded_particles)
          load_values[i] = (1. - alpha[i]) * load_density(i, time);
      }
    for_each_subrange(n_owned, [&](const unsigned int first, const unsigned int end) {
      for (unsigned int i = first; i < end; ++i)
        {
          // A slave's acceleration is that of the FE field, set by the coupling, and its
          // load acts on the FE nodes.
          if (slave[i])
            {
              applied_force[i] = Tensor<1, dim>();
              continue;
            }
          Tensor<1, dim> b = loaded && is_loaded(i) ? load_values[i] : Tensor<1, dim>();
          if (!settling_force.empty())
            b += settling_weight(i, time) * settling_force[i];
          a[i]             = (force_weight[i] * force_density[i] + b) / (rho * mass_weight[i]);
          applied_force[i] = volume * b;
        }
    });
    if (obstacle)
      push_off_obstacle();
    prescribed.restore_accelerations(state);
    // Load plus support reaction of a prescribed component: m a - f V.
    prescribed.for_each_component([&](const unsigned int i, const unsigned int d) {
      applied_force[i][d] = particle_mass(i) * a[i][d] - blended_force(i)[d];
    });
  }

  template <int dim>
  void
  PDZone<dim>::set_obstacle(Contact<dim> *model)
  {
    Assert(model == nullptr || model->acts_on_particles(),
           ExcMessage("The contact model does not act on particles."));
    obstacle = model;
    if (!obstacle)
      return;
    find_obstacle_candidates(false);
    obstacle->check_particles(communicator, 0.5 * parameters.lattice_spacing, obstacle_positions);
  }

  template <int dim>
  void
  PDZone<dim>::find_obstacle_candidates(const bool next)
  {
    const double dt = next ? time_step : 0.;
    // A particle stands for its lattice cell: its centre keeps half a spacing off the surface.
    const double           radius = 0.5 * parameters.lattice_spacing;
    const BoundingBox<dim> reach  = obstacle->reach(dt, radius);
    const Point<dim>      &lower  = reach.get_boundary_points().first,
                     &upper       = reach.get_boundary_points().second;
    const auto         x          = ghosts.reference_positions();
    const auto         u = state.displacements(), v = state.velocities(), a = state.accelerations();
    const unsigned int n_owned = ghosts.n_owned();
    // Which particles lie in the reach, on the threads (a pass over every particle, bound by
    // memory), then the few that do in the order of their numbers.
    obstacle_near.resize(n_owned);
    for_each_subrange(n_owned, [&](const unsigned int first, const unsigned int end) {
      for (unsigned int i = first; i < end; ++i)
        {
          bool inside = true;
          for (unsigned int d = 0; d < dim && inside; ++d)
            {
              const double y = x[i][d] + u[i][d] + dt * v[i][d] + (dt * dt) * a[i][d];
              inside         = y >= lower[d] && y <= upper[d];
            }
          obstacle_near[i] = inside;
        }
    });
    obstacle_candidates.clear();
    obstacle_positions.clear();
    obstacle_masses.clear();
    for (unsigned int i = 0; i < n_owned; ++i)
      if (obstacle_near[i] && alpha[i] == 0 && !slave[i] && !prescribed.contains(i))
        obstacle_candidates.push_back(i);
    // In the order of the particle ids, which a repartition or a resumed run keeps: the
    // obstacle sums its force in that order.
    const auto ids = ghosts.ids();
    std::sort(obstacle_candidates.begin(),
              obstacle_candidates.end(),
              [&](const unsigned int i, const unsigned int j) { return ids[i] < ids[j]; });
    for (const unsigned int i : obstacle_candidates)
      {
        obstacle_positions.push_back(x[i] + u[i] + dt * v[i] + (dt * dt) * a[i]);
        obstacle_masses.push_back(particle_mass(i));
      }
  }

  template <int dim>
  void
  PDZone<dim>::push_off_obstacle()
  {
    find_obstacle_candidates(true);
    obstacle->push_particles(time_step,
                             0.5 * parameters.lattice_spacing,
                             obstacle_positions,
                             obstacle_masses,
                             obstacle_pushes);
    const auto a = state.accelerations();
    for (unsigned int k = 0; k < obstacle_candidates.size(); ++k)
      a[obstacle_candidates[k]] += obstacle_pushes[k];
  }

  template <int dim>
  double
  PDZone<dim>::settling_weight(const unsigned int i, const double time) const
  {
    const double fraction = (time - settling_start[i]) / settling_time;
    if (!(fraction < 1.))
      return 0.;
    return 0.5 * (1. + std::cos(numbers::PI * std::max(fraction, 0.)));
  }

  template <int dim>
  void
  PDZone<dim>::set_settling_time(const double duration)
  {
    settling_time = duration;
  }

  template <int dim>
  void
  PDZone<dim>::start_settling(const unsigned int i, const Tensor<1, dim> &force, const double time)
  {
    Assert(settling_time > 0, ExcMessage("Set a positive settling time first."));
    Assert(!slave[i], ExcMessage("A slave follows the FE field; it cannot settle."));
    if (settling_force.empty())
      {
        settling_force.assign(ghosts.n_owned(), Tensor<1, dim>());
        settling_start.assign(ghosts.n_owned(), -std::numeric_limits<double>::infinity());
      }
    // A force that has not faded out yet fades out again from its present value.
    settling_force[i]     = settling_weight(i, time) * settling_force[i] + force;
    settling_start[i]     = time;
    latest_settling_start = std::max(latest_settling_start, time);
    state.accelerations()[i] += force / (material.density * mass_weight[i]);
    applied_force[i] += particle_volume() * force;
    tracks_work = true;
  }

  template <int dim>
  void
  PDZone<dim>::start_work_interval(const bool from_unloaded)
  {
    if (!tracks_work)
      return;
    if (from_unloaded)
      {
        previous_displacement.assign(ghosts.n_owned(), Tensor<1, dim>());
        previous_applied_force.assign(applied_force.size(), Tensor<1, dim>());
        return;
      }
    // Copies of a few MB a step in 3D: on the threads.
    const auto u = state.displacements();
    previous_displacement.resize(ghosts.n_owned());
    previous_applied_force.resize(applied_force.size());
    for_each_subrange(ghosts.n_owned(), [&](const unsigned int first, const unsigned int end) {
      std::copy(u.begin() + first, u.begin() + end, previous_displacement.begin() + first);
      std::copy(applied_force.begin() + first,
                applied_force.begin() + end,
                previous_applied_force.begin() + first);
    });
  }

  template <int dim>
  void
  PDZone<dim>::account_work()
  {
    if (!tracks_work)
      return;
    // Trapezoidal work of the applied forces over the interval.
    const auto   u = state.displacements();
    const double increment =
      sum_over_chunks<double>(ghosts.n_owned(),
                              [&](const unsigned int first, const unsigned int end) {
                                double sum = 0;
                                for (unsigned int i = first; i < end; ++i)
                                  sum += (previous_applied_force[i] + applied_force[i]) *
                                         (u[i] - previous_displacement[i]);
                                return sum;
                              });
    work += 0.5 * increment;
  }

  template <int dim>
  void
  PDZone<dim>::correct(const double dt)
  {
    const auto v = state.velocities();
    const auto a = state.accelerations();
    for_each_subrange(ghosts.n_owned(), [&](const unsigned int first, const unsigned int end) {
      for (unsigned int i = first; i < end; ++i)
        v[i] += (0.5 * dt) * a[i];
    });
    // Prescribed components keep the velocity of this time, set by impose_prescribed_motion().
    prescribed.restore_velocities(state);
  }

  namespace
  {
    /**
     * Pseudo-random value in [-1, 1) from a particle id and a component: a start vector for
     * power iterations with a component on every mode, the same on every partition.
     */
    double
    hashed_value(const types::particle_index id, const unsigned int component)
    {
      std::uint64_t h = (id * 3 + component + 1) * 0x9E3779B97F4A7C15ULL;
      h ^= h >> 31;
      h *= 0xBF58476D1CE4E5B9ULL;
      h ^= h >> 29;
      return static_cast<double>(h >> 11) / static_cast<double>(1ULL << 52) - 1.;
    }
  } // namespace

  template <int dim>
  double
  PDZone<dim>::estimate_stable_time_step(const unsigned int max_iterations)
  {
    const unsigned int                n_owned = ghosts.n_owned();
    const auto                        u       = state.displacements();
    const std::vector<Tensor<1, dim>> saved(u.begin(), u.end());
    std::vector<Tensor<1, dim>>       x(n_owned);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        x[i][d] = hashed_value(ghosts.ids()[i], d);
    const auto norm = [&](const std::vector<Tensor<1, dim>> &v) {
      double sum = 0;
      for (unsigned int i = 0; i < n_owned; ++i)
        sum += v[i] * v[i];
      return std::sqrt(Utilities::MPI::sum(sum, communicator));
    };
    // The operator is applied as -f(eps x) / (rho eps) with eps x far below the lattice
    // spacing, where the force is linear in the displacement to about 1e-8.
    double eigenvalue = 0;
    for (unsigned int it = 0; it < max_iterations; ++it)
      {
        const double scale     = 1. / norm(x);
        double       max_entry = 0;
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            x[i] *= scale;
            for (unsigned int d = 0; d < dim; ++d)
              max_entry = std::max(max_entry, std::abs(x[i][d]));
          }
        const double eps =
          1e-8 * parameters.lattice_spacing / Utilities::MPI::max(max_entry, communicator);
        for (unsigned int i = 0; i < n_owned; ++i)
          u[i] = slave[i] ? Tensor<1, dim>() : eps * x[i];
        compute_internal_forces();
        double rayleigh = 0;
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            const Tensor<1, dim> y = slave[i] ? Tensor<1, dim>() :
                                                -(force_weight[i] * force_density[i]) /
                                                  (material.density * mass_weight[i] * eps);
            rayleigh += x[i] * y;
            x[i] = y;
          }
        rayleigh             = Utilities::MPI::sum(rayleigh, communicator);
        const bool converged = std::abs(rayleigh - eigenvalue) <= 1e-6 * rayleigh;
        eigenvalue           = rayleigh;
        if (converged)
          break;
      }
    std::copy(saved.begin(), saved.end(), u.begin());
    compute_internal_forces();
    AssertThrow(eigenvalue > 0,
                ExcMessage("The PD stable-step estimate found no positive eigenvalue: does "
                           "the PD zone have bonds?"));
    // The operator was probed at rest, where no pair touches: contact adds its bound.
    if (contact)
      eigenvalue += contact->eigenvalue_bound(material.density * particle_volume());
    return 2. / std::sqrt(eigenvalue);
  }

  template <int dim>
  double
  PDZone<dim>::kinetic_energy() const
  {
    const auto   v = state.velocities();
    const double sum =
      sum_over_chunks<double>(ghosts.n_owned(),
                              [&](const unsigned int first, const unsigned int end) {
                                double chunk = 0;
                                for (unsigned int i = first; i < end; ++i)
                                  if (!slave[i])
                                    chunk += mass_weight[i] * (v[i] * v[i]);
                                return chunk;
                              });
    return 0.5 * material.density * particle_volume() * Utilities::MPI::sum(sum, communicator);
  }

  template <int dim>
  Tensor<1, dim>
  PDZone<dim>::linear_momentum() const
  {
    const auto           v = state.velocities();
    const Tensor<1, dim> sum =
      sum_over_chunks<Tensor<1, dim>>(ghosts.n_owned(),
                                      [&](const unsigned int first, const unsigned int end) {
                                        Tensor<1, dim> chunk;
                                        for (unsigned int i = first; i < end; ++i)
                                          if (!slave[i])
                                            chunk += mass_weight[i] * v[i];
                                        return chunk;
                                      });
    return material.density * particle_volume() * Utilities::MPI::sum(sum, communicator);
  }

  template <int dim>
  double
  PDZone<dim>::strain_energy() const
  {
    // With energy blending the model weighted the densities already.
    const double sum =
      sum_over_chunks<double>(ghosts.n_owned(),
                              [&](const unsigned int first, const unsigned int end) {
                                double chunk = 0;
                                for (unsigned int i = first; i < end; ++i)
                                  chunk +=
                                    (energy_blending ? 1. : 1. - alpha[i]) * energy_density[i];
                                return chunk;
                              });
    return particle_volume() * Utilities::MPI::sum(sum, communicator);
  }

  template <int dim>
  std::pair<double, double>
  PDZone<dim>::energies_in(const Region<dim> &region) const
  {
    const auto x       = ghosts.reference_positions();
    const auto v       = state.velocities();
    double     sums[2] = {0, 0};
    for (unsigned int i = 0; i < ghosts.n_owned(); ++i)
      if (region.contains(x[i]))
        {
          sums[0] += v[i] * v[i];
          sums[1] += energy_density[i];
        }
    Utilities::MPI::sum(ArrayView<const double>(sums, 2), communicator, ArrayView<double>(sums, 2));
    return {0.5 * material.density * particle_volume() * sums[0], particle_volume() * sums[1]};
  }

  template <int dim>
  double
  PDZone<dim>::external_work() const
  {
    return Utilities::MPI::sum(work, communicator);
  }

  template <int dim>
  void
  PDZone<dim>::scale_velocities(const double factor)
  {
    const auto v = state.velocities();
    for (unsigned int i = 0; i < ghosts.n_owned(); ++i)
      v[i] *= factor;
    prescribed.restore_velocities(state);
  }

  template <int dim>
  void
  PDZone<dim>::start_relaxation_step()
  {
    const auto u = state.displacements(), a = state.accelerations();
    relaxation_displacement.assign(u.begin(), u.begin() + ghosts.n_owned());
    relaxation_acceleration.assign(a.begin(), a.begin() + ghosts.n_owned());
  }

  template <int dim>
  std::pair<double, double>
  PDZone<dim>::relaxation_step_sums() const
  {
    const auto u       = state.displacements();
    const auto a       = state.accelerations();
    double     sums[2] = {0, 0};
    const auto add     = [&](const unsigned int i, const unsigned int d) {
      const double du = u[i][d] - relaxation_displacement[i][d];
      const double da = a[i][d] - relaxation_acceleration[i][d];
      sums[0] -= particle_mass(i) * du * da;
      sums[1] += particle_mass(i) * du * du;
    };
    for (unsigned int i = 0; i < ghosts.n_owned(); ++i)
      if (!slave[i])
        for (unsigned int d = 0; d < dim; ++d)
          if (!prescribed.prescribes(i, d))
            add(i, d);
    Utilities::MPI::sum(ArrayView<const double>(sums, 2), communicator, ArrayView<double>(sums, 2));
    return {sums[0], sums[1]};
  }

  template <int dim>
  std::pair<double, double>
  PDZone<dim>::squared_force_norms() const
  {
    // A slave's force acts on the FE nodes, where the FE zone counts it. The prescribed
    // components are left out, not added and taken off again: their accelerations are those
    // of the motion, which would take digits off the residual (and differ in a resumed run).
    const auto a       = state.accelerations();
    double     sums[2] = {0, 0};
    for (unsigned int i = 0; i < ghosts.n_owned(); ++i)
      {
        if (!slave[i])
          for (unsigned int d = 0; d < dim; ++d)
            if (!prescribed.prescribes(i, d))
              {
                const double residual = particle_mass(i) * a[i][d];
                sums[0] += residual * residual;
              }
        sums[1] += applied_force[i].norm_square();
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 2), communicator, ArrayView<double>(sums, 2));
    return {sums[0], sums[1]};
  }

  template <int dim>
  void
  PDZone<dim>::take_projected_residual(const double dt)
  {
    const auto          v = state.velocities();
    const auto          a = state.accelerations();
    std::vector<double> prescribed_acceleration;
    prescribed.for_each_component([&](const unsigned int i, const unsigned int d) {
      prescribed_acceleration.push_back(a[i][d]);
    });
    for (unsigned int i = 0; i < ghosts.n_owned(); ++i)
      if (!slave[i])
        a[i] = 2. / dt * v[i];
    auto kept = prescribed_acceleration.begin();
    prescribed.for_each_component(
      [&](const unsigned int i, const unsigned int d) { a[i][d] = *kept++; });
    scale_velocities(0.);
  }

  template <int dim>
  double
  PDZone<dim>::squared_residual_norm() const
  {
    const auto a   = state.accelerations();
    double     sum = 0;
    for (unsigned int i = 0; i < ghosts.n_owned(); ++i)
      if (!slave[i])
        for (unsigned int d = 0; d < dim; ++d)
          if (!prescribed.prescribes(i, d))
            sum += particle_mass(i) * a[i][d] * a[i][d];
    return Utilities::MPI::sum(sum, communicator);
  }

  template <int dim>
  void
  PDZone<dim>::update_search_direction(const double beta)
  {
    const auto a = state.accelerations();
    // A restart takes the current particles (they may have changed since the last solve).
    if (beta == 0.)
      search_direction.assign(ghosts.n_owned(), Tensor<1, dim>());
    for (unsigned int i = 0; i < ghosts.n_owned(); ++i)
      search_direction[i] = slave[i] ? Tensor<1, dim>() : a[i] + beta * search_direction[i];
    prescribed.for_each_component(
      [&](const unsigned int i, const unsigned int d) { search_direction[i][d] = 0.; });
  }

  template <int dim>
  void
  PDZone<dim>::move_along_search_direction(const double s)
  {
    const auto u = state.displacements();
    for (unsigned int i = 0; i < ghosts.n_owned(); ++i)
      u[i] = relaxation_displacement[i] + s * search_direction[i];
  }

  template <int dim>
  void
  PDZone<dim>::extrapolate_relaxation_step(const double c)
  {
    const auto u = state.displacements(), a = state.accelerations();
    for (unsigned int i = 0; i < ghosts.n_owned(); ++i)
      {
        u[i] = relaxation_displacement[i] + c * (u[i] - relaxation_displacement[i]);
        a[i] = relaxation_acceleration[i] + c * (a[i] - relaxation_acceleration[i]);
      }
  }

  template <int dim>
  void
  PDZone<dim>::suspend_fracture(const bool suspended)
  {
    fracture_suspended = suspended;
  }

  template <int dim>
  std::size_t
  PDZone<dim>::cut_bonds(const std::vector<PreCrack<dim>> &cracks,
                         const std::string                &parameter,
                         const std::string                &value)
  {
    const auto  x          = ghosts.reference_positions();
    const auto  ids        = ghosts.ids();
    std::size_t cut        = 0;
    bool        in_overlap = false;
    Point<dim>  where;
    new_damage.clear();
    for (unsigned int i = 0; i < ghosts.n_owned(); ++i)
      for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
        {
          if (bonds.state[n] == BondFamilies<dim>::broken)
            continue;
          // The ends in the order of their ids, as for pre-cracks: the ranks holding the two
          // ends decide alike.
          const unsigned int j       = bonds.neighbor(i, n);
          const bool         i_first = ids[i] < ids[j];
          const Point<dim>  &first = x[i_first ? i : j], &second = x[i_first ? j : i];
          if (std::none_of(cracks.begin(), cracks.end(), [&](const PreCrack<dim> &crack) {
                return crack.cuts(first, second);
              }))
            continue;
          if (alpha[i] > 0 || alpha[j] > 0)
            {
              in_overlap = true;
              where      = alpha[i] > 0 ? x[i] : x[j];
            }
          bonds.state[n] = BondFamilies<dim>::broken;
          new_damage.push_back(x[i]);
          new_damage.push_back(x[j]);
          cut += 1 + (j < ghosts.n_owned());
        }
    if (Utilities::MPI::logical_or(in_overlap, communicator))
      {
        std::ostringstream allowed;
        allowed << "cracks in the pure PD region, more than a bond away from the overlap";
        if (in_overlap)
          allowed << " (one cuts a bond at " << where << " m)";
        throw_invalid_parameter(parameter, value, allowed.str());
      }
    bonds.states_changed();
    find_bonds_near_overlap();
    return Utilities::MPI::sum(cut, communicator);
  }

  template class PDZone<2>;
  template class PDZone<3>;
} // namespace PeriArlequin
