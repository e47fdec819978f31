#ifndef periarlequin_tests_coupled_cases_h
#define periarlequin_tests_coupled_cases_h

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "../tests.h"

/**
 * Coupled cases shared by the coupling tests, as parameter text. Aluminium of the paper's
 * section 6.1 (E = 69 GPa, nu = 0.3, rho = 2700, plane stress); PD lattice 5 mm (m = 3.015,
 * the bonds reach 17.6 mm), FE cells 20 mm, so the ghost layer of one cell covers a family.
 */
namespace PeriArlequinTests
{
  inline std::string
  aluminium()
  {
    return "subsection Material\n"
           "  set Young's modulus = 69e9\n  set Poisson's ratio = 0.3\n"
           "  set Density = 2700\n  set Two-dimensional model = plane stress\n"
           "end\n";
  }

  inline std::string
  coupling_text(const std::string &method,
                const std::string &blending,
                const std::string &solver,
                const bool         damping,
                const std::string &overlap,
                const std::string &fe_region)
  {
    return "subsection Coupling\n  set Method = " + method + "\n  set Blending = " + blending +
           "\n  set Multiplier solver = " + solver +
           "\n  set Fine-scale damping = " + (damping ? "true" : "false") +
           "\n  set Overlap region = " + overlap + "\n  set Finite element region = " + fe_region +
           "\nend\n";
  }

  /**
   * A square plate [-0.2, 0.2]^2 whose centre [-0.06, 0.06]^2 is pure PD, ringed by an
   * overlap @p width wide and pure FE outside: no PD particle has a free surface, so uniform
   * fields are exact for both discretisations.
   */
  inline std::string
  ring_case(const double       width,
            const std::string &method,
            const std::string &blending,
            const std::string &initial_displacement,
            const std::string &initial_velocity,
            const bool         fixed_boundary,
            const double       end_time)
  {
    const double       a = 0.06 + width;
    std::ostringstream text;
    text << "set Dimension = 2\n"
         << "subsection Geometry\n  set Lower corner = -0.2, -0.2\n"
         << "  set Upper corner = 0.2, 0.2\n  set Subdivisions = 20, 20\nend\n"
         << aluminium() << "subsection Peridynamics\n  set Region = -0.06, -0.06 : 0.06, 0.06\n"
         << "  set Lattice spacing = 0.005\nend\n";
    std::ostringstream overlap, fe;
    overlap << -a << ", " << -a << " : -0.06, " << a << " ; 0.06, " << -a << " : " << a << ", " << a
            << " ; -0.06, " << -a << " : 0.06, -0.06 ; -0.06, 0.06 : 0.06, " << a;
    fe << "-0.2, -0.2 : " << -a << ", 0.2 ; " << a << ", -0.2 : 0.2, 0.2 ; " << -a
       << ", -0.2 : " << a << ", " << -a << " ; " << -a << ", " << a << " : " << a << ", 0.2";
    text << coupling_text(method, blending, "cg", false, overlap.str(), fe.str());
    text << "subsection Time\n  set Time step = 2e-7\n  set End time = " << end_time << "\nend\n"
         << "subsection Initial conditions\nsubsection function\n"
         << "  subsection Displacement\n    set Function expression = " << initial_displacement
         << "\n  end\n"
         << "  subsection Velocity\n    set Function expression = " << initial_velocity
         << "\n  end\nend\nend\n";
    if (fixed_boundary)
      {
        text << "subsection Boundary conditions\n";
        for (unsigned int b = 0; b < 4; ++b)
          text << "  subsection Boundary " << b << "\n    set Type = displacement\n"
               << "    subsection Function\n      set Function expression = "
               << initial_displacement << "\n    end\n  end\n";
        text << "end\n";
      }
    text << quiet_output();
    return text.str();
  }

  /** A smooth pulse for the strip case: u_x = 1e-4 cos^2(pi x / 0.4) m on |x| < 0.2 m. */
  inline const std::string smooth_pulse = "if(abs(x) < 0.2, 1e-4*cos(pi*x/0.4)^2, 0); 0";

  /**
   * A strip [-1.2, @p right_end] x [-0.04, 0.04] (FE cells 20 mm): pure PD on [-0.4, 0.4],
   * overlaps 0.1 m (5 cells) on both sides, pure FE beyond; @p method "none" with @p all_pd
   * makes the pure-PD reference (PD everywhere) and with !all_pd the pure-FE reference.
   */
  inline std::string
  strip_case(const std::string &method,
             const std::string &blending,
             const std::string &solver,
             const bool         damping,
             const bool         all_pd,
             const std::string &initial_displacement,
             const std::string &initial_velocity,
             const double       time_step,
             const double       end_time,
             const unsigned int energy_interval,
             const double       right_end = 1.2)
  {
    std::ostringstream text, whole_strip, fe_region;
    whole_strip << "-1.2, -0.04 : " << right_end << ", 0.04";
    fe_region << "-1.2, -0.04 : -0.5, 0.04 ; 0.5, -0.04 : " << right_end << ", 0.04";
    text << "set Dimension = 2\n"
         << "subsection Geometry\n  set Lower corner = -1.2, -0.04\n"
         << "  set Upper corner = " << right_end << ", 0.04\n  set Subdivisions = "
         << static_cast<unsigned int>(std::round((right_end + 1.2) / 0.02)) << ", 4\nend\n"
         << aluminium() << "subsection Peridynamics\n  set Region = "
         << (method == "none" ? (all_pd ? whole_strip.str() : "") : "-0.4, -0.04 : 0.4, 0.04")
         << "\n  set Lattice spacing = 0.005\nend\n";
    if (method != "none")
      text << coupling_text(method,
                            blending,
                            solver,
                            damping,
                            "-0.5, -0.04 : -0.4, 0.04 ; 0.4, -0.04 : 0.5, 0.04",
                            fe_region.str());
    text << "subsection Time\n  set Time step = " << time_step << "\n  set End time = " << end_time
         << "\nend\n"
         << "subsection Initial conditions\nsubsection function\n"
         << "  subsection Displacement\n    set Function expression = " << initial_displacement
         << "\n  end\n"
         << "  subsection Velocity\n    set Function expression = " << initial_velocity
         << "\n  end\nend\nend\n"
         << quiet_output() << "subsection Output\n  set Energy interval = " << energy_interval
         << "\n  set Monitor region = -0.4, -0.04 : 0.4, 0.04\nend\n";
    return text.str();
  }

  /**
   * parameter_files/arlequin_wave_2d_coarse.prm (the paper's section 6.1 wave study with
   * every length doubled: PD 5 mm, FE 40 mm, pure PD on [-0.6, 0.6], 0.2 m overlaps, FE
   * beyond; run up to 5e-4 s, the last time before a wave comes back from the plate ends)
   * under another coupling @p method, damping and time step; "none" runs PD on the whole
   * plate. Energy is recorded every 1e-5 s, nothing else is written.
   */
  inline std::string
  coarse_wave_case(const std::string &method, const bool damping, const double time_step)
  {
    std::ifstream file(PERIARLEQUIN_SOURCE_DIR "/parameter_files/arlequin_wave_2d_coarse.prm");
    AssertThrow(file, ExcMessage("cannot read parameter_files/arlequin_wave_2d_coarse.prm"));
    std::ostringstream text;
    text << file.rdbuf() << "subsection Coupling\n  set Method = " << method
         << "\n  set Fine-scale damping = " << (damping ? "true" : "false") << "\nend\n"
         << "subsection Time\n  set Time step = " << time_step << "\nend\n";
    if (method == "none")
      text << "subsection Peridynamics\n  set Region = -2.0, -0.04 : 2.0, 0.04\nend\n";
    text << quiet_output() << "subsection Output\n  set Energy interval = "
         << static_cast<unsigned int>(std::round(1e-5 / time_step))
         << "\n  set Monitor region = -0.6, -0.04 : 0.6, 0.04\nend\n";
    return text.str();
  }
  /**
   * A 3D bar [-0.1, 0.1] x [0, 0.02]^2 (FE cells 10 mm): pure PD on |x| <= 0.03 (lattice
   * 2.5 mm, m = 3.015), overlaps 0.03 <= |x| <= 0.05 (two cells), pure FE beyond, all
   * boundaries free.
   */
  inline std::string
  bar_case_3d(const std::string &method,
              const std::string &blending,
              const std::string &solver,
              const bool         damping,
              const std::string &displacement,
              const std::string &velocity,
              const double       time_step,
              const double       end_time)
  {
    std::ostringstream text;
    text << "set Dimension = 3\n"
         << "subsection Geometry\n  set Lower corner = -0.1, 0, 0\n"
         << "  set Upper corner = 0.1, 0.02, 0.02\n  set Subdivisions = 20, 2, 2\nend\n"
         << aluminium()
         << "subsection Peridynamics\n  set Region = -0.03, 0, 0 : 0.03, 0.02, 0.02\n"
         << "  set Lattice spacing = 0.0025\nend\n"
         << coupling_text(method,
                          blending,
                          solver,
                          damping,
                          "-0.05, 0, 0 : -0.03, 0.02, 0.02 ; 0.03, 0, 0 : 0.05, 0.02, 0.02",
                          "-0.1, 0, 0 : -0.05, 0.02, 0.02 ; 0.05, 0, 0 : 0.1, 0.02, 0.02")
         << "subsection Time\n  set Time step = " << time_step << "\n  set End time = " << end_time
         << "\nend\n"
         << "subsection Initial conditions\nsubsection function\n  subsection Displacement\n"
         << "    set Function expression = " << displacement
         << "\n  end\n  subsection Velocity\n    set Function expression = " << velocity
         << "\n  end\nend\nend\n"
         << quiet_output();
    return text.str();
  }
  /** A rigid motion for the rigid-motion tests: initial fields and their magnitudes. */
  struct RigidMotion
  {
    std::string name, displacement, velocity;
    double      u_max, v_max;
  };

  /**
   * Runs a coupled case started in a rigid motion and checks that it stays untouched: every
   * acceleration, FE and PD, below 1e-10 of a_scale = c^2 u_max / h^2 (the acceleration of
   * a node displaced by u_max against fixed neighbours one cell h away, c a wave speed), and
   * |g|, |g_dot| below 1e-12 of u_max, v_max times the square root of the number of
   * multipliers.
   */
  template <int dim>
  void
  check_rigid_motion(const std::string &parameters,
                     const std::string &name,
                     const RigidMotion &motion,
                     const double       c,
                     const double       h)
  {
    auto simulator = make_simulator<dim>(parameters);
    simulator->run();
    double      a_max = simulator->get_acceleration().linfty_norm();
    const auto &pd    = *simulator->get_pd_zone();
    for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
      a_max = std::max(a_max, pd.get_state().accelerations()[i].norm());
    a_max = Utilities::MPI::max(a_max, MPI_COMM_WORLD);
    check_below(name + ": max acceleration / a_scale",
                a_max / (c * c * motion.u_max / (h * h)),
                1e-10);
    const auto   residuals = simulator->get_coupling()->constraint_residuals();
    const double rows      = std::sqrt(simulator->get_coupling()->n_multipliers());
    check_below(name + ": |g| / (u_max sqrt(rows))",
                residuals.first / (motion.u_max * rows),
                1e-12);
    if (motion.v_max > 0)
      check_below(name + ": |g_dot| / (v_max sqrt(rows))",
                  residuals.second / (motion.v_max * rows),
                  1e-12);
  }
  /**
   * A glass plate [0, 0.1] x [0, 0.04] m (E = 72 GPa, nu = 0.22, rho = 2440, plane stress:
   * the branching benchmark's material) pulled by a traction of @p stress [Pa] applied at
   * t = 0 on its top and bottom edges. PD lattice @p dx with horizon 3.2 dx; FE cells
   * @p cell; with @p coupled the PD region is the strip |y - 0.02| <= @p half_strip, with
   * overlaps @p overlap wide above and below it and FE beyond (weak coupling, @p blending,
   * fine-scale damping), otherwise PD everywhere. @p extra is appended (e.g. fracture and
   * pre-cracks).
   */
  inline std::string
  glass_plate_case(const bool         coupled,
                   const double       dx,
                   const double       cell,
                   const double       half_strip,
                   const double       overlap,
                   const double       stress,
                   const double       time_step,
                   const double       end_time,
                   const std::string &blending = "force",
                   const std::string &extra    = "")
  {
    std::ostringstream text;
    const double       a = 0.02 - half_strip, b = 0.02 + half_strip;
    text << "set Dimension = 2\n"
         << "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = 0.1, 0.04\n"
         << "  set Subdivisions = " << std::lround(0.1 / cell) << ", " << std::lround(0.04 / cell)
         << "\nend\n"
         << "subsection Material\n  set Young's modulus = 72e9\n  set Poisson's ratio = 0.22\n"
         << "  set Density = 2440\n  set Two-dimensional model = plane stress\nend\n"
         << "subsection Peridynamics\n  set Region = 0, " << (coupled ? a : 0.) << " : 0.1, "
         << (coupled ? b : 0.04) << "\n  set Lattice spacing = " << dx
         << "\n  set Horizon factor = 3.2\nend\n"
         << opposite_y_tractions(stress, 2);
    if (coupled)
      {
        std::ostringstream overlap_text, fe_text;
        overlap_text << "0, " << a - overlap << " : 0.1, " << a << " ; 0, " << b << " : 0.1, "
                     << b + overlap;
        fe_text << "0, 0 : 0.1, " << a - overlap << " ; 0, " << b + overlap << " : 0.1, 0.04";
        text
          << coupling_text("weak", blending, "diagonal", true, overlap_text.str(), fe_text.str());
      }
    text << "subsection Time\n  set Time step = " << time_step << "\n  set End time = " << end_time
         << "\nend\n"
         << quiet_output() << extra;
    return text.str();
  }
  /**
   * The notched glass plate at a coarse resolution (lattice 0.625 mm, delta = 2 mm, FE cells
   * 2.5 mm, time step 40 ns): glass_plate_case with fracture (G0 = 3.8 J/m^2), a 50 mm notch
   * along y = 20 mm from the left edge, PD strip |y - 20 mm| <= @p half_strip with overlaps
   * up to 5 mm from the loaded edges (force blending) or PD everywhere, the crack
   * diagnostics recorded every 1 us, to @p end_time.
   */
  inline std::string
  notched_glass_plate_case(const bool coupled, const double half_strip, const double end_time)
  {
    return glass_plate_case(coupled,
                            6.25e-4,
                            0.0025,
                            half_strip,
                            0.015 - half_strip,
                            2e6,
                            4e-8,
                            end_time,
                            "force",
                            "subsection Peridynamics\n  set Fracture = true\n"
                            "  set Critical energy release rate = 3.8\n"
                            "  set Pre-cracks = 0, 0.02 : 0.05, 0.02\nend\n"
                            "subsection Output\n  set Energy interval = 25\nend\n"
                            "subsection Postprocess\n  set List of postprocessors = energies, "
                            "cracks\nend\n");
  }
  /**
   * The mixed-mode case of the paper's section 6.4 (studies/mixed_mode/run.sh): a 62.5 mm square
   * (E = 29 GPa, nu = 0.29, rho = 2400, G0 = 36 kJ/m^2, plane strain) with a crack from the
   * middle of its left side to the centre, the crack-tip field on its four sides with
   * K_eff = Kdot t at the phase angle @p psi [deg], Kdot such that G = G0 at @p critical_time,
   * run to @p end_time; the time step is 1e-7 s x 128 / n. A lattice of @p n sites per side,
   * horizon factor @p m, @p cells FE cells per side; coupled: PD for x <= A c, |y| <= H c (c the
   * cell size, H c >= 7 delta, A c >= 6 delta), overlaps of 2 cells, FE beyond, weak coupling,
   * force blending, damping constant 10 (the paper's 30 over-damps these narrow overlaps at this
   * time step). The crack diagnostics follow the tip at the centre; bonds break as the fracture
   * criterion
   * @p criterion says.
   */
  inline std::string
  mixed_mode_case(const bool         coupled,
                  const unsigned int n,
                  const double       m,
                  const unsigned int cells,
                  const double       psi,
                  const double       critical_time,
                  const double       end_time,
                  const std::string &criterion = "critical stretch")
  {
    const double       L = 0.03125, dx = 2 * L / n, c = 2 * L / cells, delta = m * dx;
    const double       kc = std::sqrt(36e3 * 29e9 / (1 - 0.29 * 0.29));
    std::ostringstream text;
    text << std::setprecision(15) << "set Dimension = 2\n"
         << "subsection Geometry\n  set Lower corner = " << -L << ", " << -L
         << "\n  set Upper corner = " << L << ", " << L << "\n  set Subdivisions = " << cells
         << ", " << cells << "\nend\n"
         << "subsection Material\n  set Young's modulus = 29e9\n  set Poisson's ratio = 0.29\n"
         << "  set Density = 2400\n  set Two-dimensional model = plane strain\nend\n"
         << "subsection Peridynamics\n  set Lattice spacing = " << dx
         << "\n  set Horizon factor = " << m
         << "\n  set Fracture = true\n  set Fracture criterion = " << criterion
         << "\n  set Critical energy release rate = 36e3\n"
         << "  set Pre-cracks = " << -L << ", 0 : 0, 0\n";
    if (!coupled)
      text << "  set Region = " << -L << ", " << -L << " : " << L << ", " << L << "\nend\n";
    else
      {
        const double y1 = std::ceil(7 * delta / c - 1e-9) * c;
        const double x1 = std::ceil(6 * delta / c - 1e-9) * c;
        const double oy = y1 + 2 * c, ox = x1 + 2 * c;
        text << "  set Region = " << -L << ", " << -y1 << " : " << x1 << ", " << y1 << "\nend\n"
             << "subsection Coupling\n  set Method = weak\n  set Blending = force\n"
             << "  set Damping constant = 10\n"
             << "  set Overlap region = " << -L << ", " << y1 << " : " << ox << ", " << oy << " ; "
             << -L << ", " << -oy << " : " << ox << ", " << -y1 << " ; " << x1 << ", " << -y1
             << " : " << ox << ", " << y1 << "\n"
             << "  set Finite element region = " << -L << ", " << oy << " : " << L << ", " << L
             << " ; " << -L << ", " << -L << " : " << L << ", " << -oy << " ; " << ox << ", " << -oy
             << " : " << L << ", " << oy << "\nend\n";
      }
    text << "subsection Boundary conditions\n  subsection Crack tip field\n"
         << "    set Boundary ids = 0, 1, 2, 3\n    set Tip = 0, 0\n"
         << "    set Stress intensity factor = " << kc / critical_time << "*t\n"
         << "    set Phase angle = " << psi << "\n  end\nend\n"
         << "subsection Time\n  set Time step = " << 1e-7 * 128 / n
         << "\n  set End time = " << end_time << "\nend\n"
         << "subsection Postprocess\n  set List of postprocessors = energies, cracks\n"
         << "  subsection cracks\n    set Initial tip = 0, 0\n  end\nend\n"
         << quiet_output() << "subsection Output\n  set Energy interval = 10\nend\n";
    return text.str();
  }
} // namespace PeriArlequinTests

#endif
