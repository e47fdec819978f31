// A user application on the installed library: runs a 2D case whose parameter file may use
// the plugins of this project ("scaled LPS", "momentum").
//
//   user_plugins case.prm            run it
//   user_plugins case.prm --verify   run it and check the example case: the momentum of a
//                                    free PD plate is conserved (1e-10 of its initial value,
//                                    round-off of pair-wise forces), and the critical stretch
//                                    is the factor times the LPS formula (1e-12)

#include <periarlequin/simulator.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iostream>

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      AssertThrow(argc == 2 || (argc == 3 && std::string(argv[2]) == "--verify"),
                  ExcMessage("usage: user_plugins case.prm [--verify]"));
      ParameterHandler prm;
      PeriArlequin::Simulator<2>::declare_parameters(prm);
      prm.parse_input(argv[1]);
      PeriArlequin::Simulator<2> simulator(prm, MPI_COMM_WORLD);
      simulator.run();
      if (argc == 2)
        return 0;

      const auto momentum = simulator.get_energy_history().column("momentum_x");
      double     drift    = 0;
      for (const double p : momentum)
        drift = std::max(drift, std::abs(p - momentum.front()));
      drift /= std::abs(momentum.front());

      prm.enter_subsection("Material");
      const double E = prm.get_double("Young's modulus");
      prm.leave_subsection();
      prm.enter_subsection("Peridynamics");
      const double G0    = prm.get_double("Critical energy release rate");
      const double delta = prm.get_double("Horizon factor") * prm.get_double("Lattice spacing");
      prm.enter_subsection("scaled LPS");
      const double factor = prm.get_double("Critical stretch factor");
      prm.leave_subsection();
      prm.leave_subsection();
      const double expected = factor * std::sqrt(4 * numbers::PI * G0 / (9 * E * delta));
      const double stretch_error =
        std::abs(simulator.get_pd_zone()->get_critical_stretch() / expected - 1);

      std::cout << "momentum drift / initial momentum = " << drift
                << "\ncritical stretch / (factor x plane-stress formula) - 1 = " << stretch_error
                << std::endl;
      AssertThrow(drift < 1e-10 && stretch_error < 1e-12,
                  ExcMessage("the example case is not verified"));
      std::cout << "verified" << std::endl;
    }
  catch (const std::exception &error)
    {
      std::cerr << "Error: " << error.what() << std::endl;
      return 1;
    }
  return 0;
}
