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
   * on its FE edge. It is applied with the half-step velocities, the velocity-Verlet form of
   * eq. 79; the coarse part d - d_fine = N u is untouched (eq. 80).
   */
  template <int dim>
  class FineScaleDamping
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    /**
     * Coefficients at the overlap PD nodes @p particles (the rows of @p overlap); refuses a
     * damping that explicit integration cannot carry at @p time_step (C_I dt >= 1).
     */
    FineScaleDamping(const Parameters::Coupling       &parameters,
                     const Parameters::Material       &material,
                     const BlendingField<dim>         &blending,
                     const PDZone<dim>                &pd_zone,
                     const std::vector<unsigned int>  &particles,
                     const InterpolationOperator<dim> &overlap,
                     const double                      time_step);

    /** b_I -= C_I (w_I - (N v)_I) with the FE velocity @p fe_velocity. */
    void
    apply(const VectorType &fe_velocity, PDZone<dim> &pd_zone) const;

  private:
    const InterpolationOperator<dim> &overlap;
    const std::vector<unsigned int>  &particles;
    std::vector<double>               coefficient;
  };
} // namespace PeriArlequin

#endif
