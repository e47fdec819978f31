#include <periarlequin/io/pvd_series.h>

#include <deal.II/base/data_out_base.h>

#include <fstream>

namespace PeriArlequin
{
  PVDSeries::PVDSeries(const std::string &pvd_file_name, const MPI_Comm communicator)
    : file_name(pvd_file_name)
    , writer(Utilities::MPI::this_mpi_process(communicator) == 0)
  {}

  void
  PVDSeries::add(const double time, const std::string &pvtu_file_name)
  {
    records.emplace_back(time, pvtu_file_name);
    write();
  }

  const std::vector<std::pair<double, std::string>> &
  PVDSeries::get_records() const
  {
    return records;
  }

  void
  PVDSeries::restore(const std::vector<std::pair<double, std::string>> &earlier_records)
  {
    records = earlier_records;
    write();
  }

  void
  PVDSeries::write() const
  {
    if (!writer || records.empty())
      return;
    std::ofstream pvd(file_name);
    DataOutBase::write_pvd_record(pvd, records);
  }
} // namespace PeriArlequin
