#include <periarlequin/base/initial_conditions.h>
#include <periarlequin/base/parameters.h>
#include <periarlequin/base/problem_data.h>

#include <deal.II/base/numbers.h>
#include <deal.II/lac/vector.h>

#include <cmath>

namespace PeriArlequin
{
  template <int dim>
  void
  InitialCondition<dim>::parse_parameters(ParameterHandler &)
  {}

  namespace
  {
    template <int dim>
    Tensor<1, dim>
    evaluate(Functions::ParsedFunction<dim> &function, const Point<dim> &x)
    {
      Vector<double> value(dim);
      function.vector_value(x, value);
      Tensor<1, dim> result;
      for (unsigned int d = 0; d < dim; ++d)
        result[d] = value(d);
      return result;
    }
  } // namespace

  template <int dim>
  FunctionInitialCondition<dim>::FunctionInitialCondition()
    : displacement_function(dim)
    , velocity_function(dim)
  {}

  template <int dim>
  void
  FunctionInitialCondition<dim>::declare_parameters(ParameterHandler &prm)
  {
    declare_vector_function<dim>(prm, "Displacement", "Initial displacement u(x, 0) [m].");
    declare_vector_function<dim>(prm, "Velocity", "Initial velocity v(x, 0) [m/s].");
  }

  template <int dim>
  void
  FunctionInitialCondition<dim>::parse_parameters(ParameterHandler &prm)
  {
    const std::string path = "Initial conditions/function/";
    parse_vector_function(prm, path, "Displacement", displacement_function);
    parse_vector_function(prm, path, "Velocity", velocity_function);
    displacement_function.set_time(0.);
    velocity_function.set_time(0.);
  }

  template <int dim>
  Tensor<1, dim>
  FunctionInitialCondition<dim>::displacement(const Point<dim> &x) const
  {
    return evaluate(displacement_function, x);
  }

  template <int dim>
  Tensor<1, dim>
  FunctionInitialCondition<dim>::velocity(const Point<dim> &x) const
  {
    return evaluate(velocity_function, x);
  }

  template <int dim>
  void
  WavePulseInitialCondition<dim>::entries(ParameterEntries &entries)
  {
    entries.add("Amplitude", amplitude, Patterns::Double(), "a1 [m].");
    entries.add("Modulation",
                modulation,
                Patterns::Double(),
                "a2, relative amplitude of the short-wave modulation [-].");
    entries.add("Width", width, Patterns::Double(), "w1, length of the pulse, > 0 [m].");
    entries.add("Modulation wavelength", modulation_wavelength, Patterns::Double(), "w2, > 0 [m].");
    entries.add("Centre",
                centre,
                Patterns::Double(),
                "x0, x coordinate of the pulse's centre [m].");
    const SelectionNames<unsigned int> axes = {{"x", 0}, {"y", 1}, {"z", 2}};
    entries.add("Component",
                component,
                SelectionNames<unsigned int>(axes.begin(), axes.begin() + dim),
                "Displacement component of the pulse: x gives a longitudinal (P) wave, y or z "
                "a shear (S) wave.");
  }

  template <int dim>
  void
  WavePulseInitialCondition<dim>::declare_parameters(ParameterHandler &prm)
  {
    ParameterEntries::declare_here<WavePulseInitialCondition<dim>>(prm);
  }

  template <int dim>
  void
  WavePulseInitialCondition<dim>::parse_parameters(ParameterHandler &prm)
  {
    ParameterEntries::parse_here(prm, *this, "Initial conditions/wave pulse/");
    if (!(width > 0))
      throw_invalid_parameter("Initial conditions/wave pulse/Width", width, "a length > 0 [m]");
    if (!(modulation_wavelength > 0))
      throw_invalid_parameter("Initial conditions/wave pulse/Modulation wavelength",
                              modulation_wavelength,
                              "a length > 0 [m]");
  }

  template <int dim>
  Tensor<1, dim>
  WavePulseInitialCondition<dim>::displacement(const Point<dim> &x) const
  {
    const double   s = x[0] - centre;
    Tensor<1, dim> u;
    if (std::abs(s) <= width / 2)
      u[component] =
        amplitude * (1 + std::cos(2 * numbers::PI * s / width)) *
        (1 + modulation * std::cos(2 * numbers::PI * (s + width / 2) / modulation_wavelength));
    return u;
  }

  template <int dim>
  Tensor<1, dim>
  WavePulseInitialCondition<dim>::velocity(const Point<dim> &) const
  {
    return Tensor<1, dim>();
  }

  template class InitialCondition<2>;
  template class InitialCondition<3>;
  template class FunctionInitialCondition<2>;
  template class FunctionInitialCondition<3>;
  template class WavePulseInitialCondition<2>;
  template class WavePulseInitialCondition<3>;
  template class PluginRegistry<InitialCondition<2>>;
  template class PluginRegistry<InitialCondition<3>>;

  PERIARLEQUIN_REGISTER_INITIAL_CONDITION(FunctionInitialCondition,
                                          "function",
                                          "displacement and velocity given as muparser "
                                          "expressions of the position");
  PERIARLEQUIN_REGISTER_INITIAL_CONDITION(WavePulseInitialCondition,
                                          "wave pulse",
                                          "the modulated cosine pulse of the paper's wave "
                                          "study (eq. 81), at rest");
} // namespace PeriArlequin
