// Without damping, velocity Verlet conserves the energy of the linear FE model up to a bounded
// O((omega dt)^2) fluctuation: the total kinetic + strain - external work must stay within
// 0.1 % of its initial value over 2000 steps, with free boundaries, with fixed (zero
// displacement) ends, and with a time-dependent prescribed displacement plus a traction that
// do work on the body (which checks the work of loads and support reactions). The bodies
// start undeformed with a smooth velocity field, so that no mode near the mesh cut-off is
// excited by initial data out of equilibrium with the boundaries.
//
// Tolerance 0.1 % (the bound) at a quarter of the stable step: the energy of velocity
// Verlet fluctuates by (dt^2 / 8) a^T M a, i.e. (omega dt)^2 / 8 of the energy in a mode of
// frequency omega; at half the stable step that reaches 0.2 % for these cases.
//
// Independently of that fluctuation, for the unloaded free body the scheme conserves exactly
// its discrete energy 1/2 v^T M v + 1/2 u^T K u - dt^2/8 a^T M a (a = -M^-1 K u): asserted to
// 1e-10 relative, i.e. round-off over 2000 steps.

#include "../tests.h"

using namespace PeriArlequinTests;

template <int dim>
std::string
case_parameters(const std::string &boundaries)
{
  std::ostringstream prm;
  prm << "set Dimension = " << dim << "\n"
      << "subsection Geometry\n"
      << (dim == 2 ? "  set Lower corner = 0, 0\n  set Upper corner = 0.4, 0.1\n"
                     "  set Subdivisions = 40, 10\n" :
                     "  set Lower corner = 0, 0, 0\n  set Upper corner = 0.2, 0.1, 0.1\n"
                     "  set Subdivisions = 12, 6, 6\n")
      << "end\n"
      << "subsection Time\n  set Time step = " << (dim == 2 ? 4.5e-7 : 4e-7)
      << "\n  set End time = " << (dim == 2 ? 4.5e-7 : 4e-7) * 2000 << "\nend\n"
      << "subsection Initial conditions\nsubsection function\n"
      << "  subsection Velocity\n    set Function constants = L=" << (dim == 2 ? 0.4 : 0.2)
      << ", H=0.1\n"
      << "    set Function expression = 0.05*sin(pi*x/L)*cos(pi*y/H); 0.02*sin(2*pi*x/L)"
      << (dim == 3 ? "; 0.03*sin(pi*x/L)*sin(pi*z/H)" : "") << "\n  end\nend\n"
      << "end\n"
      << boundaries << quiet_output();
  return prm.str();
}

/** Discrete energy of velocity Verlet for an unloaded, unconstrained body. */
template <int dim>
double
discrete_energy(const PeriArlequin::Simulator<dim> &simulator)
{
  const auto                                &fe_zone = simulator.get_fe_zone();
  const auto                                &mass    = fe_zone.lumped_mass();
  LinearAlgebra::distributed::Vector<double> force;
  fe_zone.initialize_vector(force);
  fe_zone.compute_internal_force(simulator.get_displacement(), force);
  double a_M_a = 0;
  for (unsigned int i = 0; i < force.locally_owned_size(); ++i)
    a_M_a += force.local_element(i) * force.local_element(i) / mass.local_element(i);
  a_M_a           = Utilities::MPI::sum(a_M_a, MPI_COMM_WORLD);
  const double dt = simulator.get_time_step();
  return fe_zone.kinetic_energy() + 0.5 * (simulator.get_displacement() * force) -
         dt * dt / 8 * a_M_a;
}

template <int dim>
void
check_discrete_energy()
{
  auto simulator = make_simulator<dim>(case_parameters<dim>(""));
  simulator->setup();
  const double initial = discrete_energy(*simulator);
  double       drift   = 0;
  for (unsigned int n = 0; n < 2000; ++n)
    {
      simulator->advance();
      drift = std::max(drift, std::abs(discrete_energy(*simulator) - initial));
    }
  check_below(std::to_string(dim) + "D free: max |discrete Verlet energy drift| / initial",
              drift / initial,
              1e-10);
}

template <int dim>
void
check_energy(const std::string &name, const std::string &boundaries)
{
  auto simulator = make_simulator<dim>(case_parameters<dim>(boundaries));
  simulator->run();
  check_energy_conservation(name, *simulator, 2000, 1e-3);
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    check_discrete_energy<2>();
    check_energy<2>("2D free", "");
    check_energy<2>("2D fixed ends",
                    "subsection Boundary conditions\n"
                    "  subsection Boundary 0\n    set Type = displacement\n  end\n"
                    "  subsection Boundary 1\n    set Type = displacement\n  end\n"
                    "end\n");
    check_energy<2>("2D driven end and traction",
                    "subsection Boundary conditions\n"
                    "  subsection Boundary 0\n    set Type = displacement\n"
                    "    subsection Function\n"
                    "      set Function expression = 2e-6*sin(2e4*t); 0\n"
                    "    end\n  end\n"
                    "  subsection Boundary 3\n    set Type = traction\n"
                    "    subsection Function\n"
                    "      set Function expression = 0; 1e6*sin(pi*x/0.4)*sin(1.5e4*t)\n"
                    "    end\n  end\n"
                    "end\n");
    check_energy<3>("3D fixed ends",
                    "subsection Boundary conditions\n"
                    "  subsection Boundary 0\n    set Type = displacement\n  end\n"
                    "  subsection Boundary 1\n    set Type = displacement\n  end\n"
                    "end\n");
  });
}
