#include <periarlequin/io/energy_history.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <iomanip>

namespace PeriArlequin
{
  EnergyHistory::EnergyHistory(const std::string &csv_file_name, const MPI_Comm communicator)
    : file_name(csv_file_name)
    , root(Utilities::MPI::this_mpi_process(communicator) == 0)
  {}

  void
  EnergyHistory::add_value(const std::string &name, const double value)
  {
    AssertThrow(std::find(row_names.begin(), row_names.end(), name) == row_names.end(),
                ExcMessage("The history column '" + name + "' is given twice in one row."));
    AssertThrow(table.empty() || std::find(names.begin(), names.end(), name) != names.end(),
                ExcMessage("The history column '" + name +
                           "' is not one of the columns of the first row."));
    row_names.push_back(name);
    row_values.push_back(value);
  }

  void
  EnergyHistory::end_row()
  {
    if (table.empty())
      {
        names = row_names;
        open_file();
      }
    AssertThrow(row_names.size() == names.size(),
                ExcMessage("A history row gives " + std::to_string(row_names.size()) +
                           " columns, the first row " + std::to_string(names.size()) + "."));
    // The values in the order of the first row.
    std::vector<double> row(names.size());
    for (unsigned int k = 0; k < row_names.size(); ++k)
      row[std::find(names.begin(), names.end(), row_names[k]) - names.begin()] = row_values[k];
    table.push_back(row);
    row_names.clear();
    row_values.clear();
    write_row(row);
  }

  void
  EnergyHistory::restore(const std::vector<std::string>         &column_names,
                         const std::vector<std::vector<double>> &rows)
  {
    AssertThrow(table.empty() && row_names.empty(),
                ExcMessage("EnergyHistory::restore() needs an empty history."));
    names = column_names;
    table = rows;
    if (table.empty())
      return;
    open_file();
    for (const auto &row : table)
      write_row(row);
  }

  void
  EnergyHistory::open_file()
  {
    if (!root || file_name.empty())
      return;
    csv.open(file_name);
    AssertThrow(csv, ExcMessage("Cannot open the energy history file '" + file_name + "'."));
    for (unsigned int i = 0; i < names.size(); ++i)
      csv << (i ? "," : "") << names[i];
    csv << '\n' << std::setprecision(12);
  }

  void
  EnergyHistory::write_row(const std::vector<double> &row)
  {
    if (!csv.is_open())
      return;
    for (unsigned int i = 0; i < row.size(); ++i)
      csv << (i ? "," : "") << row[i];
    csv << '\n';
    csv.flush();
  }

  const std::vector<std::string> &
  EnergyHistory::column_names() const
  {
    return names;
  }

  const std::vector<std::vector<double>> &
  EnergyHistory::rows() const
  {
    return table;
  }

  std::vector<double>
  EnergyHistory::column(const std::string &name) const
  {
    const auto position = std::find(names.begin(), names.end(), name);
    AssertThrow(position != names.end(),
                ExcMessage("The energy history has no column '" + name + "'."));
    const std::size_t   index = position - names.begin();
    std::vector<double> values;
    for (const auto &row : table)
      values.push_back(row[index]);
    return values;
  }
} // namespace PeriArlequin
