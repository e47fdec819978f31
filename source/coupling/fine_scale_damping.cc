#include <periarlequin/coupling/fine_scale_damping.h>

#include <cmath>

namespace PeriArlequin
{
  template <int dim>
  FineScaleDamping<dim>::FineScaleDamping(const Parameters::Coupling       &parameters,
                                          const Parameters::Material       &material,
                                          const BlendingField<dim>         &blending,
                                          const PDZone<dim>                &pd_zone,
                                          const std::vector<unsigned int>  &particles,
                                          const InterpolationOperator<dim> &overlap,
                                          const double                      time_step)
    : overlap(overlap)
    , particles(particles)
    , integration(parameters.damping_integration)
    , time_step(time_step)
  {
    const double wave_speed = parameters.damping_wave_speed > 0 ?
                                parameters.damping_wave_speed :
                                material.longitudinal_wave_speed(dim);
    for (const unsigned int i : particles)
      {
        const double alpha = pd_zone.blending_weights()[i];
        const double width = parameters.damping_overlap_width > 0 ?
                               parameters.damping_overlap_width :
                               blending.overlap_width(pd_zone.reference_positions()[i]);
        // Prescribed particles keep their prescribed motion: no damping force.
        const bool damped = parameters.damping && !pd_zone.is_prescribed(i);
        coefficient.push_back(
          damped ? parameters.damping_constant * wave_speed * alpha * alpha / width : 0.);
        largest_coefficient = std::max(largest_coefficient, coefficient.back());
      }
    largest_coefficient = Utilities::MPI::max(largest_coefficient, pd_zone.get_communicator());
  }

  template <int dim>
  double
  FineScaleDamping<dim>::stable_time_step(const double undamped_step) const
  {
    if (integration == Parameters::DampingIntegration::implicit)
      return undamped_step;
    // A node of the highest frequency omega = 2 / undamped_step with damping ratio
    // xi = C_I / (2 omega), the force taken at the half-step velocity: stable for
    // omega dt <= 2 (sqrt(1 + xi^2) - xi).
    const double xi = 0.25 * largest_coefficient * undamped_step;
    return undamped_step * (std::sqrt(1. + xi * xi) - xi);
  }

  template <int dim>
  void
  FineScaleDamping<dim>::apply(const FEState &fe_state, PDZone<dim> &pd_zone) const
  {
    const auto v = pd_zone.get_state().velocities();
    const auto a = pd_zone.get_state().accelerations();
    fe_state.velocity.update_ghost_values();
    if (integration == Parameters::DampingIntegration::half_step)
      {
        overlap.for_each_row_range([&](const unsigned int first, const unsigned int end) {
          for (unsigned int r = first; r < end; ++r)
            {
              const unsigned int i = particles[r];
              pd_zone.add_to_acceleration(i,
                                          -coefficient[r] *
                                            (v[i] - overlap.interpolate(fe_state.velocity, r)));
            }
        });
        return;
      }
    // The corrector will set w = w_half + dt/2 a. With the damping force at that velocity,
    // a = a_trial - C_I (w - N v_end), the node's equation solves to
    // a = a_trial - C_I / (1 + C_I dt/2) (w_half + dt/2 a_trial - N v_end), where
    // v_end = v_half + dt/2 a_FE is the FE velocity the corrector gives (before the
    // multipliers, like the PD side).
    fe_state.acceleration.update_ghost_values();
    const double half_step = 0.5 * time_step;
    overlap.for_each_row_range([&](const unsigned int first, const unsigned int end) {
      for (unsigned int r = first; r < end; ++r)
        {
          const unsigned int   i = particles[r];
          const Tensor<1, dim> fine_velocity =
            v[i] + half_step * a[i] - overlap.interpolate(fe_state.velocity, r) -
            half_step * overlap.interpolate(fe_state.acceleration, r);
          pd_zone.add_to_acceleration(i,
                                      -(coefficient[r] / (1. + half_step * coefficient[r])) *
                                        fine_velocity);
        }
    });
  }

  template class FineScaleDamping<2>;
  template class FineScaleDamping<3>;
} // namespace PeriArlequin
