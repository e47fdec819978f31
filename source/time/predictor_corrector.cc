#include <periarlequin/time/predictor_corrector.h>

#include <cmath>

namespace PeriArlequin
{
  template <int dim>
  PredictorCorrector<dim>::PredictorCorrector(const std::vector<IntegratedZone *> &zones,
                                              Coupling<dim>                       *coupling,
                                              const double                         time_step,
                                              const unsigned int                   n_steps,
                                              TimerOutput                         &timer)
    : zones(zones)
    , coupling(coupling)
    , time(0., n_steps * time_step, time_step)
    , timer(timer)
  {}

  template <int dim>
  template <typename Action>
  void
  PredictorCorrector<dim>::timed(const std::string &section, const Action &what)
  {
    TimerOutput::Scope scope(timer, section);
    what();
  }

  template <int dim>
  void
  PredictorCorrector<dim>::initialize()
  {
    impose_prescribed_motion();
    slaves_follow_masters();
    compute_trial_accelerations();
    if (coupling)
      timed("coupling", [&] { coupling->set_slave_velocities(); });
  }

  template <int dim>
  void
  PredictorCorrector<dim>::resume_at(const unsigned int step_number)
  {
    while (time.get_step_number() < step_number)
      time.advance_time();
  }

  template <int dim>
  void
  PredictorCorrector<dim>::step()
  {
    // The clock stretches the last step to land on the end time by the round-off of the sum
    // of the steps before (1e-11 of a step after a thousand): the zones take the step of the
    // others, so that a run stopped there with a checkpoint and one that goes on are the same.
    double dt = time.get_next_step_size();
    if (time.get_step_number() > 0 &&
        std::abs(dt - time.get_previous_step_size()) <= 1e-8 * time.get_previous_step_size())
      dt = time.get_previous_step_size();
    start_work_interval();
    predict(dt);
    time.advance_time();
    complete_step(dt);
    account_work();
  }

  template <int dim>
  void
  PredictorCorrector<dim>::advance_clock()
  {
    time.advance_time();
  }

  template <int dim>
  void
  PredictorCorrector<dim>::complete_step(const double dt)
  {
    impose_prescribed_motion();
    slaves_follow_masters();
    compute_trial_accelerations();
    damp_fine_scale();
    compute_trial_velocities(dt);
    solve_multipliers_and_correct();
  }

  template <int dim>
  void
  PredictorCorrector<dim>::relax(const double velocity_factor, const double dt)
  {
    predict(dt);
    complete_step(dt);
    for (IntegratedZone *zone : zones)
      zone->scale_velocities(velocity_factor);
    if (coupling)
      timed("coupling", [&] { coupling->set_slave_velocities(); });
  }

  template <int dim>
  void
  PredictorCorrector<dim>::project_residual(const double dt)
  {
    for (IntegratedZone *zone : zones)
      zone->scale_velocities(0.);
    impose_prescribed_motion();
    slaves_follow_masters();
    compute_trial_accelerations();
    if (coupling)
      coupling->solve_multipliers_exactly(true);
    // Coupled, projected twice: the multipliers of the trial accelerations, which carry the
    // constraint forces, are solved to a relative 1e-12, an error that a poorly conditioned
    // multiplier matrix (weak multipliers) makes larger than the residual near an
    // equilibrium; the second projection removes it to 1e-12 of the residual itself. Each
    // pass starts from rest (take_projected_residual() zeroes the velocities).
    const unsigned int passes = coupling ? 2 : 1;
    for (unsigned int pass = 0; pass < passes; ++pass)
      {
        compute_trial_velocities(dt);
        solve_multipliers_and_correct();
        for (IntegratedZone *zone : zones)
          zone->take_projected_residual(dt);
      }
    if (coupling)
      coupling->solve_multipliers_exactly(false);
  }

  template <int dim>
  void
  PredictorCorrector<dim>::predict(const double dt)
  {
    for (IntegratedZone *zone : zones)
      zone->predict(dt);
  }

  template <int dim>
  void
  PredictorCorrector<dim>::impose_prescribed_motion()
  {
    for (IntegratedZone *zone : zones)
      zone->impose_prescribed_motion(time.get_current_time());
  }

  template <int dim>
  void
  PredictorCorrector<dim>::slaves_follow_masters()
  {
    if (coupling)
      timed("coupling", [&] { coupling->set_slave_displacements(); });
  }

  template <int dim>
  void
  PredictorCorrector<dim>::compute_trial_accelerations()
  {
    const double t = time.get_current_time();
    for (IntegratedZone *zone : zones)
      timed(zone->name() + " forces", [&] { zone->compute_forces(t); });
    if (coupling)
      timed("coupling", [&] { coupling->add_interface_forces(t); });
    for (IntegratedZone *zone : zones)
      timed(zone->name() + " forces", [&] { zone->compute_accelerations(t); });
  }

  template <int dim>
  void
  PredictorCorrector<dim>::damp_fine_scale()
  {
    if (coupling)
      timed("coupling", [&] { coupling->apply_damping(); });
  }

  template <int dim>
  void
  PredictorCorrector<dim>::compute_trial_velocities(const double dt)
  {
    for (IntegratedZone *zone : zones)
      zone->correct(dt);
  }

  template <int dim>
  void
  PredictorCorrector<dim>::solve_multipliers_and_correct()
  {
    if (coupling)
      timed("coupling", [&] {
        coupling->enforce_constraint();
        coupling->set_slave_velocities();
      });
  }

  template <int dim>
  void
  PredictorCorrector<dim>::start_work_interval(const bool from_unloaded)
  {
    for (IntegratedZone *zone : zones)
      zone->start_work_interval(from_unloaded);
  }

  template <int dim>
  void
  PredictorCorrector<dim>::account_work()
  {
    for (IntegratedZone *zone : zones)
      zone->account_work();
  }

  template <int dim>
  const DiscreteTime &
  PredictorCorrector<dim>::get_time() const
  {
    return time;
  }

  template class PredictorCorrector<2>;
  template class PredictorCorrector<3>;
} // namespace PeriArlequin
