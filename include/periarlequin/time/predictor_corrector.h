#ifndef periarlequin_time_predictor_corrector_h
#define periarlequin_time_predictor_corrector_h

#include <periarlequin/coupling/coupling.h>
#include <periarlequin/time/integrated_zone.h>

#include <deal.II/base/discrete_time.h>
#include <deal.II/base/timer.h>

#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The explicit time loop of the paper (section 4.3, eq. 58-69, with the fine-scale damping of
   * eq. 76-80): velocity Verlet for every zone, with the predictor-corrector of the Arlequin
   * coupling between its parts when the zones are coupled. Each step is the sequence of named
   * parts below; a zone or a coupling takes part only if the case has it. Without a coupling
   * the step is plain velocity Verlet of each zone.
   */
  template <int dim>
  class PredictorCorrector
  {
  public:
    /**
     * Integrate @p zones from t = 0 to @p n_steps x @p time_step; @p coupling may be nullptr.
     * Sections are timed in @p timer.
     */
    PredictorCorrector(const std::vector<IntegratedZone *> &zones,
                       Coupling<dim>                       *coupling,
                       const double                         time_step,
                       const unsigned int                   n_steps,
                       TimerOutput                         &timer);

    /** Accelerations at t = 0 (eq. 60), with prescribed nodes and slaves on their masters. */
    void
    initialize();
    /**
     * Instead of initialize(), continuing from a checkpoint whose state the zones hold: the
     * clock advanced to step @p step_number by the same additions as the steps made it.
     */
    void
    resume_at(const unsigned int step_number);

    /** One step from t_n to t_n+1. */
    void
    step();

    /**
     * One step of dynamic relaxation, of size @p dt: a step whose clock stays where it is
     * (the loads and prescribed displacements of the current time), without work accounting,
     * after which every velocity is multiplied by @p velocity_factor (the slaves follow): a
     * viscous damping that keeps the coupling's velocity constraint, since both zones'
     * velocities scale alike. A coupling's multiplier matrix is built for a time step: with
     * a coupling, @p dt must be that one (the caller's to ensure: the clock's step may
     * differ, see advance_clock()).
     */
    void
    relax(const double velocity_factor, const double dt);

    /**
     * For a static solve by conjugate gradients: the projected residual z = P M^-1 (F_ext -
     * F_int) of the current displacements (the prescribed ones imposed, the slaves on their
     * masters) as the zones' accelerations, every velocity zero; P is the M-orthogonal
     * projection onto the motions that keep the coupling's constraint. A step of @p dt (the
     * coupling's) from rest, without damping, gives it: the exact multipliers make the trial
     * velocities dt/2 a* keep the constraint, and so turn them into dt/2 z.
     */
    void
    project_residual(const double dt);

    /**
     * Advance the clock by its step without moving anything: the next loads and prescribed
     * displacements of a sequence of static solves (whose clock steps by the load step).
     */
    void
    advance_clock();

    /**
     * Start the work of the zones' applied forces over the next interval (see
     * IntegratedZone::start_work_interval()).
     */
    void
    start_work_interval(const bool from_unloaded = false);
    /** Work of loads and support reactions since start_work_interval(), zone by zone. */
    void
    account_work();

    /** Current time and step number. */
    const DiscreteTime &
    get_time() const;

  private:
    /** Eq. 58-59: displacements and half-step velocities of every node. */
    void
    predict(const double dt);
    /**
     * The parts of a step after the prediction, at the clock's current time: prescribed
     * motion, slaves, trial accelerations and velocities, fine-scale damping, multipliers.
     */
    void
    complete_step(const double dt);
    /** Prescribed nodes of every zone take their motion at the new time. */
    void
    impose_prescribed_motion();
    /**
     * The coupling's slaves follow their masters' predicted displacements: PD slaves
     * d = N u (the alpha = 1 layer that completes the families), and under the bad coupling
     * FE nodes of the PD half of the overlap follow the PD lattice.
     */
    void
    slaves_follow_masters();
    /**
     * Eq. 60: trial accelerations without multipliers: the forces of every zone, then the
     * interface forces the coupling passes between them (the slaves' PD forces N^T f on the
     * FE nodes), then the accelerations of every zone.
     */
    void
    compute_trial_accelerations();
    /**
     * Eq. 76-79: damping -M_p C_I (w - N v)_I of the fine-scale velocity on the overlap's PD
     * nodes, with the half-step velocities of both zones.
     */
    void
    damp_fine_scale();
    /** Eq. 61: trial velocities v* = v^(n+1/2) + dt/2 a*. */
    void
    compute_trial_velocities(const double dt);
    /**
     * Eq. 62-69: multipliers from d/dt g = 0 at t_n+1 (A lambda = H^T (N v* - w*)), velocity
     * and acceleration corrections of both zones, then the slaves' velocities.
     */
    void
    solve_multipliers_and_correct();
    /** Time @p what in the section "<zone> forces" or "coupling". */
    template <typename Action>
    void
    timed(const std::string &section, const Action &what);

    std::vector<IntegratedZone *> zones;
    Coupling<dim>                *coupling;
    DiscreteTime                  time;
    TimerOutput                  &timer;
  };
} // namespace PeriArlequin

#endif
