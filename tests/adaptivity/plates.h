#ifndef periarlequin_tests_adaptivity_plates_h
#define periarlequin_tests_adaptivity_plates_h

// Parameter text of the plates that several adaptivity tests run: the dimension, the box
// mesh, the material and subsection Peridynamics (closed), to which a test adds its loads,
// coupling, adaptive settings and time.

#include <sstream>
#include <string>

namespace PeriArlequinTests
{
  /**
   * The notched glass plate 0.1 x 0.04 m (E = 72 GPa, nu = 0.22, 2440 kg/m^3, plane stress,
   * FE cells 2.5 mm), lattice 0.625 mm, horizon 3.2 dx = 2 mm, G0 = 3.8 J/m^2, a notch of
   * 50 mm along y = 20 mm, PD on @p region.
   */
  inline std::string
  notched_glass_plate(const std::string &region)
  {
    std::ostringstream text;
    text << "set Dimension = 2\n"
         << "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = 0.1, 0.04\n"
         << "  set Subdivisions = 40, 16\nend\n"
         << "subsection Material\n  set Young's modulus = 72e9\n  set Poisson's ratio = 0.22\n"
         << "  set Density = 2440\n  set Two-dimensional model = plane stress\nend\n"
         << "subsection Peridynamics\n  set Region = " << region << "\n"
         << "  set Lattice spacing = 6.25e-4\n  set Horizon factor = 3.2\n"
         << "  set Fracture = true\n  set Critical energy release rate = 3.8\n"
         << "  set Pre-cracks = 0, 0.02 : 0.05, 0.02\nend\n";
    return text.str();
  }

  /**
   * The steel plate 0.1 x 0.2 m (E = 190 GPa, nu = 0.3, 8000 kg/m^3, plane strain, FE cells
   * 5 mm) with two edge notches 50 mm long at y = 75 and 125 mm, struck between them: the
   * particles of x < 3 mm there move at 32 m/s in x. Lattice 1 mm, horizon 3.015 dx,
   * G0 = 22.17 kJ/m^2, PD on @p region.
   */
  inline std::string
  struck_steel_plate(const std::string &region)
  {
    std::ostringstream text;
    text << "set Dimension = 2\n"
         << "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = 0.1, 0.2\n"
         << "  set Subdivisions = 20, 40\nend\n"
         << "subsection Material\n  set Young's modulus = 190e9\n  set Poisson's ratio = 0.3\n"
         << "  set Density = 8000\n  set Two-dimensional model = plane strain\nend\n"
         << "subsection Peridynamics\n  set Region = " << region << "\n"
         << "  set Lattice spacing = 1e-3\n  set Horizon factor = 3.015\n"
         << "  set Fracture = true\n  set Critical energy release rate = 22170\n"
         << "  set Pre-cracks = 0, 0.075 : 0.05, 0.075 ; 0, 0.125 : 0.05, 0.125\n"
         << "  subsection Prescribed region 0\n    set Region = 0, 0.075 : 0.003, 0.125\n"
         << "    set Type = velocity\n    set Components = x\n"
         << "    subsection Function\n      set Function expression = 32; 0\n    end\n  end\n"
         << "end\n";
    return text.str();
  }

  /**
   * The notched glass plate in 3D, 0.06 x 0.04 x 0.008 m (E = 72 GPa, nu = 0.22,
   * 2440 kg/m^3, FE cells 4 mm), lattice 1 mm, horizon 3.015 dx, G0 = 3.8 J/m^2, a
   * through-thickness notch 30 mm long along y = 20 mm, PD on @p region.
   */
  inline std::string
  notched_glass_plate_3d(const std::string &region)
  {
    std::ostringstream text;
    text << "set Dimension = 3\n"
         << "subsection Geometry\n  set Lower corner = 0, 0, 0\n"
         << "  set Upper corner = 0.06, 0.04, 0.008\n  set Subdivisions = 15, 10, 2\nend\n"
         << "subsection Material\n  set Young's modulus = 72e9\n  set Poisson's ratio = 0.22\n"
         << "  set Density = 2440\nend\n"
         << "subsection Peridynamics\n  set Region = " << region << "\n"
         << "  set Lattice spacing = 1e-3\n  set Fracture = true\n"
         << "  set Critical energy release rate = 3.8\n"
         << "  set Pre-cracks = 0, 0.02, 0 : 0.03, 0, 0 : 0, 0, 0.008\nend\n";
    return text.str();
  }
} // namespace PeriArlequinTests

#endif
