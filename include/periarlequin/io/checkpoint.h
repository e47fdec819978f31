#ifndef periarlequin_io_checkpoint_h
#define periarlequin_io_checkpoint_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The two checkpoint slots of a run, `DIRECTORY/BASE_checkpoint_0` and `_1`, and the file
   * `BASE_checkpoint.last` that names the newest complete one. A checkpoint is written into
   * the other slot and only then named, by renaming a new pointer file over the old (atomic
   * on POSIX file systems): a run killed while writing leaves the previous checkpoint named
   * and intact.
   */
  class CheckpointSlots
  {
  public:
    CheckpointSlots(const std::string &directory,
                    const std::string &base_name,
                    const MPI_Comm     communicator);

    /**
     * The slot to write next (collective): the one the pointer does not name, emptied and
     * created on rank 0. Returns its directory, with a trailing slash.
     */
    std::string
    begin_writing();
    /** Name the slot begin_writing() returned as the newest checkpoint (collective). */
    void
    commit();
    /**
     * Directory of the newest complete checkpoint, with a trailing slash; a clear error if
     * there is none.
     */
    std::string
    newest() const;

  private:
    std::string
    slot_directory(const unsigned int slot) const;
    /** The slot the pointer names, or numbers::invalid_unsigned_int (on rank 0). */
    unsigned int
    read_pointer() const;

    const std::string directory, base_name;
    const MPI_Comm    communicator;
    unsigned int      writing = 0;
  };

  /**
   * The parameters that define a run's physics, as "Subsection/Entry = value" lines in the
   * handler's order: every entry except those of the subsections Output and Checkpoint and
   * Time/End time, which a resumed run may change.
   */
  std::vector<std::string>
  checkpointed_parameters(const ParameterHandler &prm);

  /** FNV-1a hash of @p bytes: checkpoints carry it to detect corrupt or truncated files. */
  std::uint64_t
  checksum(const std::string &bytes);

  /**
   * The names and checksums of the files in @p slot (a directory) other than @p skip, sorted by
   * name; an unreadable file has checksum 0.
   */
  std::vector<std::pair<std::string, std::uint64_t>>
  file_checksums(const std::string &slot, const std::string &skip);
} // namespace PeriArlequin

#endif
