#include <periarlequin/io/checkpoint.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace PeriArlequin
{
  CheckpointSlots::CheckpointSlots(const std::string &directory,
                                   const std::string &base_name,
                                   const MPI_Comm     communicator)
    : directory(directory)
    , base_name(base_name)
    , communicator(communicator)
  {}

  std::string
  CheckpointSlots::slot_directory(const unsigned int slot) const
  {
    return directory + "/" + base_name + "_checkpoint_" + std::to_string(slot) + "/";
  }

  unsigned int
  CheckpointSlots::read_pointer() const
  {
    std::ifstream pointer(directory + "/" + base_name + "_checkpoint.last");
    unsigned int  slot = numbers::invalid_unsigned_int;
    if (!(pointer >> slot) || slot > 1)
      return numbers::invalid_unsigned_int;
    return slot;
  }

  std::string
  CheckpointSlots::begin_writing()
  {
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        writing = read_pointer() == 0 ? 1 : 0;
        std::filesystem::remove_all(slot_directory(writing));
        std::filesystem::create_directories(slot_directory(writing));
      }
    writing = Utilities::MPI::broadcast(communicator, writing, 0);
    return slot_directory(writing);
  }

  void
  CheckpointSlots::commit()
  {
    MPI_Barrier(communicator);
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        const std::string pointer = directory + "/" + base_name + "_checkpoint.last";
        {
          std::ofstream file(pointer + ".new");
          file << writing << '\n';
          file.flush();
          AssertThrow(file, ExcMessage("Cannot write " + pointer + ".new"));
        }
        std::filesystem::rename(pointer + ".new", pointer);
      }
    MPI_Barrier(communicator);
  }

  std::string
  CheckpointSlots::newest() const
  {
    unsigned int slot = numbers::invalid_unsigned_int;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      slot = read_pointer();
    slot = Utilities::MPI::broadcast(communicator, slot, 0);
    AssertThrow(slot != numbers::invalid_unsigned_int,
                ExcMessage("Invalid input: parameter 'Checkpoint/Resume' = true, but " + directory +
                           "/" + base_name +
                           "_checkpoint.last names no checkpoint; allowed: true only where a "
                           "run with the same 'Output/Directory' and 'Output/Base name' wrote "
                           "a checkpoint (Checkpoint/Interval, Wall time interval or At end)."));
    return slot_directory(slot);
  }

  std::vector<std::string>
  checkpointed_parameters(const ParameterHandler &prm)
  {
    std::ostringstream text;
    prm.print_parameters(text,
                         ParameterHandler::OutputStyle(ParameterHandler::PRM |
                                                       ParameterHandler::Short));
    std::vector<std::string> lines, path;
    std::string              line;
    std::istringstream       input(text.str());
    while (std::getline(input, line))
      {
        const std::string trimmed = Utilities::trim(line);
        if (trimmed.rfind("subsection ", 0) == 0)
          path.push_back(Utilities::trim(trimmed.substr(11)));
        else if (trimmed == "end")
          path.pop_back();
        else if (trimmed.rfind("set ", 0) == 0)
          {
            const auto        equals = trimmed.find('=');
            const std::string name   = Utilities::trim(trimmed.substr(4, equals - 4));
            const std::string value  = Utilities::trim(trimmed.substr(equals + 1));
            if (!path.empty() && (path[0] == "Output" || path[0] == "Checkpoint"))
              continue;
            if (path.size() == 1 && path[0] == "Time" && name == "End time")
              continue;
            std::string full;
            for (const std::string &subsection : path)
              full += subsection + "/";
            lines.push_back(full + name + " = " + value);
          }
      }
    return lines;
  }

  std::uint64_t
  checksum(const std::string &bytes)
  {
    std::uint64_t hash = 14695981039346656037ull;
    for (const char c : bytes)
      hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    return hash;
  }

  std::vector<std::pair<std::string, std::uint64_t>>
  file_checksums(const std::string &slot, const std::string &skip)
  {
    std::vector<std::pair<std::string, std::uint64_t>> sums;
    for (const auto &entry : std::filesystem::directory_iterator(slot))
      {
        const std::string name = entry.path().filename().string();
        if (name == skip || !entry.is_regular_file())
          continue;
        std::ifstream     file(entry.path(), std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(file)),
                                std::istreambuf_iterator<char>());
        sums.emplace_back(name, file ? checksum(bytes) : 0);
      }
    std::sort(sums.begin(), sums.end());
    return sums;
  }
} // namespace PeriArlequin
