#ifndef periarlequin_coupling_fine_scale_damping_h
#define periarlequin_coupling_fine_scale_damping_h

#include <periarlequin/coupling/blending_field.h>
#include <periarlequin/coupling/interpolation_operator.h>

#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * Damping of the fine-scale motion of the overlap's PD nodes (section 5): the fine part of
   * the velocity, w_fine = w - N v (eq. 70-72), feels the force -M_p,I C_I w_fine,I (eq. 76)
   * with C_I = C v_w alpha_I^2 / L_B (eq. 78): zero on the PD edge of the overlap, C v_w / L_B
   * on its FE edge. The force takes the end-of-step velocity, solved node by node, so that
   * the damping cannot destabilise the step (Parameters::DampingIntegration::implicit), or
   * the half-step velocity of eq. 79c; the coarse part d - d_fine = N u is untouched (eq. 80).
   */
  template <int dim>
  class FineScaleDamping
  {
  public:
    using FEState = typename FEZone<dim>::State;

    /** Coefficients C_I at the overlap PD nodes @p particles (the rows of @p overlap). */
    FineScaleDamping(const Parameters::Coupling       &parameters,
                     const Parameters::Material       &material,
                     const BlendingField<dim>         &blending,
                     const PDZone<dim>                &pd_zone,
                     const std::vector<unsigned int>  &particles,
                     const InterpolationOperator<dim> &overlap,
                     const double                      time_step);

    /**
     * The stable step with this damping, from the undamped one @p undamped_step: the same
     * for the implicit form, lower for the half-step form.
     */
    double
    stable_time_step(const double undamped_step) const;

    /**
     * a_I -= C_I (w_I - (N v)_I) after the trial accelerations, with the FE zone's predicted
     * velocity and trial acceleration in @p fe_state.
     */
    void
    apply(const FEState &fe_state, PDZone<dim> &pd_zone) const;

  private:
    const InterpolationOperator<dim>    &overlap;
    const std::vector<unsigned int>     &particles;
    const Parameters::DampingIntegration integration;
    const double                         time_step;
    std::vector<double>                  coefficient;
    /** The largest C_I over all ranks [1/s]. */
    double largest_coefficient = 0.;
  };
} // namespace PeriArlequin

#endif
