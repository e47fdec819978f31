#include <periarlequin/coupling/fine_scale_damping.h>

#include <sstream>

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
  {
    const double wave_speed = parameters.damping_wave_speed > 0 ?
                                parameters.damping_wave_speed :
                                material.longitudinal_wave_speed(dim);
    double       largest    = 0;
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
        largest = std::max(largest, coefficient.back());
      }
    largest = Utilities::MPI::max(largest, pd_zone.get_communicator());
    if (largest * time_step >= 1.)
      {
        std::ostringstream allowed;
        allowed << "a value for which C v_w alpha^2 / L_B x dt < 1 (here " << largest * time_step
                << "): explicit damping over-damps and turns unstable beyond; lower C or the "
                   "time step";
        throw_invalid_parameter("Coupling/Damping constant",
                                parameters.damping_constant,
                                allowed.str());
      }
  }

  template <int dim>
  void
  FineScaleDamping<dim>::apply(const VectorType &fe_velocity, PDZone<dim> &pd_zone) const
  {
    fe_velocity.update_ghost_values();
    for (unsigned int r = 0; r < particles.size(); ++r)
      {
        const unsigned int i = particles[r];
        pd_zone.add_to_acceleration(i,
                                    -(coefficient[r] * (pd_zone.get_state().velocities()[i] -
                                                        overlap.interpolate(fe_velocity, r))));
      }
  }

  template class FineScaleDamping<2>;
  template class FineScaleDamping<3>;
} // namespace PeriArlequin
