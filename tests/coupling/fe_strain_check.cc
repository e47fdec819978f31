// The FE zone cannot break: Simulator::check_fe_strain() compares the FE field's largest
// principal strain at the cell centres with the critical stretch. A plate 0.2 x 0.05 m
// (E = 72 GPa, plane stress), PD on x < 0.05 m, an overlap band of 0.02 m, FE beyond, fracture
// with a given critical stretch s_c = 1e-3; at rest, displaced by
// u_x = e0 max(x - 0.1, 0), a strain e0 in x beyond x = 0.1 m, where all cells are FE and no
// particle lies. The Q1 field holds that piecewise linear u exactly (x = 0.1 is a cell face),
// so the largest centre strain is e0 and the ratio e0 / s_c, to round-off (1e-12):
//  - e0 = 1.25 s_c: ratio 1.25 (the run warns: PD would crack there, the FE zone cannot);
//  - e0 = 0.8 s_c: ratio 0.8 (no warning);
//  - without fracture: no critical stretch, ratio 0.
// The same on 1 and 2 ranks.

#include "../tests.h"

using namespace PeriArlequinTests;

std::string
strained_plate(const double e0, const bool fracture)
{
  std::ostringstream text;
  text << std::setprecision(17) << "set Dimension = 2\n"
       << "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = 0.2, 0.05\n"
       << "  set Subdivisions = 40, 10\nend\n"
       << "subsection Material\n  set Young's modulus = 72e9\n  set Poisson's ratio = 0.22\n"
       << "  set Density = 2440\nend\n"
       << "subsection Peridynamics\n  set Region = 0, 0 : 0.05, 0.05\n"
       << "  set Lattice spacing = 1.25e-3\n  set Fracture = " << (fracture ? "true" : "false")
       << "\n  set Critical stretch = 1e-3\nend\n"
       << "subsection Coupling\n  set Method = weak\n  set Blending = force\n"
       << "  set Overlap width = 0.02\nend\n"
       << "subsection Initial conditions\nsubsection function\n  subsection Displacement\n"
       << "    set Function expression = " << e0 << "*max(x - 0.1, 0); 0\n  end\nend\nend\n"
       << "subsection Time\n  set Time step = 1e-8\n  set End time = 1e-8\nend\n"
       << quiet_output();
  return text.str();
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const auto ratio = [](const double e0, const bool fracture) {
      auto simulator = make_simulator<2>(strained_plate(e0, fracture));
      simulator->setup();
      return simulator->check_fe_strain();
    };
    check("e0 = 1.25 s_c: FE strain / critical stretch", ratio(1.25e-3, true), 1.25, 1e-12);
    check("e0 = 0.8 s_c: FE strain / critical stretch", ratio(0.8e-3, true), 0.8, 1e-12);
    check("no fracture: FE strain / critical stretch", ratio(1.25e-3, false), 0, 0);
  });
}
