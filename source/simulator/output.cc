#include <periarlequin/simulator.h>

#include <filesystem>
#include <iomanip>
#include <sstream>

namespace PeriArlequin
{
  template <int dim>
  void
  Simulator<dim>::prepare_output()
  {
    if (output_parameters.output_interval > 0 || output_parameters.energy_interval > 0)
      {
        if (Utilities::MPI::this_mpi_process(communicator) == 0)
          std::filesystem::create_directories(output_parameters.directory);
        MPI_Barrier(communicator);
      }
    energy_history =
      std::make_unique<EnergyHistory>(output_parameters.energy_interval > 0 ?
                                        output_parameters.directory + "/" +
                                          output_parameters.base_name + "_energy.csv" :
                                        std::string(),
                                      communicator);
    if (fe_zone)
      fe_output = std::make_unique<FEOutput<dim>>(*fe_zone, output_parameters);
    if (pd_zone)
      pd_output = std::make_unique<PDOutput<dim>>(*pd_zone, output_parameters);
  }

  template <int dim>
  void
  Simulator<dim>::record_statistics()
  {
    TimerOutput::Scope scope(timer, "energies");
    double             energy = 0;
    for (const IntegratedZone *zone : zones)
      energy += zone->kinetic_energy() + zone->strain_energy();
    check_finite(energy);
    energy_history->add_value("step", get_step_number());
    energy_history->add_value("time", get_time());
    for (const auto &postprocessor : postprocessors)
      postprocessor->execute(*this, *energy_history);
    energy_history->end_row();
  }

  template <int dim>
  void
  Simulator<dim>::check_finite(const double energy) const
  {
    if (std::isfinite(energy))
      return;
    std::ostringstream message;
    message << "The solution is not finite at step " << get_step_number() << " (t = " << get_time()
            << " s): an unstable time step, or initial data, loads or boundary values that "
               "evaluate to NaN or infinity.";
    AssertThrow(false, ExcMessage(message.str()));
  }

  template <int dim>
  double
  Simulator<dim>::kinetic_energy() const
  {
    double sum = 0;
    for (const IntegratedZone *zone : zones)
      sum += zone->kinetic_energy();
    return sum;
  }

  template <int dim>
  void
  Simulator<dim>::write_output()
  {
    TimerOutput::Scope scope(timer, "output");
    if (fe_output)
      fe_output->write(get_step_number(), get_time(), get_displacement(), get_velocity());
    if (pd_output)
      pd_output->write(get_step_number(), get_time());
    if (line_samples)
      line_samples->write(get_step_number(), fe_zone.get(), pd_zone.get());
  }

  template <int dim>
  void
  Simulator<dim>::report_progress(const bool force)
  {
    if (output_parameters.progress_interval <= 0)
      return;
    // The clocks of the ranks differ, and the finiteness check below is collective: rank 0's
    // clock decides for all.
    const double wall = Utilities::MPI::broadcast(communicator, wall_clock.wall_time(), 0);
    if (!force && wall - last_progress_time < output_parameters.progress_interval)
      return;
    last_progress_time = wall;
    // Energies may not be recorded: make sure the state is finite when progress is shown.
    check_finite(kinetic_energy());
    const unsigned int n         = get_step_number();
    const double       remaining = n > first_step ? wall * (n_steps - n) / (n - first_step) : 0.;
    pcout << "  step " << n << "/" << n_steps << ", t = " << std::setprecision(4) << std::scientific
          << get_time() << " s, wall " << std::fixed << std::setprecision(1) << wall << " s, about "
          << remaining << " s to go" << std::defaultfloat << std::setprecision(6) << std::endl;
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace PeriArlequin
