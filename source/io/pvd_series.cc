#include <periarlequin/io/pvd_series.h>

#include <deal.II/base/data_out_base.h>

#include <fstream>

namespace PeriArlequin
{
  DataOutBase::VtkFlags
  vtk_flags(const Parameters::Output &parameters, const double time, const unsigned int step)
  {
    DataOutBase::VtkFlags flags(time, step);
    switch (parameters.compression)
      {
        case Parameters::OutputCompression::fast:
          flags.compression_level = DataOutBase::VtkFlags::best_speed;
          break;
        case Parameters::OutputCompression::small:
          flags.compression_level = DataOutBase::VtkFlags::best_compression;
          break;
        case Parameters::OutputCompression::none:
          flags.compression_level = DataOutBase::VtkFlags::no_compression;
          break;
      }
    return flags;
  }

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
