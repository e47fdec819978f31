#ifndef periarlequin_time_dynamic_relaxation_h
#define periarlequin_time_dynamic_relaxation_h

#include <periarlequin/base/parameters.h>
#include <periarlequin/base/regions.h>
#include <periarlequin/time/integrated_zone.h>
#include <periarlequin/time/predictor_corrector.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <string>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  namespace Parameters
  {
    /**
     * When a static solve has converged, how long it may try, and the cracks released when
     * it is done.
     */
    template <int dim>
    struct StaticSolve
    {
      double       tolerance      = 1e-6;
      unsigned int max_iterations = 200000;
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
   * The static equilibrium of the coupled model under the loads of the current time, by
   * adaptive dynamic relaxation: the explicit steps of the time loop (the same forces, the
   * same coupling and multipliers) with the clock held, the velocities damped after each
   * step by exp(-c dt). The damping c = 2 omega is critical for the frequency omega^2 =
   * du^T K du / du^T M du of the last step's motion du (the local Rayleigh quotient, K du
   * = -M da from the change of acceleration over the step, so it holds for the coupled,
   * blended model too), so it follows the slowest mode as the motion settles into it. The
   * quotient of the step, not of the whole displacement: a displacement that is mostly a
   * stress-free motion (a part that a grip carries, once cracked off) would give omega near
   * 0 and no damping. Converged when the out-of-balance force |M a| of
   * the free components falls below the tolerance times the norm of the applied forces
   * (loads and support reactions; at least the largest of the equilibria found before, for
   * a sequence of solves in which the body unloads as it cracks).
   */
  template <int dim>
  class DynamicRelaxation
  {
  public:
    /** What a solve reached. */
    struct Result
    {
      unsigned int iterations;
      /** |M a| / |F_applied| at the end. */
      double relative_residual;
    };

    /** Called every iteration with the iteration and the relative residual. */
    using Progress = std::function<void(unsigned int, double)>;

    /** Relax @p zones by steps of @p time_step of @p integrator (see relax() there). */
    DynamicRelaxation(const Parameters::StaticSolve<dim>  &parameters,
                      const std::vector<IntegratedZone *> &zones,
                      PredictorCorrector<dim>             &integrator,
                      const double                         time_step);

    /**
     * Relax to equilibrium, then leave every velocity at zero. Throws if the tolerance is
     * not reached within the allowed iterations, if the residual grows without bound, or if
     * it stops falling.
     */
    Result
    solve(const Progress &progress);

    /**
     * Count the current state's applied forces among those of the equilibria found, the
     * scale of later residuals: solve() does so at its end, and a run resumed from a
     * checkpoint of an equilibrium before its first solve (collective).
     */
    void
    remember_equilibrium();

    /** The relaxation's step [s]. */
    double
    get_time_step() const;

  private:
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
     * exp(-c dt) with c from the local Rayleigh quotient of the last step's motion, or
     * @p previous where the step gives none (collective).
     */
    double
    velocity_factor(const double previous) const;

    /** Iterations without a 1 % fall of the least residual after which a solve has stalled. */
    static constexpr unsigned int stall_iterations = 10000;

    const Parameters::StaticSolve<dim> parameters;
    std::vector<IntegratedZone *>      zones;
    PredictorCorrector<dim>           &integrator;
    const double                       time_step;
    /**
     * The largest |F_applied|^2 of the equilibria found: the scale of the residual once a
     * body unloads (not of the transients of a relaxation, which a resumed run has not seen).
     */
    double largest_equilibrium_force = 0;
  };
} // namespace PeriArlequin

#endif
