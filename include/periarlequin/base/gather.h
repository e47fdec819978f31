#ifndef periarlequin_base_gather_h
#define periarlequin_base_gather_h

#include <deal.II/base/mpi.h>

#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The values of all ranks in one list, in rank order (collective). Plain MPI on doubles:
   * Utilities::MPI::all_gather() serialises, which costs more than the exchange for the
   * thousands of values that damage diagnostics gather.
   */
  std::vector<double>
  gather_values(const std::vector<double> &local, const MPI_Comm communicator);
} // namespace PeriArlequin

#endif
