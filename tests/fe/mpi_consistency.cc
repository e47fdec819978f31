// MPI: the same case on 2 ranks reproduces the 1-rank energy history. The test runs on two
// ranks; rank 0 also runs the case alone (on MPI_COMM_SELF), and every recorded quantity of
// every step is compared. The case exercises body force, tractions and a moving prescribed
// boundary, so every force term and the work bookkeeping cross the partition boundary.
//
// Tolerance 1e-10 relative to each column's largest magnitude: the two runs differ only in
// the order of floating-point sums, a round-off of order 1e-15 per step.

#include "../tests.h"

using namespace PeriArlequinTests;

template <int dim>
std::string
case_parameters()
{
  std::ostringstream prm;
  prm << "set Dimension = " << dim << "\n"
      << "subsection Geometry\n"
      << (dim == 2 ? "  set Lower corner = 0, 0\n  set Upper corner = 0.4, 0.1\n"
                     "  set Subdivisions = 40, 10\n" :
                     "  set Lower corner = 0, 0, 0\n  set Upper corner = 0.2, 0.1, 0.1\n"
                     "  set Subdivisions = 10, 5, 5\n")
      << "end\n"
      << "subsection Time\n  set Time step = 5e-7\n  set End time = 1.5e-4\nend\n"
      << "subsection Initial conditions\nsubsection function\n  subsection Velocity\n"
      << "    set Function expression = 0.05*sin(pi*x/0.4); 0.01" << (dim == 3 ? "; 0" : "")
      << "\n  end\nend\nend\n"
      << "subsection Body force\n  set Function expression = 0; -2.7e4*sin(1e4*t)"
      << (dim == 3 ? "; 1e4" : "") << "\nend\n"
      << "subsection Boundary conditions\n"
      << "  subsection Boundary 0\n    set Type = displacement\n    set Components = x\n"
      << "    subsection Function\n      set Function expression = 1e-6*sin(3e4*t); 0"
      << (dim == 3 ? "; 0" : "") << "\n    end\n  end\n"
      << "  subsection Boundary 3\n    set Type = traction\n    subsection Function\n"
      << "      set Function expression = 1e6*x; 0" << (dim == 3 ? "; 0" : "")
      << "\n    end\n  end\n"
      << "end\n"
      << quiet_output();
  return prm.str();
}

template <int dim>
void
compare_one_and_two_ranks()
{
  check_below(std::to_string(dim) + "D energy history, 2 ranks vs 1 rank, max relative difference",
              parallel_vs_serial_history_difference<dim>(case_parameters<dim>(),
                                                         std::to_string(dim) + "D"),
              1e-10);
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    require_several_ranks();
    compare_one_and_two_ranks<2>();
    compare_one_and_two_ranks<3>();
  });
}
