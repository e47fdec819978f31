#ifndef periarlequin_base_crack_tip_field_h
#define periarlequin_base_crack_tip_field_h

#include <periarlequin/base/parameters.h>
#include <periarlequin/base/separable_field.h>

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <array>
#include <string>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The asymptotic displacement field of a crack tip loaded in modes I and II (eq. 82 of the
   * paper; plane stress, plane strain, or in 3D the plane-strain field independent of z):
   * with r, theta polar coordinates about the tip, theta = 0 along the crack direction (the
   * crack faces at theta = +-pi), mu the shear modulus and kappa = 3 - 4 nu (plane strain, 3D)
   * or (3 - nu)/(1 + nu) (plane stress),
   *   u_x' = sqrt(r / 2 pi) / (2 mu) [K_I cos(theta/2) (kappa - 1 + 2 sin^2(theta/2))
   *                                   + K_II sin(theta/2) (kappa + 1 + 2 cos^2(theta/2))],
   *   u_y' = sqrt(r / 2 pi) / (2 mu) [K_I sin(theta/2) (kappa + 1 - 2 cos^2(theta/2))
   *                                   - K_II cos(theta/2) (kappa - 1 - 2 sin^2(theta/2))],
   * rotated from the crack's frame to x, y. K_I = K(t) cos psi, K_II = K(t) sin psi with K(t)
   * an expression of the time and psi the phase angle.
   */
  template <int dim>
  class CrackTipField
    : public Function<dim>
    , public SeparableField<dim>
  {
  public:
    /** The entries of "Boundary conditions/Crack tip field", as given (angles in degrees). */
    struct Input
    {
      std::vector<unsigned int> boundary_ids;
      std::vector<double>       tip              = {0., 0.};
      double                    direction        = 0.;
      std::string               stress_intensity = "0";
      double                    phase_angle      = 0.;

      void
      entries(ParameterEntries &entries);
    };

    /** Declare the entries of "Boundary conditions/Crack tip field". */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * The field of that subsection for @p material (its elastic constants and, in 2D, its
     * plane model); fills @p boundary_ids with the ids it prescribes.
     */
    CrackTipField(ParameterHandler           &prm,
                  const Parameters::Material &material,
                  std::vector<unsigned int>  &boundary_ids);

    /** The field of a tip at @p tip whose crack grows along @p direction [rad]. */
    CrackTipField(const Point<2>             &tip,
                  const double                direction,
                  const std::string          &stress_intensity,
                  const double                phase_angle,
                  const Parameters::Material &material);

    void
    vector_value(const Point<dim> &p, Vector<double> &values) const override;
    double
    value(const Point<dim> &p, const unsigned int component = 0) const override;

    /** K(t) [Pa m^(1/2)]. */
    double
    time_factor(const double t) const override;

    /** The field at K = 1 [m / (Pa m^(1/2))]. */
    Tensor<1, dim>
    spatial_field(const Point<dim> &p) const override;

    /** K_I and K_II at time @p t [Pa m^(1/2)]. */
    std::array<double, 2>
    stress_intensity_factors(const double t) const;

    /**
     * The energy release rate of the field at time @p t, (K_I^2 + K_II^2) / E' with
     * E' = 8 mu / (kappa + 1): E in plane stress, E / (1 - nu^2) in plane strain [J/m^2].
     */
    double
    energy_release_rate(const double t) const;

  private:
    void
    initialize(const std::string &stress_intensity, const Parameters::Material &material);

    Point<2>          tip;
    double            direction = 0, phase_angle = 0, shear_modulus = 0, kappa = 0;
    FunctionParser<1> stress_intensity_factor;
  };
} // namespace PeriArlequin

#endif
