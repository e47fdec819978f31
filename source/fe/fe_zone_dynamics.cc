// FEZone: the state and its velocity-Verlet parts (eq. 58-61), prescribed boundary motion and
// the work of loads and support reactions. Assembly and operators are in fe_zone.cc.
#include <periarlequin/base/parallel_loops.h>
#include <periarlequin/fe/fe_zone.h>

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/fe/fe_values.h>

#include <limits>

namespace PeriArlequin
{
  namespace
  {
    /** A vector field given as a tensor-valued function object, for interpolation. */
    template <int dim>
    class VectorField : public Function<dim>
    {
    public:
      explicit VectorField(std::function<Tensor<1, dim>(const Point<dim> &)> field)
        : Function<dim>(dim)
        , field(std::move(field))
      {}

      double
      value(const Point<dim> &x, const unsigned int component) const override
      {
        return field(x)[component];
      }

      void
      vector_value(const Point<dim> &x, Vector<double> &values) const override
      {
        const Tensor<1, dim> t = field(x);
        for (unsigned int d = 0; d < dim; ++d)
          values(d) = t[d];
      }

    private:
      std::function<Tensor<1, dim>(const Point<dim> &)> field;
    };
  } // namespace

  template <int dim>
  void
  FEZone<dim>::initialize_state(const ProblemData<dim> &data, const double dt)
  {
    problem_data = &data;
    time_step    = dt;
    for (VectorType *v : {&state.displacement,
                          &state.velocity,
                          &state.acceleration,
                          &internal_force,
                          &applied_force,
                          &previous_applied_force,
                          &previous_displacement,
                          &interface_force})
      initialize_vector(*v);
    find_prescribed_dofs(data);
    tracks_work = data.has_body_force || data.has_tractions() ||
                  Utilities::MPI::logical_or(!prescribed.empty(), communicator);
    work = 0;

    const InitialCondition<dim> &initial = *data.initial_condition;
    interpolate(VectorField<dim>([&](const Point<dim> &x) { return initial.displacement(x); }),
                state.displacement);
    interpolate(VectorField<dim>([&](const Point<dim> &x) { return initial.velocity(x); }),
                state.velocity);
  }

  template <int dim>
  std::string
  FEZone<dim>::name() const
  {
    return "FE";
  }

  template <int dim>
  void
  FEZone<dim>::predict(const double dt)
  {
    state.displacement.add(dt, state.velocity, 0.5 * dt * dt, state.acceleration);
    state.velocity.add(0.5 * dt, state.acceleration);
  }

  template <int dim>
  void
  FEZone<dim>::impose_prescribed_motion(const double t)
  {
    const double dt = time_step;
    prescribed_velocity.resize(prescribed.size());
    prescribed_acceleration.resize(prescribed.size());
    TimeFactors<dim> time_factors(t, dt);
    for (unsigned int k = 0; k < prescribed.size(); ++k)
      {
        const auto  &dof      = prescribed[k];
        auto        &function = *problem_data->boundary_conditions[dof.boundary_id].function;
        const double times[3] = {t - dt, t, t + dt};
        const auto   value    = [&](const unsigned int which) {
          if (dof.separable)
            return time_factors(*dof.separable)[which] * dof.spatial_value;
          function.set_time(times[which]);
          return function.value(dof.location, dof.component);
        };
        const double before = value(0), now = value(1), after = value(2);
        prescribed_velocity[k]                            = (after - before) / (2. * dt);
        prescribed_acceleration[k]                        = (after - 2. * now + before) / (dt * dt);
        state.displacement.local_element(dof.local_index) = now;
        state.velocity.local_element(dof.local_index)     = prescribed_velocity[k];
        state.acceleration.local_element(dof.local_index) = prescribed_acceleration[k];
      }
  }

  template <int dim>
  void
  FEZone<dim>::compute_forces(const double t)
  {
    compute_internal_force(state.displacement, internal_force);
    if (!nodal_force_weights.empty())
      for_each_subrange(internal_force.locally_owned_size(),
                        [&](const unsigned int first, const unsigned int end) {
                          for (unsigned int i = first; i < end; ++i)
                            internal_force.local_element(i) *= nodal_force_weights[i];
                        });
    interface_force = 0.;
    compute_external_force(*problem_data, t, applied_force);
  }

  template <int dim>
  typename FEZone<dim>::VectorType &
  FEZone<dim>::interface_forces()
  {
    return interface_force;
  }

  template <int dim>
  typename FEZone<dim>::VectorType &
  FEZone<dim>::applied_forces()
  {
    return applied_force;
  }

  template <int dim>
  const typename FEZone<dim>::VectorType &
  FEZone<dim>::applied_forces() const
  {
    return applied_force;
  }

  template <int dim>
  void
  FEZone<dim>::compute_accelerations(const double)
  {
    for_each_subrange(mass.locally_owned_size(),
                      [&](const unsigned int first, const unsigned int end) {
                        for (unsigned int i = first; i < end; ++i)
                          state.acceleration.local_element(i) =
                            (applied_force.local_element(i) - internal_force.local_element(i) +
                             interface_force.local_element(i)) /
                            mass.local_element(i);
                      });
    if (contact)
      contact->enforce(time_step,
                       mass,
                       state.displacement,
                       state.velocity,
                       state.acceleration,
                       applied_force);
    // Prescribed DoFs keep their prescribed acceleration; their applied force takes the
    // support reaction M a + F_int - F_interface.
    for (unsigned int k = 0; k < prescribed.size(); ++k)
      {
        const unsigned int i                = prescribed[k].local_index;
        state.acceleration.local_element(i) = prescribed_acceleration[k];
        applied_force.local_element(i)      = mass.local_element(i) * prescribed_acceleration[k] +
                                         internal_force.local_element(i) -
                                         interface_force.local_element(i);
      }
  }

  template <int dim>
  void
  FEZone<dim>::correct(const double dt)
  {
    state.velocity.add(0.5 * dt, state.acceleration);
    for (unsigned int k = 0; k < prescribed.size(); ++k)
      state.velocity.local_element(prescribed[k].local_index) = prescribed_velocity[k];
  }

  template <int dim>
  void
  FEZone<dim>::start_work_interval(const bool from_unloaded)
  {
    if (!tracks_work)
      return;
    if (from_unloaded)
      {
        previous_displacement  = 0.;
        previous_applied_force = 0.;
        return;
      }
    previous_displacement  = state.displacement;
    previous_applied_force = applied_force;
  }

  template <int dim>
  void
  FEZone<dim>::account_work()
  {
    if (!tracks_work)
      return;
    previous_applied_force += applied_force;
    previous_displacement.sadd(-1., state.displacement);
    work += 0.5 * (previous_applied_force * previous_displacement);
  }

  template <int dim>
  double
  FEZone<dim>::kinetic_energy() const
  {
    double local = 0;
    for (unsigned int i = 0; i < mass.locally_owned_size(); ++i)
      local +=
        mass.local_element(i) * state.velocity.local_element(i) * state.velocity.local_element(i);
    return 0.5 * Utilities::MPI::sum(local, communicator);
  }

  template <int dim>
  Tensor<1, dim>
  FEZone<dim>::linear_momentum() const
  {
    Tensor<1, dim> sum;
    for (unsigned int i = 0; i < mass.locally_owned_size(); ++i)
      sum[owned_dof_component[i]] += mass.local_element(i) * state.velocity.local_element(i);
    return Utilities::MPI::sum(sum, communicator);
  }

  template <int dim>
  double
  FEZone<dim>::strain_energy() const
  {
    return 0.5 * (state.displacement * internal_force);
  }

  template <int dim>
  double
  FEZone<dim>::external_work() const
  {
    return work;
  }

  template <int dim>
  std::vector<double>
  FEZone<dim>::largest_principal_strains(const Quadrature<dim>   &points,
                                         std::vector<Point<dim>> *where) const
  {
    const auto &u = state.displacement;
    u.update_ghost_values();
    std::vector<double> largest(triangulation.n_active_cells(),
                                -std::numeric_limits<double>::infinity());
    if (where)
      where->assign(triangulation.n_active_cells(), Point<dim>());
    FEValues<dim>                        fe_values(mapping,
                            fe_collection[0],
                            points,
                            update_gradients | (where ? update_quadrature_points : update_default));
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strain(points.size());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0)
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(u, strain);
          const unsigned int c = cell->active_cell_index();
          for (unsigned int q = 0; q < strain.size(); ++q)
            {
              const double e = eigenvalues(strain[q])[0];
              if (e > largest[c])
                {
                  largest[c] = e;
                  if (where)
                    (*where)[c] = fe_values.quadrature_point(q);
                }
            }
        }
    return largest;
  }

  template <int dim>
  const typename FEZone<dim>::State &
  FEZone<dim>::get_state() const
  {
    return state;
  }

  template <int dim>
  const std::vector<typename FEZone<dim>::PrescribedDoF> &
  FEZone<dim>::get_prescribed_dofs() const
  {
    return prescribed;
  }

  template <int dim>
  void
  FEZone<dim>::set_nodal_force_weights(const std::vector<double> &weights)
  {
    nodal_force_weights = weights;
  }

  template <int dim>
  void
  FEZone<dim>::set_contact(Contact<dim> *contact_model)
  {
    contact     = contact_model;
    tracks_work = tracks_work || contact != nullptr;
  }

  template <int dim>
  void
  FEZone<dim>::scale_velocities(const double factor)
  {
    state.velocity *= factor;
    for (unsigned int k = 0; k < prescribed.size(); ++k)
      state.velocity.local_element(prescribed[k].local_index) = prescribed_velocity[k];
  }

  template <int dim>
  void
  FEZone<dim>::start_relaxation_step()
  {
    relaxation_displacement = state.displacement;
    relaxation_acceleration = state.acceleration;
  }

  template <int dim>
  std::pair<double, double>
  FEZone<dim>::relaxation_step_sums() const
  {
    double sums[2] = {0, 0};
    for (unsigned int k = 0; k < mass.locally_owned_size(); ++k)
      if (!is_prescribed_dof[k])
        {
          const double m = mass.local_element(k);
          const double du =
            state.displacement.local_element(k) - relaxation_displacement.local_element(k);
          const double da =
            state.acceleration.local_element(k) - relaxation_acceleration.local_element(k);
          sums[0] -= m * du * da;
          sums[1] += m * du * du;
        }
    Utilities::MPI::sum(ArrayView<const double>(sums, 2), communicator, ArrayView<double>(sums, 2));
    return {sums[0], sums[1]};
  }

  template <int dim>
  std::pair<double, double>
  FEZone<dim>::squared_force_norms() const
  {
    // The prescribed DoFs left out, not added and taken off again: their accelerations are
    // those of the motion, which would take digits off the residual.
    double sums[2] = {0, 0};
    for (unsigned int i = 0; i < mass.locally_owned_size(); ++i)
      {
        if (!is_prescribed_dof[i])
          {
            const double residual = mass.local_element(i) * state.acceleration.local_element(i);
            sums[0] += residual * residual;
          }
        sums[1] += applied_force.local_element(i) * applied_force.local_element(i);
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 2), communicator, ArrayView<double>(sums, 2));
    return {sums[0], sums[1]};
  }

  template <int dim>
  void
  FEZone<dim>::take_projected_residual(const double dt)
  {
    std::vector<double> prescribed_acceleration(prescribed.size());
    for (unsigned int k = 0; k < prescribed.size(); ++k)
      prescribed_acceleration[k] = state.acceleration.local_element(prescribed[k].local_index);
    for (unsigned int i = 0; i < state.velocity.locally_owned_size(); ++i)
      state.acceleration.local_element(i) = 2. / dt * state.velocity.local_element(i);
    for (unsigned int k = 0; k < prescribed.size(); ++k)
      state.acceleration.local_element(prescribed[k].local_index) = prescribed_acceleration[k];
    scale_velocities(0.);
  }

  template <int dim>
  double
  FEZone<dim>::squared_residual_norm() const
  {
    const auto term = [&](const unsigned int i) {
      const double a = state.acceleration.local_element(i);
      return mass.local_element(i) * a * a;
    };
    double sum = 0;
    for (unsigned int i = 0; i < mass.locally_owned_size(); ++i)
      if (!is_prescribed_dof[i])
        sum += term(i);
    return Utilities::MPI::sum(sum, communicator);
  }

  template <int dim>
  void
  FEZone<dim>::update_search_direction(const double beta)
  {
    // A restart takes the current layout (the DoFs may have changed since the last solve).
    if (beta == 0.)
      search_direction.reinit(state.acceleration);
    for (unsigned int i = 0; i < search_direction.locally_owned_size(); ++i)
      search_direction.local_element(i) =
        state.acceleration.local_element(i) + beta * search_direction.local_element(i);
    for (const auto &dof : prescribed)
      search_direction.local_element(dof.local_index) = 0.;
  }

  template <int dim>
  void
  FEZone<dim>::move_along_search_direction(const double s)
  {
    for (unsigned int i = 0; i < search_direction.locally_owned_size(); ++i)
      state.displacement.local_element(i) =
        relaxation_displacement.local_element(i) + s * search_direction.local_element(i);
  }

  template <int dim>
  void
  FEZone<dim>::extrapolate_relaxation_step(const double c)
  {
    for (unsigned int i = 0; i < state.displacement.locally_owned_size(); ++i)
      {
        double &u = state.displacement.local_element(i);
        double &a = state.acceleration.local_element(i);
        u         = relaxation_displacement.local_element(i) +
            c * (u - relaxation_displacement.local_element(i));
        a = relaxation_acceleration.local_element(i) +
            c * (a - relaxation_acceleration.local_element(i));
      }
  }

  // The class is instantiated in fe_zone.cc; the members defined here are instantiated here.
#define PERIARLEQUIN_INSTANTIATE(dim)                                                             \
  template void        FEZone<dim>::initialize_state(const ProblemData<dim> &, const double);     \
  template std::string FEZone<dim>::name() const;                                                 \
  template void        FEZone<dim>::predict(const double);                                        \
  template void        FEZone<dim>::impose_prescribed_motion(const double);                       \
  template void        FEZone<dim>::compute_accelerations(const double);                          \
  template void        FEZone<dim>::correct(const double);                                        \
  template void        FEZone<dim>::account_work();                                               \
  template void        FEZone<dim>::start_work_interval(const bool);                              \
  template double      FEZone<dim>::kinetic_energy() const;                                       \
  template double      FEZone<dim>::strain_energy() const;                                        \
  template std::vector<double> FEZone<dim>::largest_principal_strains(const Quadrature<dim> &,    \
                                                                      std::vector<Point<dim>> *)  \
    const;                                                                                        \
  template Tensor<1, dim>                                 FEZone<dim>::linear_momentum() const;   \
  template double                                         FEZone<dim>::external_work() const;     \
  template const FEZone<dim>::State                      &FEZone<dim>::get_state() const;         \
  template const std::vector<FEZone<dim>::PrescribedDoF> &FEZone<dim>::get_prescribed_dofs()      \
    const;                                                                                        \
  template void FEZone<dim>::set_nodal_force_weights(const std::vector<double> &);                \
  template void FEZone<dim>::set_contact(Contact<dim> *);                                         \
  template void FEZone<dim>::compute_forces(const double);                                        \
  template FEZone<dim>::VectorType       &FEZone<dim>::interface_forces();                        \
  template FEZone<dim>::VectorType       &FEZone<dim>::applied_forces();                          \
  template const FEZone<dim>::VectorType &FEZone<dim>::applied_forces() const;                    \
  template void                           FEZone<dim>::scale_velocities(const double);            \
  template void                           FEZone<dim>::start_relaxation_step();                   \
  template std::pair<double, double>      FEZone<dim>::relaxation_step_sums() const;              \
  template std::pair<double, double>      FEZone<dim>::squared_force_norms() const;               \
  template void                           FEZone<dim>::take_projected_residual(const double);     \
  template double                         FEZone<dim>::squared_residual_norm() const;             \
  template void                           FEZone<dim>::update_search_direction(const double);     \
  template void                           FEZone<dim>::move_along_search_direction(const double); \
  template void                           FEZone<dim>::extrapolate_relaxation_step(const double);

  PERIARLEQUIN_INSTANTIATE(2)
  PERIARLEQUIN_INSTANTIATE(3)
#undef PERIARLEQUIN_INSTANTIATE
} // namespace PeriArlequin
