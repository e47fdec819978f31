// Without fracture or damping, the pure-PD zone under velocity Verlet keeps its total energy
// (kinetic + strain - work of loads and reactions) within 0.1 % over 2000 steps: a free 2D
// plane-stress block, a 3D block, and a 2D block with a body force and a moving prescribed
// layer (which checks the work bookkeeping of the particle zone).
//
// Tolerance 0.1 % (the bound) at 0.13 (2D) and 0.08 (3D) of the stable step: the energy of
// velocity Verlet fluctuates by (omega dt)^2 / 8 of the energy in a mode of frequency omega.

#include "../tests.h"

using namespace PeriArlequinTests;

template <int dim>
void
check_energy(const std::string &name, const std::string &extra)
{
  std::ostringstream prm;
  prm << "set Dimension = " << dim << "\n"
      << "subsection Geometry\n  set Lower corner = " << (dim == 2 ? "0, 0" : "0, 0, 0")
      << "\n  set Upper corner = " << (dim == 2 ? "0.04, 0.02" : "0.01, 0.01, 0.01")
      << "\n  set Subdivisions = " << (dim == 2 ? "8, 4" : "2, 2, 2") << "\nend\n"
      << "subsection Peridynamics\n  set Region = "
      << (dim == 2 ? "0, 0 : 0.04, 0.02" : "0, 0, 0 : 0.01, 0.01, 0.01")
      << "\n  set Lattice spacing = 1e-3\n"
      << extra << "end\n"
      << "subsection Time\n  set Time step = " << (dim == 2 ? 5e-8 : 2.5e-8)
      << "\n  set End time = " << (dim == 2 ? 5e-8 : 2.5e-8) * 2000 << "\nend\n"
      << "subsection Initial conditions\nsubsection function\n  subsection Velocity\n"
      << "    set Function constants = L=" << (dim == 2 ? 0.04 : 0.01)
      << ", H=" << (dim == 2 ? 0.02 : 0.01) << "\n"
      << "    set Function expression = 0.1*sin(pi*x/L)*cos(pi*y/H); 0.05*sin(2*pi*x/L)"
      << (dim == 3 ? "; 0.05*sin(pi*z/H)" : "") << "\n  end\nend\nend\n"
      << (name.find("loaded") != std::string::npos ?
            "subsection Body force\n  set Function expression = 2e6*sin(3e4*t); 1e6\nend\n" :
            "")
      << quiet_output();
  auto simulator = make_simulator<dim>(prm.str());
  simulator->run();
  check_energy_conservation(name, *simulator, 2000, 1e-3);
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    check_energy<2>("2D free", "");
    check_energy<2>("2D loaded, driven layer",
                    "  subsection Prescribed region 0\n"
                    "    set Region = 0, 0 : 0.003, 0.02\n"
                    "    set Components = x\n"
                    "    subsection Function\n"
                    "      set Function expression = 2e-6*sin(2e4*t); 0\n"
                    "    end\n  end\n");
    check_energy<3>("3D free", "");
  });
}
