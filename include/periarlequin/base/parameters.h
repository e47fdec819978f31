#ifndef periarlequin_base_parameters_h
#define periarlequin_base_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

/**
 * Parameter structures of the parts of a simulation. Each one declares its own documented
 * subsection of the input file and parses (and validates) it, ASPECT style.
 */
namespace PeriArlequin
{
  using namespace dealii;

  /**
   * Throw a uniform error for an invalid input value: it names the parameter (with its
   * subsection path), the value that was given and what is allowed.
   */
  [[noreturn]] void
  throw_invalid_parameter(const std::string &parameter,
                          const std::string &value,
                          const std::string &allowed);

  /** The same for a number, printed as the parameter file would give it. */
  [[noreturn]] void
  throw_invalid_parameter(const std::string &parameter,
                          const double       value,
                          const std::string &allowed);

  /**
   * The values of an enumeration with the names a parameter file gives them: one table per
   * enumeration declares the entry's pattern (selection_pattern) and converts what was read
   * (selection_value), so names and values cannot drift apart.
   */
  template <typename Enum>
  using SelectionNames = std::vector<std::pair<std::string, Enum>>;

  /** Patterns::Selection of the names of @p names. */
  template <typename Enum>
  Patterns::Selection
  selection_pattern(const SelectionNames<Enum> &names)
  {
    std::string list;
    for (const auto &[name, value] : names)
      list += (list.empty() ? "" : "|") + name;
    return Patterns::Selection(list);
  }

  /** The value named @p name in @p names (the entry's pattern has checked the name). */
  template <typename Enum>
  Enum
  selection_value(const std::string &name, const SelectionNames<Enum> &names)
  {
    for (const auto &[candidate, value] : names)
      if (candidate == name)
        return value;
    AssertThrow(false, ExcMessage("'" + name + "' is not a name of the selection."));
    return names.front().second;
  }

  namespace Parameters
  {
    /** A box domain meshed by a subdivided hyper-rectangle. */
    struct Geometry
    {
      std::vector<double>       lower_corner;
      std::vector<double>       upper_corner;
      std::vector<unsigned int> subdivisions;
      unsigned int              global_refinements;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const unsigned int dim);
    };

    /** How a two-dimensional model reads the third direction. */
    enum class PlanarModel
    {
      plane_stress,
      plane_strain
    };

    inline const SelectionNames<PlanarModel> planar_model_names = {
      {"plane stress", PlanarModel::plane_stress},
      {"plane strain", PlanarModel::plane_strain}};

    /** Isotropic linear elastic material shared by the FE and PD zones. */
    struct Material
    {
      double      youngs_modulus;
      double      poissons_ratio;
      double      density;
      PlanarModel planar_model;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /** Shear modulus mu [Pa]. */
      double
      shear_modulus() const;
      /** Three-dimensional bulk modulus K [Pa]. */
      double
      bulk_modulus() const;
      /**
       * First Lame constant of the model in @p dim dimensions [Pa]: in plane stress the
       * eliminated out-of-plane strain turns lambda into 2 lambda mu / (lambda + 2 mu).
       */
      double
      effective_lambda(const unsigned int dim) const;
      /** Speed of plane longitudinal waves, sqrt((lambda_eff + 2 mu) / rho) [m/s]. */
      double
      longitudinal_wave_speed(const unsigned int dim) const;
    };

    /** The finite-element discretisation of the classical zone. */
    struct FiniteElements
    {
      unsigned int degree;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** Explicit time stepping. */
    struct Time
    {
      double time_step;
      double end_time;
      /** Power iterations allowed for the estimate of the largest eigenvalue of M^-1 K. */
      unsigned int stability_iterations;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** What is written, where, and how often. */
    struct Output
    {
      std::string  directory;
      std::string  base_name;
      unsigned int output_interval;
      unsigned int energy_interval;
      double       progress_interval;
      bool         print_timing;
      /** Segment "x0, y0 : x1, y1" along which displacements are sampled ("" for none). */
      std::string  sample_line;
      /** Boxes whose PD energies are recorded as the pure PD zone's ("" : the PD region). */
      std::string  monitor_region;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace PeriArlequin

#endif
