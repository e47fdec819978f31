#include <periarlequin/base/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <sstream>
#include <limits>

namespace PeriArlequin
{
  void
  throw_invalid_parameter(const std::string &parameter,
                          const std::string &value,
                          const std::string &allowed)
  {
    AssertThrow(false,
                ExcMessage("Invalid input: parameter '" + parameter + "' = '" + value +
                           "'; allowed: " + allowed + "."));
    // AssertThrow(false, ...) always throws; this keeps [[noreturn]] honest for the compiler.
    throw std::logic_error("unreachable");
  }

  void
  throw_invalid_parameter(const std::string &parameter,
                          const double       value,
                          const std::string &allowed)
  {
    std::ostringstream text;
    text << value;
    throw_invalid_parameter(parameter, text.str(), allowed);
  }

  namespace Parameters
  {
    void
    Geometry::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      prm.declare_entry("Lower corner",
                        "0, 0",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Lower corner of the box domain, one coordinate per dimension [m].");
      prm.declare_entry("Upper corner",
                        "1, 1",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Upper corner of the box domain, one coordinate per dimension [m].");
      prm.declare_entry("Subdivisions",
                        "10, 10",
                        Patterns::List(Patterns::Integer(1), 2, 3),
                        "Number of coarse cells in each direction. Boundary ids are 0/1 on the "
                        "lower/upper x faces, 2/3 on the y faces and 4/5 on the z faces.");
      prm.declare_entry("Global refinements",
                        "0",
                        Patterns::Integer(0, 12),
                        "Uniform refinements of the coarse mesh (each halves the cell size).");
      prm.leave_subsection();
    }

    void
    Geometry::parse_parameters(ParameterHandler &prm, const unsigned int dim)
    {
      prm.enter_subsection("Geometry");
      const auto read_list = [&](const std::string &name) {
        const std::string text = prm.get(name);
        const auto values = Utilities::string_to_double(Utilities::split_string_list(text));
        if (values.size() != dim)
          throw_invalid_parameter("Geometry/" + name,
                                  text,
                                  "a list of exactly " + std::to_string(dim) +
                                    " numbers (one per dimension, Dimension = " +
                                    std::to_string(dim) + ")");
        return values;
      };
      lower_corner = read_list("Lower corner");
      upper_corner = read_list("Upper corner");
      const auto cells = read_list("Subdivisions");
      subdivisions.assign(cells.begin(), cells.end());
      for (unsigned int d = 0; d < dim; ++d)
        if (!(upper_corner[d] > lower_corner[d]))
          throw_invalid_parameter("Geometry/Upper corner",
                                  prm.get("Upper corner"),
                                  "coordinates strictly above those of 'Lower corner' (" +
                                    prm.get("Lower corner") + ")");
      global_refinements = prm.get_integer("Global refinements");
      prm.leave_subsection();
    }

    void
    Material::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      prm.declare_entry("Young's modulus", "69e9", Patterns::Double(), "Young's modulus E [Pa].");
      prm.declare_entry("Poisson's ratio",
                        "0.3",
                        Patterns::Double(),
                        "Poisson's ratio nu [-], in (-1, 0.5).");
      prm.declare_entry("Density", "2700", Patterns::Double(), "Mass density rho [kg/m^3].");
      prm.declare_entry("Two-dimensional model",
                        "plane stress",
                        selection_pattern(planar_model_names),
                        "How a 2D run treats the third direction. Ignored in 3D.");
      prm.leave_subsection();
    }

    void
    Material::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      youngs_modulus = prm.get_double("Young's modulus");
      poissons_ratio = prm.get_double("Poisson's ratio");
      density        = prm.get_double("Density");
      planar_model = selection_value(prm.get("Two-dimensional model"), planar_model_names);
      prm.leave_subsection();

      if (!(youngs_modulus > 0))
        throw_invalid_parameter("Material/Young's modulus",
                                youngs_modulus,
                                "a value > 0 [Pa]");
      if (!(poissons_ratio > -1 && poissons_ratio < 0.5))
        throw_invalid_parameter("Material/Poisson's ratio",
                                poissons_ratio,
                                "a value in the open interval (-1, 0.5)");
      if (!(density > 0))
        throw_invalid_parameter("Material/Density", density, "a value > 0 [kg/m^3]");
    }

    double
    Material::shear_modulus() const
    {
      return youngs_modulus / (2. * (1. + poissons_ratio));
    }

    double
    Material::bulk_modulus() const
    {
      return youngs_modulus / (3. * (1. - 2. * poissons_ratio));
    }

    double
    Material::effective_lambda(const unsigned int dim) const
    {
      const double mu     = shear_modulus();
      const double lambda = youngs_modulus * poissons_ratio /
                            ((1. + poissons_ratio) * (1. - 2. * poissons_ratio));
      if (dim == 2 && planar_model == PlanarModel::plane_stress)
        return 2. * lambda * mu / (lambda + 2. * mu);
      return lambda;
    }

    double
    Material::longitudinal_wave_speed(const unsigned int dim) const
    {
      return std::sqrt((effective_lambda(dim) + 2. * shear_modulus()) / density);
    }

    void
    FiniteElements::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Finite elements");
      prm.declare_entry("Polynomial degree",
                        "1",
                        Patterns::Integer(1, 4),
                        "Degree of the FE_Q displacement element of the classical zone.");
      prm.leave_subsection();
    }

    void
    FiniteElements::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Finite elements");
      degree = prm.get_integer("Polynomial degree");
      prm.leave_subsection();
    }

    void
    Time::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      prm.declare_entry("Time step",
                        "1e-7",
                        Patterns::Double(),
                        "Step dt of the explicit integrator [s]; must be > 0 and not above "
                        "the estimated stable step 2/sqrt(lambda_max(M^-1 K)).");
      prm.declare_entry("End time", "1e-5", Patterns::Double(), "Simulated end time [s], > 0.");
      prm.declare_entry("Stability estimate iterations",
                        "200",
                        Patterns::Integer(1),
                        "Maximum power iterations for the largest eigenvalue of M^-1 K.");
      prm.leave_subsection();
    }

    void
    Time::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      time_step            = prm.get_double("Time step");
      end_time             = prm.get_double("End time");
      stability_iterations = prm.get_integer("Stability estimate iterations");
      prm.leave_subsection();
      if (!(time_step > 0))
        throw_invalid_parameter("Time/Time step", time_step, "a value > 0 [s]");
      if (!(end_time > 0))
        throw_invalid_parameter("Time/End time", end_time, "a value > 0 [s]");
    }

    void
    Output::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Directory",
                        "output",
                        Patterns::DirectoryName(),
                        "Directory for the .pvtu/.pvd files and the energy history (created "
                        "if missing).");
      prm.declare_entry("Base name", "solution", Patterns::FileName(), "Prefix of output files.");
      prm.declare_entry("Output interval",
                        "100",
                        Patterns::Integer(0),
                        "Write fields every this many steps (0: never) [steps].");
      prm.declare_entry("Energy interval",
                        "1",
                        Patterns::Integer(0),
                        "Record the energy history every this many steps (0: never) [steps].");
      prm.declare_entry("Progress interval",
                        "5",
                        Patterns::Double(0),
                        "Print a progress line at most every this many wall-clock seconds "
                        "(0: never) [s].");
      prm.declare_entry("Print timing summary",
                        "true",
                        Patterns::Bool(),
                        "Print the TimerOutput summary at the end of the run.");
      prm.declare_entry("Sample line",
                        "",
                        Patterns::Anything(),
                        "Segment 'x0, y0 : x1, y1' [m]: with every field output, write "
                        "<base>_line_<step>.csv with the displacement of the FE nodes on it and "
                        "of the PD particles within half a lattice spacing of it. Empty: none.");
      prm.declare_entry("Monitor region",
                        "",
                        Patterns::Anything(),
                        "Boxes 'lower : upper ; ...' [m]: the PD particles whose kinetic and "
                        "strain energy the history records as pure_pd_* (e.g. the pure PD zone "
                        "of a coupled run, in its pure-PD reference). Empty: "
                        "Peridynamics/Region.");
      prm.leave_subsection();
    }

    void
    Output::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      directory         = prm.get("Directory");
      base_name         = prm.get("Base name");
      output_interval   = prm.get_integer("Output interval");
      energy_interval   = prm.get_integer("Energy interval");
      progress_interval = prm.get_double("Progress interval");
      print_timing      = prm.get_bool("Print timing summary");
      sample_line       = prm.get("Sample line");
      monitor_region    = prm.get("Monitor region");
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace PeriArlequin
