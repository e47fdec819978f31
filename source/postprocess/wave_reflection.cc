#include <deal.II/base/utilities.h>

#include <periarlequin/base/parameters.h>
#include <periarlequin/postprocess/wave_reflection.h>
#include <periarlequin/simulator.h>

#include <cmath>
#include <map>
#include <sstream>

namespace PeriArlequin
{
  void
  WaveReflection::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Wave reflection");
    prm.declare_entry("FE cell size", "0.02", Patterns::Double(0), "FE cell size h [m].");
    prm.declare_entry("Size ratio",
                      "8",
                      Patterns::Integer(4),
                      "h / dx, the FE cell over the PD lattice spacing; at least 4 so that a "
                      "cell holds the bonds of m = 3 [-].");
    prm.declare_entry("Overlap cells", "5", Patterns::Integer(1), "Overlap width in FE cells [-].");
    prm.declare_entry("Wavelength", "6", Patterns::Double(0), "The packet's wavelength / h [-].");
    prm.declare_entry("Horizon factor", "3.015", Patterns::Double(1), "m = delta / dx [-].");
    prm.declare_entry("Time step fraction",
                      "1",
                      Patterns::Double(0),
                      "The time step over 0.2 dx / c_L (about a fifth of the PD stable step) [-].");
    prm.declare_entry("Coupling",
                      "set Method = weak",
                      Patterns::Anything(),
                      "Entries of the Coupling subsection other than the regions, separated by "
                      "';' (e.g. 'set Method = weak; set Damping constant = 30').");
    prm.leave_subsection();
  }

  void
  WaveReflection::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Wave reflection");
    fe_cell_size       = prm.get_double("FE cell size");
    size_ratio         = prm.get_integer("Size ratio");
    overlap_cells      = prm.get_integer("Overlap cells");
    wavelength         = prm.get_double("Wavelength");
    horizon_factor     = prm.get_double("Horizon factor");
    time_step_fraction = prm.get_double("Time step fraction");
    coupling.clear();
    for (const auto &entry : Utilities::split_string_list(prm.get("Coupling"), ';'))
      coupling += entry + "\n";
    prm.leave_subsection();
    if (!(size_ratio + 0.5 >= horizon_factor + 0.5))
      throw_invalid_parameter("Wave reflection/Size ratio",
                              std::to_string(size_ratio),
                              "at least the horizon factor + 1/2, so that one FE cell holds a "
                              "particle's bonds (the ghost layer)");
  }

  namespace
  {
    /** The strip's lengths [m], whole FE cells each, and the measuring time [s]. */
    struct StripLayout
    {
      double sigma, x0, pure_pd_end, overlap_end, length, end_time;
    };

    StripLayout
    layout(const WaveReflection &study)
    {
      const double h = study.fe_cell_size, lambda = study.wavelength * h;
      const double c = std::sqrt(WaveReflection::youngs_modulus / WaveReflection::density);
      const auto   cells = [h](const double length) { return h * std::ceil(length / h - 1e-9); };
      StripLayout  strip;
      strip.sigma               = lambda;
      const double half_extent  = 3.5 * strip.sigma;
      strip.x0                  = half_extent + h;
      strip.pure_pd_end         = cells(strip.x0 + half_extent + 2 * h);
      const double width        = study.overlap_cells * h;
      strip.overlap_end         = strip.pure_pd_end + width;
      // The reflection, centred mid-overlap, must be back in the pure PD zone with its whole
      // extent and a cell to spare; the slower group speed of short waves is allowed for.
      const double path = (strip.pure_pd_end + width / 2 - strip.x0) + (width / 2 + half_extent + h);
      strip.end_time    = path / (0.8 * c);
      // The transmitted wave must not come back from the strip's end by then.
      strip.length = strip.overlap_end + cells(0.5 * (c * strip.end_time - width) + 2 * h);
      return strip;
    }
  } // namespace

  std::string
  WaveReflection::case_text(const bool reference) const
  {
    const StripLayout  strip = layout(*this);
    const double       h = fe_cell_size, dx = h / size_ratio, k = 2 * M_PI / (wavelength * h);
    const double       c_bar = std::sqrt(youngs_modulus / density);
    const double       c_l   = std::sqrt(youngs_modulus / (density * (1 - poissons_ratio * poissons_ratio)));
    std::ostringstream text;
    text << std::setprecision(17);
    // u = A g cos(k s), s = x - x0, g = exp(-s^2 / (2 sigma^2)); its derivatives by hand.
    std::ostringstream s, g, u1, u2;
    s << "(x - " << strip.x0 << ")";
    g << "exp(-" << s.str() << "^2 / " << 2 * strip.sigma * strip.sigma << ")";
    const double amplitude = 1e-5, yc = 0.5 * h;
    u1 << amplitude << " * " << g.str() << " * (-" << s.str() << " / " << strip.sigma * strip.sigma
       << " * cos(" << k << " * " << s.str() << ") - " << k << " * sin(" << k << " * " << s.str()
       << "))";
    u2 << amplitude << " * " << g.str() << " * ((" << s.str() << "^2 / " << std::pow(strip.sigma, 4)
       << " - " << 1 / (strip.sigma * strip.sigma) << " - " << k * k << ") * cos(" << k << " * "
       << s.str() << ") + " << 2 * k / (strip.sigma * strip.sigma) << " * " << s.str() << " * sin("
       << k << " * " << s.str() << "))";
    const double length = strip.length;
    text << "set Dimension = 2\n"
         << "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = " << length << ", "
         << h << "\n  set Subdivisions = " << std::lround(length / h) << ", 1\nend\n"
         << "subsection Material\n  set Young's modulus = " << youngs_modulus
         << "\n  set Poisson's ratio = " << poissons_ratio << "\n  set Density = " << density
         << "\n  set Two-dimensional model = plane stress\nend\n"
         << "subsection Peridynamics\n  set Region = 0, 0 : "
         << (reference ? length : strip.pure_pd_end) << ", " << h
         << "\n  set Lattice spacing = " << dx << "\n  set Horizon factor = " << horizon_factor
         << "\nend\n";
    if (!reference)
      text << "subsection Coupling\n"
           << coupling << "  set Overlap region = " << strip.pure_pd_end << ", 0 : "
           << strip.overlap_end << ", " << h << "\n  set Finite element region = "
           << strip.overlap_end << ", 0 : " << length << ", " << h << "\nend\n";
    // The packet moving to +x (v = -c u'), with the lateral strain -nu u' of uniaxial stress.
    text << "subsection Initial conditions\n  subsection function\n    subsection Displacement\n"
         << "      set Function expression = " << amplitude << " * " << g.str() << " * cos(" << k
         << " * " << s.str() << "); " << -poissons_ratio << " * " << u1.str() << " * (y - " << yc
         << ")\n    end\n    subsection Velocity\n      set Function expression = " << -c_bar
         << " * " << u1.str() << "; " << poissons_ratio * c_bar << " * " << u2.str() << " * (y - "
         << yc << ")\n    end\n  end\nend\n"
         << "subsection Time\n  set Time step = " << time_step_fraction * 0.2 * dx / c_l
         << "\n  set End time = " << strip.end_time << "\nend\n"
         << "subsection Postprocess\n  set List of postprocessors = energies\nend\n"
         << "subsection Output\n  set Directory = .\n  set Output interval = 0\n"
         << "  set Energy interval = 0\n  set Progress interval = 0\n"
         << "  set Print timing summary = false\nend\n";
    return text.str();
  }

  namespace
  {
    std::unique_ptr<Simulator<2>>
    make(const std::string &text, const MPI_Comm communicator)
    {
      ParameterHandler prm;
      Simulator<2>::declare_parameters(prm);
      prm.parse_input_from_string(text);
      return std::make_unique<Simulator<2>>(prm, communicator);
    }
  } // namespace

  WaveReflection::Result
  WaveReflection::measure(const MPI_Comm communicator) const
  {
    const StripLayout strip     = layout(*this);
    auto              reference = make(case_text(true), communicator);
    auto              coupled   = make(case_text(false), communicator);
    reference->setup();
    coupled->setup();
    const PDZone<2> &pd_reference = *reference->get_pd_zone();
    Result           result;
    result.incident_energy = pd_reference.kinetic_energy() + pd_reference.strain_energy();
    reference->run();
    coupled->run();
    result.time = coupled->get_time();

    // The pure-PD particles' velocities of both runs by id, on rank 0.
    const auto collect = [&](const PDZone<2> &pd, const bool with_mass) {
      std::vector<double> rows;
      for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
        if (pd.reference_positions()[i][0] < strip.pure_pd_end && pd.blending_weights()[i] == 0)
          {
            rows.push_back(pd.particle_ids()[i]);
            rows.push_back(with_mass ? pd.particle_mass(i) : 0.);
            rows.push_back(pd.get_state().velocities()[i][0]);
            rows.push_back(pd.get_state().velocities()[i][1]);
          }
      return Utilities::MPI::gather(communicator, rows, 0);
    };
    const auto mine   = collect(*coupled->get_pd_zone(), true);
    const auto theirs = collect(pd_reference, false);
    double     reflected = 0;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::map<double, std::array<double, 2>> velocity;
        for (const auto &part : theirs)
          for (unsigned int r = 0; r + 4 <= part.size(); r += 4)
            velocity[part[r]] = {{part[r + 2], part[r + 3]}};
        for (const auto &part : mine)
          for (unsigned int r = 0; r + 4 <= part.size(); r += 4)
            {
              const auto &w = velocity.at(part[r]);
              reflected += part[r + 1] * (std::pow(part[r + 2] - w[0], 2) + std::pow(part[r + 3] - w[1], 2));
            }
      }
    result.reflected = Utilities::MPI::broadcast(communicator, reflected, 0) / result.incident_energy;

    Region<2> pure_pd;
    pure_pd.boxes.push_back(Box<2>{Point<2>(0, 0), Point<2>(strip.pure_pd_end, fe_cell_size)});
    const auto   left     = pd_reference.energies_in(pure_pd);
    const double past     = pd_reference.kinetic_energy() + pd_reference.strain_energy() - left.first - left.second;
    const auto  &fe       = coupled->get_fe_zone();
    result.transmitted    = (fe.kinetic_energy() + fe.strain_energy()) / past;
    return result;
  }
} // namespace PeriArlequin
