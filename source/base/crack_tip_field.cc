#include <periarlequin/base/crack_tip_field.h>

#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <cmath>

namespace PeriArlequin
{
  template <int dim>
  void
  CrackTipField<dim>::Input::entries(ParameterEntries &entries)
  {
    entries.add("Boundary ids",
                boundary_ids,
                Patterns::List(Patterns::Integer(0, 2 * dim - 1)),
                "Boundary ids whose displacement is the crack-tip field of eq. 82 (their own "
                "Type must be free); empty: none.");
    entries.add("Tip", tip, Patterns::List(Patterns::Double(), 2, 2), "Crack tip x, y [m].");
    entries.add("Crack direction",
                direction,
                Patterns::Double(-360, 360),
                "Direction in which the crack points, from its faces to the tip, "
                "counter-clockwise from x [degrees]: 0 is a crack along the negative x axis of "
                "the tip.");
    entries.add("Stress intensity factor",
                stress_intensity,
                Patterns::Anything(),
                "K_eff(t) = sqrt(K_I^2 + K_II^2) as a muparser expression of the time t [Pa "
                "m^1/2], e.g. 1e9*t for the paper's ramp of 1e3 MPa m^1/2/s.");
    entries.add("Phase angle",
                phase_angle,
                Patterns::Double(-90, 90),
                "psi with K_I = K_eff cos psi, K_II = K_eff sin psi [degrees].");
  }

  template <int dim>
  void
  CrackTipField<dim>::declare_parameters(ParameterHandler &prm)
  {
    ParameterEntries::declare<Input>(prm, "Crack tip field");
  }

  template <int dim>
  CrackTipField<dim>::CrackTipField(ParameterHandler           &prm,
                                    const Parameters::Material &material,
                                    std::vector<unsigned int>  &boundary_ids)
    : Function<dim>(dim)
  {
    Input input;
    ParameterEntries::parse(prm, "Crack tip field", input, "Boundary conditions/");
    boundary_ids = input.boundary_ids;
    tip          = Point<2>(input.tip[0], input.tip[1]);
    direction    = input.direction * numbers::PI / 180.;
    phase_angle  = input.phase_angle * numbers::PI / 180.;
    initialize(input.stress_intensity, material);
  }

  template <int dim>
  CrackTipField<dim>::CrackTipField(const Point<2>             &tip,
                                    const double                direction,
                                    const std::string          &stress_intensity,
                                    const double                phase_angle,
                                    const Parameters::Material &material)
    : Function<dim>(dim)
    , tip(tip)
    , direction(direction)
    , phase_angle(phase_angle)
  {
    initialize(stress_intensity, material);
  }

  template <int dim>
  void
  CrackTipField<dim>::initialize(const std::string          &stress_intensity,
                                 const Parameters::Material &material)
  {
    const double nu = material.poissons_ratio;
    shear_modulus   = material.youngs_modulus / (2. * (1. + nu));
    kappa           = (dim == 2 && material.planar_model == Parameters::PlanarModel::plane_stress) ?
                        (3. - nu) / (1. + nu) :
                        3. - 4. * nu;
    try
      {
        stress_intensity_factor.initialize("t", stress_intensity, {{"pi", numbers::PI}});
        // muparser parses at the first evaluation.
        AssertThrow(std::isfinite(stress_intensity_factor.value(Point<1>(0.))),
                    ExcMessage("not finite"));
      }
    catch (...)
      {
        throw_invalid_parameter("Boundary conditions/Crack tip field/Stress intensity factor",
                                stress_intensity,
                                "a muparser expression of the time t [Pa m^1/2]");
      }
  }

  template <int dim>
  Tensor<1, dim>
  CrackTipField<dim>::spatial_field(const Point<dim> &p) const
  {
    // Polar coordinates in the crack's frame.
    const double c = std::cos(direction), s = std::sin(direction);
    const double dx = p[0] - tip[0], dy = p[1] - tip[1];
    const double x = c * dx + s * dy, y = -s * dx + c * dy;
    const double r = std::sqrt(x * x + y * y), theta = std::atan2(y, x);
    const double K_I = std::cos(phase_angle), K_II = std::sin(phase_angle);
    const double scale = std::sqrt(r / (2. * numbers::PI)) / (2. * shear_modulus);
    const double ch = std::cos(theta / 2), sh = std::sin(theta / 2);
    const double ux =
      scale * (K_I * ch * (kappa - 1. + 2. * sh * sh) + K_II * sh * (kappa + 1. + 2. * ch * ch));
    const double uy =
      scale * (K_I * sh * (kappa + 1. - 2. * ch * ch) - K_II * ch * (kappa - 1. - 2. * sh * sh));
    Tensor<1, dim> field;
    field[0] = c * ux - s * uy;
    field[1] = s * ux + c * uy;
    return field;
  }

  template <int dim>
  double
  CrackTipField<dim>::time_factor(const double t) const
  {
    return stress_intensity_factor.value(Point<1>(t));
  }

  template <int dim>
  void
  CrackTipField<dim>::vector_value(const Point<dim> &p, Vector<double> &values) const
  {
    const Tensor<1, dim> field = time_factor(this->get_time()) * spatial_field(p);
    for (unsigned int d = 0; d < dim; ++d)
      values(d) = field[d];
  }

  template <int dim>
  double
  CrackTipField<dim>::value(const Point<dim> &p, const unsigned int component) const
  {
    Vector<double> values(dim);
    vector_value(p, values);
    return values(component);
  }

  template <int dim>
  std::array<double, 2>
  CrackTipField<dim>::stress_intensity_factors(const double t) const
  {
    const double K = time_factor(t);
    return {{K * std::cos(phase_angle), K * std::sin(phase_angle)}};
  }

  template <int dim>
  double
  CrackTipField<dim>::energy_release_rate(const double t) const
  {
    const auto [K_I, K_II] = stress_intensity_factors(t);
    return (K_I * K_I + K_II * K_II) * (kappa + 1.) / (8. * shear_modulus);
  }

  template class CrackTipField<2>;
  template class CrackTipField<3>;
} // namespace PeriArlequin
