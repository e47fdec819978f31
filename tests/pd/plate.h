#ifndef periarlequin_tests_pd_plate_h
#define periarlequin_tests_pd_plate_h

// A 40 mm square plane-stress plate of LPS particles (spacing dx), optionally with an edge
// pre-crack from x = 0 to the centre on y = 20 mm, pulled apart by its top and bottom
// layers (one horizon thick) displaced by +-U (1 - cos(pi t / T)) / 2 with T = n_steps dt,
// U such that the far-field strain ends at 0.5 of the critical stretch.

#include "../tests.h"

inline std::string
plate_parameters(const double dx, const bool pre_crack, const unsigned int n_steps)
{
  const double       E = 69e9, G0 = 1e3, delta = 3.015 * dx;
  const double       s_c = std::sqrt(4 * dealii::numbers::PI * G0 / (9 * E * delta));
  const double       H = 0.04, U = 0.5 * s_c * H / 2, dt = 0.25 * dx / 5300, T = n_steps * dt;
  std::ostringstream prm;
  prm << std::setprecision(17) << "set Dimension = 2\n"
      << "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = 0.04, 0.04\n"
      << "  set Subdivisions = 8, 8\nend\n"
      << "subsection Peridynamics\n  set Region = 0, 0 : 0.04, 0.04\n"
      << "  set Lattice spacing = " << dx << "\n  set Fracture = true\n"
      << "  set Critical energy release rate = " << G0 << "\n"
      << "  set Pre-cracks = " << (pre_crack ? "0, 0.02 : 0.02, 0.02" : "") << "\n"
      << "  set No-fail region = 0, 0 : 0.04, " << delta << " ; 0, " << H - delta
      << " : 0.04, 0.04\n"
      << "  subsection Prescribed region 0\n    set Region = 0, 0 : 0.04, " << delta << "\n"
      << "    set Components = y\n    subsection Function\n"
      << "      set Function constants = U=" << U << ", T=" << T << "\n"
      << "      set Function expression = 0; -U*(1-cos(pi*min(t,T)/T))/2\n    end\n  end\n"
      << "  subsection Prescribed region 1\n    set Region = 0, " << H - delta
      << " : 0.04, 0.04\n    set Components = y\n    subsection Function\n"
      << "      set Function constants = U=" << U << ", T=" << T << "\n"
      << "      set Function expression = 0; U*(1-cos(pi*min(t,T)/T))/2\n    end\n  end\n"
      << "end\n"
      << "subsection Time\n  set Time step = " << dt << "\n  set End time = " << T
      << "\n  set Stability estimate iterations = 50\nend\n"
      << PeriArlequinTests::quiet_output();
  return prm.str();
}

#endif
