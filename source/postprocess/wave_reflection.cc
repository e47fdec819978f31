#include <periarlequin/base/parameters.h>
#include <periarlequin/postprocess/wave_reflection.h>
#include <periarlequin/simulator.h>

#include <deal.II/base/utilities.h>

#include <array>
#include <cmath>
#include <map>
#include <sstream>

namespace PeriArlequin
{
  void
  WaveReflection::entries(ParameterEntries &entries)
  {
    entries.add("FE cell size", fe_cell_size, Patterns::Double(0), "FE cell size h [m].");
    entries.add("Size ratio",
                size_ratio,
                Patterns::Integer(4),
                "h / dx, the FE cell over the PD lattice spacing; at least 4 so that a cell "
                "holds the bonds of m = 3 [-].");
    entries.add("Overlap cells",
                overlap_cells,
                Patterns::Integer(1),
                "Overlap width in FE cells [-].");
    entries.add("Wavelength", wavelength, Patterns::Double(0), "The packet's wavelength / h [-].");
    entries.add("Horizon factor", horizon_factor, Patterns::Double(1), "m = delta / dx [-].");
    entries.add("Time step fraction",
                time_step_fraction,
                Patterns::Double(0),
                "The time step over 0.2 dx / c_L (about a fifth of the PD stable step) [-].");
    entries.add("Incident side",
                from_fe,
                SelectionNames<bool>{{"pd", false}, {"fe", true}},
                "Where the packet starts: in the pure PD zone or in the FE zone.");
    entries.add_parsed<std::string>(
      "Coupling",
      coupling,
      "set Method = weak",
      [](const std::string &text, const std::string &) {
        std::string lines;
        for (const auto &entry : Utilities::split_string_list(text, ';'))
          lines += entry + "\n";
        return lines;
      },
      "Entries of the Coupling subsection other than the regions, separated by ';' (e.g. "
      "'set Method = weak; set Damping constant = 30').");
  }

  void
  WaveReflection::declare_parameters(ParameterHandler &prm)
  {
    ParameterEntries::declare<WaveReflection>(prm, "Wave reflection");
  }

  void
  WaveReflection::parse_parameters(ParameterHandler &prm)
  {
    ParameterEntries::parse(prm, "Wave reflection", *this);
    if (size_ratio < horizon_factor + 0.5)
      throw_invalid_parameter("Wave reflection/Size ratio",
                              std::to_string(size_ratio),
                              "at least the horizon factor + 1/2 (" +
                                std::to_string(horizon_factor + 0.5) +
                                "), so that one FE cell holds a particle's bonds (the ghost "
                                "layer)");
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
      const double c     = std::sqrt(WaveReflection::youngs_modulus / WaveReflection::density);
      const auto   cells = [h](const double length) { return h * std::ceil(length / h - 1e-9); };
      StripLayout  strip;
      strip.sigma              = lambda;
      const double half_extent = 3.5 * strip.sigma;
      const double width       = study.overlap_cells * h;
      // The reflection, centred mid-overlap, must be back on the incident side with its whole
      // extent and a cell to spare; the slower group speed of short waves is allowed for.
      // The packet starts a cell farther from the overlap than its extent.
      const double path = 2 * half_extent + 3 * h + width;
      strip.end_time    = path / (0.8 * c);
      // What passes must not come back from the strip's end on the far side by then.
      const double far_side = cells(0.5 * (c * strip.end_time - width) + 2 * h);
      if (!study.from_fe)
        {
          strip.x0          = half_extent + h;
          strip.pure_pd_end = cells(strip.x0 + half_extent + 2 * h);
          strip.overlap_end = strip.pure_pd_end + width;
          strip.length      = strip.overlap_end + far_side;
        }
      else
        {
          strip.pure_pd_end = far_side;
          strip.overlap_end = strip.pure_pd_end + width;
          strip.x0          = strip.overlap_end + half_extent + 2 * h;
          strip.length      = cells(strip.x0 + half_extent + h);
        }
      return strip;
    }
  } // namespace

  std::string
  WaveReflection::case_text(const bool reference) const
  {
    const StripLayout strip = layout(*this);
    const double      h = fe_cell_size, dx = h / size_ratio, k = 2 * M_PI / (wavelength * h);
    const double      c_bar = std::sqrt(youngs_modulus / density);
    const double      c_l =
      std::sqrt(youngs_modulus / (density * (1 - poissons_ratio * poissons_ratio)));
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
         << "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = " << length
         << ", " << h << "\n  set Subdivisions = " << std::lround(length / h) << ", 1\nend\n"
         << "subsection Material\n  set Young's modulus = " << youngs_modulus
         << "\n  set Poisson's ratio = " << poissons_ratio << "\n  set Density = " << density
         << "\n  set Two-dimensional model = plane stress\nend\n"
         << "subsection Peridynamics\n  set Region = ";
    // The reference: PD everywhere for a packet from the PD side, FE everywhere from the FE side.
    if (!(reference && from_fe))
      text << "0, 0 : " << (reference ? length : strip.pure_pd_end) << ", " << h;
    text << "\n  set Lattice spacing = " << dx << "\n  set Horizon factor = " << horizon_factor
         << "\nend\n";
    if (!reference)
      text << "subsection Coupling\n"
           << coupling << "  set Overlap region = " << strip.pure_pd_end
           << ", 0 : " << strip.overlap_end << ", " << h
           << "\n  set Finite element region = " << strip.overlap_end << ", 0 : " << length << ", "
           << h << "\nend\n";
    // The packet moving towards the overlap (v = -c u' to +x, +c u' to -x), with the
    // lateral strain -nu u' of uniaxial stress.
    const double speed = from_fe ? -c_bar : c_bar;
    text << "subsection Initial conditions\n  subsection function\n    subsection Displacement\n"
         << "      set Function expression = " << amplitude << " * " << g.str() << " * cos(" << k
         << " * " << s.str() << "); " << -poissons_ratio << " * " << u1.str() << " * (y - " << yc
         << ")\n    end\n    subsection Velocity\n      set Function expression = " << -speed
         << " * " << u1.str() << "; " << poissons_ratio * speed << " * " << u2.str() << " * (y - "
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

  namespace
  {
    /**
     * Rows (key 1, key 2, mass, v_x, v_y) of this rank's owned PD particles (keys: id, 0) or
     * FE nodes (keys: position) whose x lies in [@p from, @p to], gathered on rank 0.
     */
    std::vector<std::vector<double>>
    collect(const Simulator<2> &simulator,
            const bool          fe_nodes,
            const double        from,
            const double        to,
            const MPI_Comm      communicator)
    {
      std::vector<double> rows;
      const auto          inside = [&](const Point<2> &x) { return x[0] >= from && x[0] <= to; };
      if (!fe_nodes)
        {
          const PDZone<2> &pd = *simulator.get_pd_zone();
          for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
            if (inside(pd.reference_positions()[i]) && pd.blending_weights()[i] == 0)
              rows.insert(rows.end(),
                          {double(pd.particle_ids()[i]),
                           0.,
                           pd.particle_mass(i),
                           pd.get_state().velocities()[i][0],
                           pd.get_state().velocities()[i][1]});
        }
      else
        {
          const FEZone<2>          &fe = simulator.get_fe_zone();
          std::vector<unsigned int> dofs, components;
          std::vector<Point<2>>     points;
          fe.support_points(dofs, points, components);
          std::map<std::pair<double, double>, std::array<double, 3>> nodes;
          for (unsigned int k = 0; k < dofs.size(); ++k)
            if (inside(points[k]))
              {
                auto &node              = nodes[{points[k][0], points[k][1]}];
                node[0]                 = fe.lumped_mass().local_element(dofs[k]);
                node[1 + components[k]] = fe.get_state().velocity.local_element(dofs[k]);
              }
          for (const auto &[x, node] : nodes)
            rows.insert(rows.end(), {x.first, x.second, node[0], node[1], node[2]});
        }
      return Utilities::MPI::gather(communicator, rows, 0);
    }

    /** On rank 0: sum m |v - v_ref|^2 over @p rows, v_ref of the same key in @p reference. */
    double
    difference_energy(const std::vector<std::vector<double>> &rows,
                      const std::vector<std::vector<double>> &reference)
    {
      std::map<std::pair<double, double>, std::array<double, 2>> velocity;
      for (const auto &part : reference)
        for (unsigned int r = 0; r + 5 <= part.size(); r += 5)
          velocity[{part[r], part[r + 1]}] = {{part[r + 3], part[r + 4]}};
      double sum = 0;
      for (const auto &part : rows)
        for (unsigned int r = 0; r + 5 <= part.size(); r += 5)
          {
            const auto &w = velocity.at({part[r], part[r + 1]});
            sum +=
              part[r + 2] * (std::pow(part[r + 3] - w[0], 2) + std::pow(part[r + 4] - w[1], 2));
          }
      return sum;
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
    const auto energy = [this](const Simulator<2> &simulator) {
      return from_fe ?
               simulator.get_fe_zone().kinetic_energy() + simulator.get_fe_zone().strain_energy() :
               simulator.get_pd_zone()->kinetic_energy() + simulator.get_pd_zone()->strain_energy();
    };
    Result result;
    result.incident_energy = energy(*reference);
    reference->run();
    coupled->run();
    result.time = coupled->get_time();

    // The incident side's pure zone: what came back is the difference there.
    const double from = from_fe ? strip.overlap_end + 1e-9 * fe_cell_size : 0.;
    const double to   = from_fe ? strip.length : strip.pure_pd_end;
    const auto   back = difference_energy(collect(*coupled, from_fe, from, to, communicator),
                                        collect(*reference, from_fe, from, to, communicator));
    const bool   root = Utilities::MPI::this_mpi_process(communicator) == 0;
    result.reflected =
      Utilities::MPI::broadcast(communicator, root ? back : 0., 0) / result.incident_energy;

    if (!from_fe)
      {
        // The FE zone's energy over what the reference carried past the pure PD zone.
        Region<2> pure_pd;
        pure_pd.boxes.push_back(Box<2>{Point<2>(0, 0), Point<2>(strip.pure_pd_end, fe_cell_size)});
        const auto  &pd    = *reference->get_pd_zone();
        const auto   left  = pd.energies_in(pure_pd);
        const double past  = pd.kinetic_energy() + pd.strain_energy() - left.first - left.second;
        const auto  &fe    = coupled->get_fe_zone();
        result.transmitted = (fe.kinetic_energy() + fe.strain_energy()) / past;
      }
    else
      {
        // The pure PD zone's energy over the packet's.
        Region<2> pure_pd;
        pure_pd.boxes.push_back(Box<2>{Point<2>(0, 0), Point<2>(strip.pure_pd_end, fe_cell_size)});
        const auto in_pd   = coupled->get_pd_zone()->energies_in(pure_pd);
        result.transmitted = (in_pd.first + in_pd.second) / result.incident_energy;
      }
    return result;
  }
} // namespace PeriArlequin
