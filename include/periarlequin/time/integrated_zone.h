#ifndef periarlequin_time_integrated_zone_h
#define periarlequin_time_integrated_zone_h

#include <string>
#include <utility>

namespace PeriArlequin
{
  /**
   * What the explicit integrator needs of a zone (the FE zone, the PD zone): velocity Verlet
   * split into the parts between which the Arlequin coupling acts (eq. 58-61). A zone owns
   * its state (displacement, velocity, acceleration of its nodes) and its loads.
   */
  class IntegratedZone
  {
  public:
    virtual ~IntegratedZone() = default;

    /** "FE" or "PD": the zone's name in timings. */
    virtual std::string
    name() const = 0;

    /** Eq. 58-59: x += dt v + dt^2/2 a, then the half-step velocity v += dt/2 a. */
    virtual void
    predict(const double dt) = 0;

    /**
     * Prescribed nodes take the displacement, velocity and acceleration of their prescribed
     * motion at @p time (central differences in time over the step).
     */
    virtual void
    impose_prescribed_motion(const double time) = 0;

    /**
     * The forces of the current displacements at @p time: internal (and, for particles,
     * bond breaking first) and applied. Between this and compute_accelerations() a coupling
     * adds the forces the other zone exerts (the interface forces of eq. 58-59).
     */
    virtual void
    compute_forces(const double time) = 0;

    /**
     * Eq. 60: trial accelerations M^-1 (F_ext - F_int + F_interface) at @p time, without
     * multipliers; prescribed nodes keep their prescribed acceleration, and their applied
     * force takes the support reaction.
     */
    virtual void
    compute_accelerations(const double time) = 0;

    /** Eq. 61: trial velocities v += dt/2 a; prescribed nodes keep their velocity. */
    virtual void
    correct(const double dt) = 0;

    /**
     * Remember the displacements and applied forces at which the work of the next interval
     * starts: before a step, or before a static solve. With @p from_unloaded the interval
     * starts from zero displacement and force instead: the work of a static solve from the
     * unloaded body is that of loads raised slowly (half the final force times the
     * displacement for a linear response), not that of loads applied at once.
     */
    virtual void
    start_work_interval(const bool from_unloaded = false) = 0;
    /**
     * Work of loads and support reactions since start_work_interval() (trapezoidal rule:
     * exact for forces linear in the displacement between the two states).
     */
    virtual void
    account_work() = 0;

    /** Kinetic energy of the weighted masses [J]. */
    virtual double
    kinetic_energy() const = 0;
    /** Blended strain energy of the last computed forces [J]. */
    virtual double
    strain_energy() const = 0;
    /** Work of loads and support reactions since the start [J]. */
    virtual double
    external_work() const = 0;

    /**
     * Dynamic relaxation: multiply the velocities of the nodes that are not prescribed by
     * @p factor (the coupling's slaves follow after).
     */
    virtual void
    scale_velocities(const double factor) = 0;
    /** Dynamic relaxation: keep the displacements and accelerations before a step. */
    virtual void
    start_relaxation_step() = 0;
    /**
     * Dynamic relaxation, after the step: over the components that are neither prescribed
     * nor slaves, the sums of -m du . da and m du . du, du and da the changes of
     * displacement and acceleration over the step: du^T K du and du^T M du, the local
     * Rayleigh quotient of the motion the damping acts on [N m, kg m^2] (collective).
     */
    virtual std::pair<double, double>
    relaxation_step_sums() const = 0;
    /**
     * For the convergence of a static solve, the squared norms of the out-of-balance force
     * M a over the components that are not prescribed, and of the applied forces (loads and
     * support reactions) over all [N^2] (collective).
     */
    virtual std::pair<double, double>
    squared_force_norms() const = 0;

    /**
     * @name Static solve by conjugate gradients, over the free components (neither
     * prescribed nor slaves). The projected residual z = P M^-1 (F_ext - F_int), P the
     * M-orthogonal projection onto the velocities that keep the coupling's constraint, is
     * held as the acceleration; start_relaxation_step() keeps the displacement u0 and z0.
     */
    /** @{ */
    /**
     * After a step from rest whose multipliers made the velocities keep the constraint, the
     * velocities of the free components are dt/2 z: z becomes the acceleration, the
     * velocities zero.
     */
    virtual void
    take_projected_residual(const double dt) = 0;
    /** z . M z, the sum of m a . a over the free components [N m/s^2] (collective). */
    virtual double
    squared_residual_norm() const = 0;
    /** The search direction p = a + @p beta p (0 on the other components). */
    virtual void
    update_search_direction(const double beta) = 0;
    /** u = u0 + @p s p. */
    virtual void
    move_along_search_direction(const double s) = 0;
    /**
     * u = u0 + @p c (u - u0), a = z0 + @p c (a - z0): the state of a move @p c times the
     * last one, for forces linear in the displacement.
     */
    virtual void
    extrapolate_relaxation_step(const double c) = 0;
    /** @} */
  };
} // namespace PeriArlequin

#endif
