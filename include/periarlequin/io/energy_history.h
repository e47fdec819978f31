#ifndef periarlequin_io_energy_history_h
#define periarlequin_io_energy_history_h

#include <deal.II/base/mpi.h>

#include <fstream>
#include <string>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * A history of named scalar diagnostics (energies, residuals), one row per recorded step.
   * Rows are kept in memory for tests and post-processing and, if a file name is given,
   * appended to a CSV file on rank 0 as they come, so that a running job can be watched.
   */
  class EnergyHistory
  {
  public:
    EnergyHistory(std::vector<std::string> column_names,
                  const std::string       &csv_file_name,
                  const MPI_Comm           communicator);

    void
    add_row(const std::vector<double> &values);

    const std::vector<std::string> &
    column_names() const;
    const std::vector<std::vector<double>> &
    rows() const;
    /** The values of one named column over all rows. */
    std::vector<double>
    column(const std::string &name) const;

  private:
    std::vector<std::string>         names;
    std::vector<std::vector<double>> table;
    std::ofstream                    csv;
  };
} // namespace PeriArlequin

#endif
