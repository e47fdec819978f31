// A check that fails on one rank of two must end the whole run with a non-zero exit code: the
// other rank waits in a collective call (here a barrier) and would wait forever if the
// failing rank just returned. Run by tests/mpi/CMakeLists.txt, which expects the failure
// message and an exit code within a time limit.

#include "../tests.h"

int
main(int argc, char **argv)
{
  using namespace PeriArlequinTests;
  return run_test(argc, argv, [] {
    require_several_ranks();
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 1)
      check_below("deliberately failing check on rank 1", 1., 0.);
    MPI_Barrier(MPI_COMM_WORLD);
  });
}
