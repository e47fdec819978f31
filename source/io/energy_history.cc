#include <periarlequin/io/energy_history.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <iomanip>

namespace PeriArlequin
{
  EnergyHistory::EnergyHistory(std::vector<std::string> column_names,
                               const std::string       &csv_file_name,
                               const MPI_Comm           communicator)
    : names(std::move(column_names))
  {
    if (csv_file_name.empty() || Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    csv.open(csv_file_name);
    AssertThrow(csv, ExcMessage("Cannot open the energy history file '" + csv_file_name + "'."));
    for (unsigned int i = 0; i < names.size(); ++i)
      csv << (i ? "," : "") << names[i];
    csv << '\n' << std::setprecision(12);
  }

  void
  EnergyHistory::add_row(const std::vector<double> &values)
  {
    Assert(values.size() == names.size(), ExcDimensionMismatch(values.size(), names.size()));
    table.push_back(values);
    if (!csv.is_open())
      return;
    for (unsigned int i = 0; i < values.size(); ++i)
      csv << (i ? "," : "") << values[i];
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
