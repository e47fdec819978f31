#include <periarlequin/base/gather.h>

namespace PeriArlequin
{
  std::vector<double>
  gather_values(const std::vector<double> &local, const MPI_Comm communicator)
  {
    const int        n_local = static_cast<int>(local.size());
    std::vector<int> counts(Utilities::MPI::n_mpi_processes(communicator));
    MPI_Allgather(&n_local, 1, MPI_INT, counts.data(), 1, MPI_INT, communicator);
    std::vector<int> offsets(counts.size() + 1, 0);
    for (unsigned int r = 0; r < counts.size(); ++r)
      offsets[r + 1] = offsets[r] + counts[r];
    std::vector<double> all(offsets.back());
    MPI_Allgatherv(local.data(),
                   n_local,
                   MPI_DOUBLE,
                   all.data(),
                   counts.data(),
                   offsets.data(),
                   MPI_DOUBLE,
                   communicator);
    return all;
  }
} // namespace PeriArlequin
