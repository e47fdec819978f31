#ifndef periarlequin_tests_coupled_cases_h
#define periarlequin_tests_coupled_cases_h

#include "../tests.h"

#include <cmath>
#include <sstream>

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
           "\n  set Overlap region = " + overlap + "\n  set Finite element region = " +
           fe_region + "\nend\n";
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
         << aluminium()
         << "subsection Peridynamics\n  set Region = -0.06, -0.06 : 0.06, 0.06\n"
         << "  set Lattice spacing = 0.005\nend\n";
    std::ostringstream overlap, fe;
    overlap << -a << ", " << -a << " : -0.06, " << a << " ; 0.06, " << -a << " : " << a << ", "
            << a << " ; -0.06, " << -a << " : 0.06, -0.06 ; -0.06, 0.06 : 0.06, " << a;
    fe << "-0.2, -0.2 : " << -a << ", 0.2 ; " << a << ", -0.2 : 0.2, 0.2 ; " << -a
       << ", -0.2 : " << a << ", " << -a << " ; " << -a << ", " << a << " : " << a << ", 0.2";
    text << coupling_text(method, blending, "cg", false, overlap.str(), fe.str());
    text << "subsection Time\n  set Time step = 2e-7\n  set End time = " << end_time
         << "\nend\n"
         << "subsection Initial conditions\n"
         << "  subsection Displacement\n    set Function expression = " << initial_displacement
         << "\n  end\n"
         << "  subsection Velocity\n    set Function expression = " << initial_velocity
         << "\n  end\nend\n";
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
         << "subsection Initial conditions\n"
         << "  subsection Displacement\n    set Function expression = " << initial_displacement
         << "\n  end\n"
         << "  subsection Velocity\n    set Function expression = " << initial_velocity
         << "\n  end\nend\n"
         << quiet_output() << "subsection Output\n  set Energy interval = " << energy_interval
         << "\n  set Monitor region = -0.4, -0.04 : 0.4, 0.04\nend\n";
    return text.str();
  }

  /**
   * The paper's section 6.1 wave study at half its resolution: every length doubled (PD
   * lattice 5 mm, m = 3.015; FE cells 40 mm; pulse of eq. 81 with w1 = 0.96 m, w2 = 6 cm,
   * a1 = 0.6 mm), on a 4 m x 8 cm plate with pure PD on [-0.6, 0.6], overlaps of 5 FE cells
   * (0.2 m) and FE beyond. The short 6 cm component (1.5 FE cells) cannot enter the FE zone:
   * the coupling must absorb it. Energy is recorded every 1e-5 s up to 5e-4 s, the last time
   * before the leading edge, reflected at a plate end, comes back to the overlap
   * ((2 - 0.48 + 1.2) m at 5.3 km/s). @p method "none" runs PD on the whole plate.
   */
  inline std::string
  half_resolution_wave_case(const std::string &method, const bool damping, const double time_step)
  {
    std::ostringstream text;
    text << "set Dimension = 2\n"
         << "subsection Geometry\n  set Lower corner = -2.0, -0.04\n"
         << "  set Upper corner = 2.0, 0.04\n  set Subdivisions = 100, 2\nend\n"
         << aluminium() << "subsection Peridynamics\n  set Region = "
         << (method == "none" ? "-2.0, -0.04 : 2.0, 0.04" : "-0.6, -0.04 : 0.6, 0.04")
         << "\n  set Lattice spacing = 0.005\nend\n";
    if (method != "none")
      text << coupling_text(method,
                            "energy",
                            "diagonal",
                            damping,
                            "-0.8, -0.04 : -0.6, 0.04 ; 0.6, -0.04 : 0.8, 0.04",
                            "-2.0, -0.04 : -0.8, 0.04 ; 0.8, -0.04 : 2.0, 0.04");
    text << "subsection Time\n  set Time step = " << time_step << "\n  set End time = 5e-4\nend\n"
         << "subsection Initial conditions\n  subsection Displacement\n"
         << "    set Function constants = a1=6e-4, a2=0.3, w1=0.96, w2=0.06\n"
         << "    set Function expression = if(abs(x) <= w1/2, "
         << "a1*(1+cos(2*pi*x/w1))*(1+a2*cos(2*pi*(x+w1/2)/w2)), 0); 0\n  end\nend\n"
         << quiet_output() << "subsection Output\n  set Energy interval = "
         << static_cast<unsigned int>(std::round(1e-5 / time_step))
         << "\n  set Monitor region = -0.6, -0.04 : 0.6, 0.04\nend\n";
    return text.str();
  }
} // namespace PeriArlequinTests

#endif
