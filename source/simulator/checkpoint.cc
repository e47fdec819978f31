#include <periarlequin/simulator.h>
#include <periarlequin/simulator/checkpoint_record.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace PeriArlequin
{
  template <int dim>
  Simulator<dim>::~Simulator() = default;

  template <int dim>
  void
  Simulator<dim>::load_checkpointed_mesh()
  {
    read_checkpoint();
    if (contact)
      contact->load_state(resumed->contact_state);
    triangulation.load(resume_directory + "mesh");
    // The owner of each cell in the checkpointed run (the first data attached).
    const unsigned int handle = triangulation.register_data_attach(
      [](const typename Triangulation<dim>::cell_iterator &,
         const typename Triangulation<dim>::CellStatus) {
        return std::vector<char>(sizeof(unsigned int));
      },
      /*returns_variable_size_data=*/false);
    saved_owner.assign(triangulation.n_active_cells(), 0);
    triangulation.notify_ready_to_unpack(
      handle,
      [this](const typename Triangulation<dim>::cell_iterator &cell,
             const typename Triangulation<dim>::CellStatus,
             const boost::iterator_range<std::vector<char>::const_iterator> &data) {
        saved_owner[cell->active_cell_index()] =
          Utilities::unpack<unsigned int>(data.begin(), data.end(), false);
      });
  }

  template <int dim>
  void
  Simulator<dim>::restore_pd_region()
  {
    if (blending && blending->is_band())
      blending->set_pd_region(resumed->pd_region);
    pd_zone->set_region(resumed->pd_region);
  }

  template <int dim>
  void
  Simulator<dim>::restore_fe_state()
  {
    fe_zone->deserialize();
    fe_zone->set_external_work(resumed->fe_work);
  }

  template <int dim>
  void
  Simulator<dim>::restore_pd_state(const double dt)
  {
    pd_zone->setup_from_checkpoint(problem_data, dt);
    const unsigned int rank = Utilities::MPI::this_mpi_process(communicator);
    // On another number of ranks the work so far is rank 0's.
    const bool same_ranks =
      resumed->pd_work.size() == Utilities::MPI::n_mpi_processes(communicator);
    double share = 0;
    if (same_ranks)
      share = resumed->pd_work[rank];
    else if (rank == 0)
      for (const double w : resumed->pd_work)
        share += w;
    pd_zone->set_local_external_work(share);
  }

  template <int dim>
  void
  Simulator<dim>::resume_run()
  {
    integrator->resume_at(resumed->step);
    // A checkpoint holds an equilibrium of a quasi-static run: the next solve is the next
    // increment's.
    quasi_static_started = true;
    if (zone_growth)
      {
        // Every rank read the record: rank 0 alone takes the running damage.
        std::vector<Point<dim>> running_damage;
        if (Utilities::MPI::this_mpi_process(communicator) == 0)
          for (std::size_t k = 0; k + dim <= resumed->running_damage.size(); k += dim)
            {
              Point<dim> p;
              for (unsigned int d = 0; d < dim; ++d)
                p[d] = resumed->running_damage[k + d];
              running_damage.push_back(p);
            }
        zone_growth->restore(resumed->converted_cells, resumed->conversion_energy, running_damage);
      }
    repartitions = resumed->repartitions;
    // load() cut the cells evenly by count: on as many ranks as the checkpointed run, its
    // partition again (so the run goes on bit for bit), on another number, the balance of
    // the cell weights.
    if (pd_zone && resumed->n_ranks == Utilities::MPI::n_mpi_processes(communicator))
      restore_saved_partition();
    else if (pd_zone)
      rebalance(0.);
    saved_owner.clear();
  }

  template <int dim>
  void
  Simulator<dim>::print_resume_summary() const
  {
    pcout << "  resumed from " << resume_directory << " at step " << resumed->step
          << ", t = " << integrator->get_time().get_current_time() << " s (written on "
          << resumed->n_ranks << " rank(s))" << std::endl;
  }

  template <int dim>
  void
  Simulator<dim>::restore_saved_partition()
  {
    // Cell weights under which p4est cuts the curve of cells exactly where the checkpointed
    // run owned them: each saved rank's cells weigh S in all (S = the largest saved count;
    // q = S / n per cell and one more for the first S mod n of them), so every cut falls on
    // a block boundary, whichever side of it p4est gives a cell on the cut.
    const unsigned int         n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    std::vector<std::uint64_t> local_count(n_ranks, 0);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        ++local_count[saved_owner[cell->active_cell_index()]];
    std::vector<std::uint64_t> count(n_ranks, 0), before(n_ranks, 0);
    MPI_Allreduce(local_count.data(), count.data(), n_ranks, MPI_UINT64_T, MPI_SUM, communicator);
    MPI_Exscan(local_count.data(), before.data(), n_ranks, MPI_UINT64_T, MPI_SUM, communicator);
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      std::fill(before.begin(), before.end(), 0);
    const std::uint64_t block = *std::max_element(count.begin(), count.end());
    partition_weights.assign(triangulation.n_active_cells(), 0);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int owner = saved_owner[cell->active_cell_index()];
          partition_weights[cell->active_cell_index()] =
            block / count[owner] + (before[owner]++ < block % count[owner] ? 1 : 0);
        }
    repartition_zones();
    partition_weights.clear();
  }

  template <int dim>
  bool
  Simulator<dim>::checkpoint_due()
  {
    const unsigned int interval = checkpoint_parameters.interval;
    if (interval > 0 && get_step_number() % interval == 0)
      return true;
    if (checkpoint_parameters.wall_time_interval > 0)
      {
        // Rank 0's clock decides, so that every rank writes.
        const double wall = Utilities::MPI::broadcast(communicator, wall_clock.wall_time(), 0);
        return wall - last_checkpoint_wall_time >= checkpoint_parameters.wall_time_interval;
      }
    return false;
  }

  template <int dim>
  void
  Simulator<dim>::write_checkpoint()
  {
    TimerOutput::Scope scope(timer, "checkpoint");
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      std::filesystem::create_directories(output_parameters.directory);
    CheckpointSlots   slots(output_parameters.directory, output_parameters.base_name, communicator);
    const std::string slot  = slots.begin_writing();
    const unsigned int rank = Utilities::MPI::this_mpi_process(communicator);
    triangulation.register_data_attach(
      [rank](const typename Triangulation<dim>::cell_iterator &,
             const typename Triangulation<dim>::CellStatus) {
        return Utilities::pack(rank, false);
      },
      /*returns_variable_size_data=*/false);
    if (fe_zone)
      fe_zone->prepare_for_serialization();
    if (pd_zone)
      pd_zone->prepare_for_serialization();
    triangulation.save(slot + "mesh");

    const std::vector<double> pd_work =
      Utilities::MPI::gather(communicator, pd_zone ? pd_zone->local_external_work() : 0., 0);
    const std::vector<Point<dim>> running_damage =
      zone_growth ? zone_growth->gather_running_damage(communicator) : std::vector<Point<dim>>();
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        CheckpointRecord record;
        for (const Point<dim> &p : running_damage)
          for (unsigned int d = 0; d < dim; ++d)
            record.running_damage.push_back(p[d]);
        record.parameters = physics_parameters;
        record.n_ranks    = Utilities::MPI::n_mpi_processes(communicator);
        record.step       = get_step_number();
        if (pd_zone)
          record.pd_region = pd_zone->get_region();
        record.converted_cells   = n_converted_cells();
        record.repartitions      = repartitions;
        record.conversion_energy = conversion_energy_change();
        record.fe_work           = fe_zone ? fe_zone->external_work() : 0.;
        record.equilibrium_force_scale =
          static_solver ? static_solver->equilibrium_force_scale() : 0.;
        record.pd_work = pd_work;
        if (energy_history)
          {
            record.history_names = energy_history->column_names();
            record.history_rows  = energy_history->rows();
          }
        if (fe_output)
          record.fe_records = fe_output->get_series().get_records();
        if (pd_output)
          record.pd_records = pd_output->get_series().get_records();
        for (const auto &postprocessor : postprocessors)
          record.postprocessor_states.push_back(postprocessor->save_state());
        if (contact)
          record.contact_state = contact->save_state();
        record.files = file_checksums(slot, "state");

        std::ostringstream bytes;
        {
          boost::archive::binary_oarchive archive(bytes);
          archive << record;
        }
        const std::string   payload = bytes.str();
        std::ofstream       file(slot + "state", std::ios::binary);
        const std::uint64_t header[2] = {payload.size(), checksum(payload)};
        file.write(reinterpret_cast<const char *>(header), sizeof(header));
        file.write(payload.data(), payload.size());
        file.flush();
        AssertThrow(file, ExcMessage("Cannot write the checkpoint record " + slot + "state"));
      }
    slots.commit();
    pcout << "  step " << get_step_number() << ": checkpoint written to " << slot << std::endl;
    last_checkpoint_wall_time = Utilities::MPI::broadcast(communicator, wall_clock.wall_time(), 0);
  }

  template <int dim>
  void
  Simulator<dim>::read_checkpoint()
  {
    const CheckpointSlots slots(output_parameters.directory,
                                output_parameters.base_name,
                                communicator);
    resume_directory            = slots.newest();
    const std::string file_name = resume_directory + "state";
    const auto        corrupt   = [&](const std::string &what) {
      AssertThrow(false,
                  ExcMessage("Invalid input: parameter 'Checkpoint/Resume' = true, but the "
                                      "checkpoint " +
                             resume_directory + " is corrupt (" + what +
                             "); allowed: a checkpoint that a run wrote completely (delete "
                                      "this slot and its pointer to start afresh)."));
    };
    std::string payload;
    bool        intact = false;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::ifstream file(file_name, std::ios::binary);
        std::uint64_t header[2] = {0, 0};
        if (file.read(reinterpret_cast<char *>(header), sizeof(header)) &&
            header[0] < (std::uint64_t(1) << 40))
          {
            payload.resize(header[0]);
            intact = file.read(payload.data(), payload.size()) && checksum(payload) == header[1];
          }
      }
    if (!Utilities::MPI::broadcast(communicator, intact, 0))
      corrupt("its record " + file_name + " is missing, truncated, or fails its checksum");
    payload = Utilities::MPI::broadcast(communicator, payload, 0);

    resumed                  = std::make_unique<CheckpointRecord>();
    const std::string format = resumed->format;
    try
      {
        std::istringstream              bytes(payload);
        boost::archive::binary_iarchive archive(bytes);
        archive >> *resumed;
      }
    catch (const std::exception &error)
      {
        corrupt(error.what());
      }
    if (resumed->format != format || resumed->dimension != dim)
      corrupt("written by another version or for another dimension");
    // The mesh and cell-data files, against the checksums the record took after writing them.
    std::string damaged_file;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        const auto found = file_checksums(resume_directory, "state");
        for (const auto &[name, sum] : resumed->files)
          {
            const auto here = std::find_if(found.begin(), found.end(), [&](const auto &f) {
              return f.first == name;
            });
            if (here == found.end() || here->second != sum)
              {
                damaged_file = name;
                break;
              }
          }
      }
    damaged_file = Utilities::MPI::broadcast(communicator, damaged_file, 0);
    if (!damaged_file.empty())
      corrupt("its file " + damaged_file + " is missing or fails its checksum");
    // The first parameter that differs, named with both values.
    const auto &saved = resumed->parameters;
    for (unsigned int k = 0; k < std::max(saved.size(), physics_parameters.size()); ++k)
      {
        const std::string was  = k < saved.size() ? saved[k] : "(absent)";
        const std::string here = k < physics_parameters.size() ? physics_parameters[k] : "(absent)";
        if (was != here)
          AssertThrow(false,
                      ExcMessage("Invalid input: parameter 'Checkpoint/Resume' = true, but "
                                 "the checkpoint in " +
                                 resume_directory + " was written with '" + was +
                                 "' where this run has '" + here +
                                 "'; allowed: the parameters of the checkpointed run "
                                 "(only the subsections Output and Checkpoint and Time/End "
                                 "time may change)."));
      }
    AssertThrow(static_cast<std::uint64_t>(resumed->step) * clock_step() <=
                  time_parameters.end_time * (1 + 1e-12),
                ExcMessage("Invalid input: parameter 'Time/End time' = " +
                           std::to_string(time_parameters.end_time) +
                           "; allowed: not before the checkpoint's step " +
                           std::to_string(resumed->step) + "."));
  }

  template <int dim>
  void
  Simulator<dim>::restore_outputs()
  {
    energy_history->restore(resumed->history_names, resumed->history_rows);
    if (fe_output)
      fe_output->get_series().restore(resumed->fe_records);
    if (pd_output)
      pd_output->get_series().restore(resumed->pd_records);
    AssertThrow(resumed->postprocessor_states.size() == postprocessors.size(),
                ExcMessage("The checkpoint holds another number of postprocessors."));
    for (unsigned int k = 0; k < postprocessors.size(); ++k)
      postprocessors[k]->load_state(resumed->postprocessor_states[k]);
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace PeriArlequin
