#ifndef periarlequin_time_static_solver_h
#define periarlequin_time_static_solver_h

#include <periarlequin/base/parameters.h>
#include <periarlequin/base/regions.h>
#include <periarlequin/time/integrated_zone.h>
#include <periarlequin/time/predictor_corrector.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  namespace Parameters
  {
    /** How a static solve finds the equilibrium. */
    enum class StaticSolveMethod
    {
      /** Conjugate gradients where the coupled stiffness is symmetric, else relaxation. */
      automatic,
      /** Adaptive dynamic relaxation (DynamicRelaxation). */
      relaxation,
      /** Projected conjugate gradients (ConjugateGradients). */
      conjugate_gradients
    };

    inline const SelectionNames<StaticSolveMethod> static_solve_method_names = {
      {"automatic", StaticSolveMethod::automatic},
      {"relaxation", StaticSolveMethod::relaxation},
      {"conjugate gradients", StaticSolveMethod::conjugate_gradients}};

    /**
     * How a static solve finds the equilibrium, when it has converged, how long it may try,
     * and the cracks released when it is done.
     */
    template <int dim>
    struct StaticSolve
    {
      StaticSolveMethod method         = StaticSolveMethod::automatic;
      double            tolerance      = 1e-6;
      unsigned int      max_iterations = 200000;
      /** Time between the equilibria of Time/Integration = quasi-static [s]. */
      double load_step = 0;
      /** Released cracks as given, and as parsed. */
      std::string                released_cracks_text;
      std::vector<PreCrack<dim>> released_cracks;

      void
      entries(ParameterEntries &entries);
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters

  /**
   * The static equilibrium of the coupled model under the loads of the current time, found
   * through the operations of the explicit integrator (the same forces, coupling and
   * multipliers) with the clock held. Converged when the out-of-balance force |M a| of the
   * free components falls below the tolerance times the norm of the applied forces (loads
   * and support reactions; at least the largest of the equilibria found before, for a
   * sequence of solves in which the body unloads as it cracks).
   */
  template <int dim>
  class StaticSolver
  {
  public:
    /** What a solve reached. */
    struct Result
    {
      /** Force evaluations, each about the cost of an explicit step. */
      unsigned int iterations;
      /** |M a| / |F_applied| at the end. */
      double relative_residual;
    };

    /** Called every iteration with the iteration and the relative residual. */
    using Progress = std::function<void(unsigned int, double)>;

    StaticSolver(const Parameters::StaticSolve<dim>  &parameters,
                 const std::vector<IntegratedZone *> &zones,
                 PredictorCorrector<dim>             &integrator,
                 const double                         time_step);
    virtual ~StaticSolver() = default;

    /**
     * The solver that Static solve/Method names; automatic: conjugate gradients unless
     * @p obstacle says why they cannot run (forces that derive from no energy, contact) or
     * the relaxation is @p relaxation_preferred. Conjugate gradients named with an
     * obstacle are refused.
     */
    static std::unique_ptr<StaticSolver<dim>>
    create(const Parameters::StaticSolve<dim>  &parameters,
           const std::vector<IntegratedZone *> &zones,
           PredictorCorrector<dim>             &integrator,
           const double                         time_step,
           const std::string                   &obstacle,
           const bool                           relaxation_preferred);

    /**
     * Find the equilibrium, then leave every velocity at zero. Throws if the tolerance is
     * not reached within the allowed iterations, if the residual grows without bound, or if
     * it stops falling.
     */
    virtual Result
    solve(const Progress &progress) = 0;

    /**
     * One force evaluation of the current state, left at rest (the bonds beyond their limit
     * break in it if fracture is on), moving nothing but by the round-off of an
     * equilibrium: a relaxation step with the velocities zeroed, or the projected residual.
     */
    virtual void
    evaluate_at_rest() = 0;

    /** "relaxation" or "conjugate gradients": the method, for the log. */
    virtual std::string
    name() const = 0;

    /**
     * Count the current state's applied forces among those of the equilibria found, the
     * scale of later residuals: solve() does so at its end (collective).
     */
    void
    remember_equilibrium();

    /** The largest |F_applied|^2 of the equilibria found so far, for checkpoints [N^2]. */
    double
    equilibrium_force_scale() const;

    /**
     * A run resumed from a checkpoint takes the scale of the equilibria its first part found
     * (@p scale, equilibrium_force_scale() when it was written), then counts the restored
     * equilibrium (collective): past the peak of a crack that runs, the restored state's own
     * applied forces would be a smaller scale, so a tighter stopping criterion, than the run
     * that did not stop had.
     */
    void
    resume_equilibrium_force_scale(const double scale);

    /** The step of the explicit operations a solve is made of [s]. */
    double
    get_time_step() const;

  protected:
    /** |M a|^2 and |F_applied|^2 over all zones (collective). */
    std::pair<double, double>
    squared_force_norms() const;
    /**
     * |M a| / |F_applied| over all zones, |F_applied| at least the largest of the
     * equilibria so far (collective).
     */
    double
    relative_residual() const;
    /**
     * After @p iteration iterations at @p residual: throw if the residual has stopped
     * falling or grown by orders of magnitude (@p diverged_hint says what to check then),
     * or if the allowed iterations are used up without convergence.
     */
    void
    watch(const unsigned int iteration, const double residual, const std::string &diverged_hint);
    /** Iterations without a 1 % fall of the least residual after which a solve has stalled. */
    static constexpr unsigned int stall_iterations = 10000;

    const Parameters::StaticSolve<dim> parameters;
    std::vector<IntegratedZone *>      zones;
    PredictorCorrector<dim>           &integrator;
    const double                       time_step;

  private:
    /**
     * The largest |F_applied|^2 of the equilibria found: the scale of the residual once a
     * body unloads (not of the transients of a solve, which a resumed run has not seen).
     */
    double largest_equilibrium_force = 0;
    /** The least residual of the current solve, and the last iteration that lowered it by 1 %. */
    double       smallest = 0, progress_reference = 0;
    unsigned int last_progress = 0;
  };

  /**
   * Adaptive dynamic relaxation: the explicit steps of the time loop with the clock held,
   * the velocities damped after each step by exp(-c dt). The damping c = 2 omega is
   * critical for the frequency omega^2 = du^T K du / du^T M du of the last step's motion du
   * (the local Rayleigh quotient, K du = -M da from the change of acceleration over the
   * step, so it holds for the coupled, blended model too), so it follows the slowest mode
   * as the motion settles into it. The quotient of the step, not of the whole displacement:
   * a displacement that is mostly a stress-free motion (a part that a grip carries, once
   * cracked off) would give omega near 0 and no damping. Works for every blending, since it
   * needs no energy.
   */
  template <int dim>
  class DynamicRelaxation : public StaticSolver<dim>
  {
  public:
    using StaticSolver<dim>::StaticSolver;
    using typename StaticSolver<dim>::Result;
    using typename StaticSolver<dim>::Progress;

    Result
    solve(const Progress &progress) override;
    void
    evaluate_at_rest() override;
    std::string
    name() const override;

  private:
    /**
     * exp(-c dt) with c from the local Rayleigh quotient of the last step's motion, or
     * @p previous where the step gives none (collective).
     */
    double
    velocity_factor(const double previous) const;
  };

  /**
   * Conjugate gradients on the free components, preconditioned by the lumped masses and
   * projected onto the displacements that keep the coupling's constraint G u = 0: the
   * residual of an iteration is z = P M^-1 (F_ext - F_int), P the M-orthogonal projection,
   * which one explicit step from rest with exact multipliers gives (the trial velocities
   * dt/2 a* corrected to keep the constraint are dt/2 z). Needs a symmetric stiffness:
   * uncoupled zones or energy blending. An iteration costs one force evaluation: the
   * curvature p^T K p along the search direction p comes from a trial move s p (s the last
   * step length), and the state at the new iterate is extrapolated linearly from it; when
   * the extrapolated residual meets the tolerance the residual is evaluated there, and the
   * iteration restarts from it if it does not (forces not quite linear: the PD bonds'
   * geometry).
   */
  template <int dim>
  class ConjugateGradients : public StaticSolver<dim>
  {
  public:
    using StaticSolver<dim>::StaticSolver;
    using typename StaticSolver<dim>::Result;
    using typename StaticSolver<dim>::Progress;

    Result
    solve(const Progress &progress) override;
    void
    evaluate_at_rest() override;
    std::string
    name() const override;

  private:
    /** z . M z over all zones (collective). */
    double
    squared_residual_norm() const;
  };
} // namespace PeriArlequin

#endif
