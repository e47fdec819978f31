#include <periarlequin/base/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <limits>
#include <sstream>

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
    Geometry::entries(ParameterEntries &entries)
    {
      entries.add("Mesh file",
                  mesh_file,
                  Patterns::Anything(),
                  "A Gmsh mesh (.msh, format 2 or 4, ASCII; quadrilaterals in 2D, hexahedra "
                  "in 3D) as the coarse mesh, a path relative to the parameter file's "
                  "directory; empty: the box below. Boundary ids are the physical tags of its "
                  "lines (2D) or surfaces (3D): ids 0 to 2 dim - 1 take Boundary conditions/"
                  "Boundary <id>, larger ids are free. Lower corner, Upper corner and "
                  "Subdivisions are then not used (the PD lattice is anchored at the mesh's "
                  "bounding box). The PD region's boxes must follow cell faces (mesh them as "
                  "surfaces of their own); an adaptive PD zone grows from them by whole "
                  "cells.");
      entries.add("Lower corner",
                  lower_corner,
                  Patterns::List(Patterns::Double(), 2, 3),
                  "Lower corner of the box domain, one coordinate per dimension [m].");
      entries.add("Upper corner",
                  upper_corner,
                  Patterns::List(Patterns::Double(), 2, 3),
                  "Upper corner of the box domain, one coordinate per dimension [m].");
      entries.add("Subdivisions",
                  subdivisions,
                  Patterns::List(Patterns::Integer(1), 2, 3),
                  "Number of coarse cells in each direction. Boundary ids are 0/1 on the "
                  "lower/upper x faces, 2/3 on the y faces and 4/5 on the z faces.");
      entries.add("Global refinements",
                  global_refinements,
                  Patterns::Integer(0, 12),
                  "Uniform refinements of the coarse mesh (each halves the cell size).");
    }

    void
    Geometry::declare_parameters(ParameterHandler &prm)
    {
      ParameterEntries::declare<Geometry>(prm, "Geometry");
    }

    namespace
    {
      template <typename T>
      std::string
      list_text(const std::vector<T> &values)
      {
        std::ostringstream text;
        for (unsigned int i = 0; i < values.size(); ++i)
          text << (i > 0 ? ", " : "") << values[i];
        return text.str();
      }
    } // namespace

    void
    Geometry::parse_parameters(ParameterHandler &prm, const unsigned int dim)
    {
      ParameterEntries::parse(prm, "Geometry", *this);
      // A mesh file replaces the box (its corners become the mesh's bounding box).
      if (!mesh_file.empty())
        {
          lower_corner.resize(dim);
          upper_corner.resize(dim);
          return;
        }
      const auto check_size = [&](const std::string &name, const auto &values) {
        if (values.size() != dim)
          throw_invalid_parameter("Geometry/" + name,
                                  list_text(values),
                                  "a list of exactly " + std::to_string(dim) +
                                    " numbers (one per dimension, Dimension = " +
                                    std::to_string(dim) + ")");
      };
      check_size("Lower corner", lower_corner);
      check_size("Upper corner", upper_corner);
      check_size("Subdivisions", subdivisions);
      for (unsigned int d = 0; d < dim; ++d)
        if (!(upper_corner[d] > lower_corner[d]))
          throw_invalid_parameter("Geometry/Upper corner",
                                  list_text(upper_corner),
                                  "coordinates strictly above those of 'Lower corner' (" +
                                    list_text(lower_corner) + ")");
    }

    void
    Material::entries(ParameterEntries &entries)
    {
      entries.add("Young's modulus", youngs_modulus, Patterns::Double(), "Young's modulus E [Pa].");
      entries.add("Poisson's ratio",
                  poissons_ratio,
                  Patterns::Double(),
                  "Poisson's ratio nu [-], in (-1, 0.5).");
      entries.add("Density", density, Patterns::Double(), "Mass density rho [kg/m^3].");
      entries.add("Two-dimensional model",
                  planar_model,
                  planar_model_names,
                  "How a 2D run treats the third direction. Ignored in 3D.");
    }

    void
    Material::declare_parameters(ParameterHandler &prm)
    {
      ParameterEntries::declare<Material>(prm, "Material");
    }

    void
    Material::parse_parameters(ParameterHandler &prm)
    {
      ParameterEntries::parse(prm, "Material", *this);
      if (!(youngs_modulus > 0))
        throw_invalid_parameter("Material/Young's modulus", youngs_modulus, "a value > 0 [Pa]");
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
      const double mu = shear_modulus();
      const double lambda =
        youngs_modulus * poissons_ratio / ((1. + poissons_ratio) * (1. - 2. * poissons_ratio));
      if (dim == 2 && planar_model == PlanarModel::plane_stress)
        return 2. * lambda * mu / (lambda + 2. * mu);
      return lambda;
    }

    double
    Material::longitudinal_wave_speed(const unsigned int dim) const
    {
      return std::sqrt((effective_lambda(dim) + 2. * shear_modulus()) / density);
    }

    double
    Material::shear_wave_speed() const
    {
      return std::sqrt(shear_modulus() / density);
    }

    void
    FiniteElements::entries(ParameterEntries &entries)
    {
      entries.add("Polynomial degree",
                  degree,
                  Patterns::Integer(1, 4),
                  "Degree of the FE_Q displacement element of the classical zone.");
    }

    void
    FiniteElements::declare_parameters(ParameterHandler &prm)
    {
      ParameterEntries::declare<FiniteElements>(prm, "Finite elements");
    }

    void
    FiniteElements::parse_parameters(ParameterHandler &prm)
    {
      ParameterEntries::parse(prm, "Finite elements", *this);
    }

    void
    Time::entries(ParameterEntries &entries)
    {
      entries.add("Integration",
                  integration,
                  integration_names,
                  "explicit: the explicit loop from the initial conditions. static then "
                  "explicit: first the static equilibrium under the loads and prescribed "
                  "displacements of t = 0 (dynamic relaxation, see subsection Static solve; "
                  "bonds do not break in it), then the explicit loop from it at rest: a body "
                  "that stores elastic energy before the dynamics starts (the energy history "
                  "starts with the stored strain energy and the work that stored it). "
                  "quasi-static: no dynamics; a static equilibrium at each t = k x Static "
                  "solve/Load step up to the end time, where t is the time of the loads and "
                  "prescribed displacements; after each equilibrium the bonds beyond their "
                  "limit break and the body is equilibrated again, until none breaks "
                  "(quasi-static fracture). History rows and outputs count increments.");
      entries.add("Time step",
                  time_step,
                  Patterns::Double(),
                  "Step dt of the explicit integrator [s]; must be > 0 and not above the "
                  "estimated stable step 2/sqrt(lambda_max(M^-1 K)).");
      entries.add("End time", end_time, Patterns::Double(), "Simulated end time [s], > 0.");
      entries.add("Stability estimate iterations",
                  stability_iterations,
                  Patterns::Integer(1),
                  "Maximum power iterations for the largest eigenvalue of M^-1 K.");
    }

    void
    Time::declare_parameters(ParameterHandler &prm)
    {
      ParameterEntries::declare<Time>(prm, "Time");
    }

    void
    Time::parse_parameters(ParameterHandler &prm)
    {
      ParameterEntries::parse(prm, "Time", *this);
      if (!(time_step > 0))
        throw_invalid_parameter("Time/Time step", time_step, "a value > 0 [s]");
      if (!(end_time > 0))
        throw_invalid_parameter("Time/End time", end_time, "a value > 0 [s]");
      // The step counter is an unsigned int; a billion steps is beyond any run of this code.
      // (A quasi-static run counts load increments instead, checked with Static solve.)
      const double max_steps = 1e9;
      if (integration != Integration::quasi_static && !(end_time / time_step <= max_steps))
        {
          std::ostringstream allowed;
          allowed << "at most " << max_steps << " time steps, End time <= " << max_steps * time_step
                  << " s with Time step = " << time_step << " s";
          throw_invalid_parameter("Time/End time", end_time, allowed.str());
        }
    }

    void
    Output::entries(ParameterEntries &entries)
    {
      entries.add("Directory",
                  directory,
                  Patterns::DirectoryName(),
                  "Directory for the .pvtu/.pvd files and the energy history (created if "
                  "missing).");
      entries.add("Base name", base_name, Patterns::FileName(), "Prefix of output files.");
      entries.add("Output interval",
                  output_interval,
                  Patterns::Integer(0),
                  "Write fields every this many steps (0: never) [steps].");
      entries.add("Energy interval",
                  energy_interval,
                  Patterns::Integer(0),
                  "Record the energy history every this many steps (0: never) [steps].");
      entries.add("Progress interval",
                  progress_interval,
                  Patterns::Double(0),
                  "Print a progress line at most every this many wall-clock seconds (0: "
                  "never) [s].");
      entries.add("Compression",
                  compression,
                  output_compression_names,
                  "zlib level of the .vtu data: fast (zlib's fastest), small (its smallest, "
                  "deal.II's default: files about 20 % smaller, several times slower to "
                  "write) or none.");
      entries.add("Print timing summary",
                  print_timing,
                  Patterns::Bool(),
                  "Print the TimerOutput summary at the end of the run.");
      entries.add(
        "Sample line",
        sample_line,
        Patterns::Anything(),
        "Segment 'x0, y0 : x1, y1' [m]: with every field output, write "
        "<base>_line_<step>.csv with the displacement and velocity of the FE nodes on it and "
        "the PD particles within half a lattice spacing of it. Empty: none.");
      entries.add("Monitor region",
                  monitor_region,
                  Patterns::Anything(),
                  "Boxes 'lower : upper ; ...' [m]: the PD particles whose kinetic and strain "
                  "energy the history records as pure_pd_* (e.g. the pure PD zone of a "
                  "coupled run, in its pure-PD reference). Empty: Peridynamics/Region.");
    }

    void
    Output::declare_parameters(ParameterHandler &prm)
    {
      ParameterEntries::declare<Output>(prm, "Output");
    }

    void
    Output::parse_parameters(ParameterHandler &prm)
    {
      ParameterEntries::parse(prm, "Output", *this);
    }

    void
    Checkpoint::entries(ParameterEntries &entries)
    {
      entries.add("Interval",
                  interval,
                  Patterns::Integer(0),
                  "Write a checkpoint every this many steps (0: never) [steps]. Two are kept, "
                  "in <Output/Directory>/<Output/Base name>_checkpoint_{0,1}; the file "
                  "<base>_checkpoint.last names the newest complete one.");
      entries.add("Wall time interval",
                  wall_time_interval,
                  Patterns::Double(0),
                  "Also write one when this much wall-clock time has passed since the start "
                  "or the last checkpoint (0: never) [s].");
      entries.add("At end",
                  at_end,
                  Patterns::Bool(),
                  "Write one after the last step (to continue later with a larger "
                  "Time/End time).");
      entries.add("Resume",
                  resume,
                  Patterns::Bool(),
                  "Continue from the newest complete checkpoint of Output/Directory and "
                  "Output/Base name, on any number of ranks. The other parameters must be "
                  "those of the checkpointed run, except the subsections Output and "
                  "Checkpoint and Time/End time.");
    }

    void
    Checkpoint::declare_parameters(ParameterHandler &prm)
    {
      ParameterEntries::declare<Checkpoint>(prm, "Checkpoint");
    }

    void
    Checkpoint::parse_parameters(ParameterHandler &prm)
    {
      ParameterEntries::parse(prm, "Checkpoint", *this);
    }
  } // namespace Parameters
} // namespace PeriArlequin
