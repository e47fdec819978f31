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
   * A history of named scalar diagnostics (energies, residuals), one row per recorded step,
   * filled by name: the first row fixes the columns, and every later row must give exactly
   * those (checked in every build). Rows are kept in memory for tests and post-processing
   * and, if a file name is given, appended to a CSV file on rank 0 as they come, so that a
   * running job can be watched.
   */
  class EnergyHistory
  {
  public:
    EnergyHistory(const std::string &csv_file_name, const MPI_Comm communicator);

    /** Set the value of column @p name in the current row. */
    void
    add_value(const std::string &name, const double value);

    /** Close the current row (and write it). */
    void
    end_row();

    const std::vector<std::string> &
    column_names() const;
    const std::vector<std::vector<double>> &
    rows() const;
    /**
     * Start from the columns and rows of an earlier run (a checkpoint); the file, if any,
     * is written anew with them.
     */
    void
    restore(const std::vector<std::string>         &column_names,
            const std::vector<std::vector<double>> &rows);
    /** The values of one named column over all rows. */
    std::vector<double>
    column(const std::string &name) const;

  private:
    /** Open the file (rank 0, if named) and write the header of the columns. */
    void
    open_file();
    void
    write_row(const std::vector<double> &row);

    std::string                      file_name;
    bool                             root;
    std::vector<std::string>         names;
    std::vector<std::vector<double>> table;
    /** The current row: names and values in the order given. */
    std::vector<std::string> row_names;
    std::vector<double>      row_values;
    std::ofstream            csv;
  };
} // namespace PeriArlequin

#endif
