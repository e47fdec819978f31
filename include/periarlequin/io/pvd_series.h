#ifndef periarlequin_io_pvd_series_h
#define periarlequin_io_pvd_series_h

#include <periarlequin/base/parameters.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>

#include <string>
#include <utility>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The VTU flags of a field file of step @p step at time @p time: the time and step stored
   * in the file, the zlib level of Output/Compression.
   */
  DataOutBase::VtkFlags
  vtk_flags(const Parameters::Output &parameters, const double time, const unsigned int step);

  /** A .pvd record of a series of .pvtu files, rewritten on rank 0 after each addition. */
  class PVDSeries
  {
  public:
    PVDSeries(const std::string &pvd_file_name, const MPI_Comm communicator);

    void
    add(const double time, const std::string &pvtu_file_name);

    /** The (time, file) records so far. */
    const std::vector<std::pair<double, std::string>> &
    get_records() const;
    /** Start from the records of an earlier run (a checkpoint); the .pvd is written anew. */
    void
    restore(const std::vector<std::pair<double, std::string>> &earlier_records);

  private:
    void
    write() const;

    const std::string                           file_name;
    const bool                                  writer;
    std::vector<std::pair<double, std::string>> records;
  };
} // namespace PeriArlequin

#endif
