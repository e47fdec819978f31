#include <periarlequin/time/static_solver.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace PeriArlequin
{
  namespace Parameters
  {
    template <int dim>
    void
    StaticSolve<dim>::entries(ParameterEntries &entries)
    {
      entries.add("Method",
                  method,
                  static_solve_method_names,
                  "How a static solve finds the equilibrium: relaxation (adaptive dynamic "
                  "relaxation: explicit steps with a damping that follows the slowest mode; "
                  "any blending, contact), conjugate gradients (preconditioned by the masses "
                  "and projected onto the coupling's constraint; needs forces that derive "
                  "from an energy: uncoupled zones or Coupling/Blending = energy, no contact; "
                  "usually several times fewer force evaluations), or automatic (conjugate "
                  "gradients where they can run, else relaxation).");
      entries.add("Tolerance",
                  tolerance,
                  Patterns::Double(0),
                  "Time/Integration = static then explicit or quasi-static: a static solve has "
                  "converged "
                  "when the out-of-balance force |M a| of the components that are not "
                  "prescribed is at most this fraction of the norm of the applied forces "
                  "(loads and support reactions; in a quasi-static run at least the largest "
                  "norm of the equilibria before, so that a body that cracks through and "
                  "unloads still converges); in [1e-12, 1) [-].");
      entries.add("Maximum iterations",
                  max_iterations,
                  Patterns::Integer(1),
                  "Iterations (force evaluations) allowed before the static solve gives up and "
                  "says which residual it reached. One costs about one explicit time step; "
                  "the iterations needed grow with the body's size over the lattice spacing "
                  "or the cell size (for relaxation several times the longitudinal wave's "
                  "transit in steps) [-].");
      entries.add("Load step",
                  load_step,
                  Patterns::Double(0),
                  "Time/Integration = quasi-static: the equilibria are those under the loads "
                  "and prescribed displacements of t = k x Load step, k = 1, 2, ... up to "
                  "Time/End time; > 0 then. The time is that of the load functions only: "
                  "choose the step so that an increment changes the load by a small fraction "
                  "of the load at which cracks grow (a peak load is resolved to one "
                  "increment) [s].");
      entries.add("Released cracks",
                  released_cracks_text,
                  Patterns::Anything(),
                  "Cracks that cut the bonds of the PD zone when the static solve is done, "
                  "before the explicit loop: a crack released in a body that stores elastic "
                  "energy. Given as Peridynamics/Pre-cracks ('x0, y0 : x1, y1' in 2D, "
                  "'corner : edge a : edge b' in 3D, separated by ';'), in the pure PD region "
                  "[m]. Empty: none.");
    }

    template <int dim>
    void
    StaticSolve<dim>::declare_parameters(ParameterHandler &prm)
    {
      ParameterEntries::declare<StaticSolve<dim>>(prm, "Static solve");
    }

    template <int dim>
    void
    StaticSolve<dim>::parse_parameters(ParameterHandler &prm)
    {
      ParameterEntries::parse(prm, "Static solve", *this);
      // Below about 1e-12 the residual is the round-off of the forces: it is never reached.
      if (!(tolerance >= 1e-12 && tolerance < 1))
        throw_invalid_parameter("Static solve/Tolerance",
                                tolerance,
                                "a value in [1e-12, 1) [-] (the residual does not fall below "
                                "the round-off of the forces)");
      released_cracks =
        PreCrack<dim>::parse_list(released_cracks_text, "Static solve/Released cracks");
    }

    template struct StaticSolve<2>;
    template struct StaticSolve<3>;
  } // namespace Parameters

  template <int dim>
  StaticSolver<dim>::StaticSolver(const Parameters::StaticSolve<dim>  &parameters,
                                  const std::vector<IntegratedZone *> &zones,
                                  PredictorCorrector<dim>             &integrator,
                                  const double                         time_step)
    : parameters(parameters)
    , zones(zones)
    , integrator(integrator)
    , time_step(time_step)
  {}

  template <int dim>
  std::unique_ptr<StaticSolver<dim>>
  StaticSolver<dim>::create(const Parameters::StaticSolve<dim>  &parameters,
                            const std::vector<IntegratedZone *> &zones,
                            PredictorCorrector<dim>             &integrator,
                            const double                         time_step,
                            const std::string                   &obstacle,
                            const bool                           relaxation_preferred)
  {
    using Method = Parameters::StaticSolveMethod;
    if (parameters.method == Method::conjugate_gradients && !obstacle.empty())
      throw_invalid_parameter("Static solve/Method",
                              "conjugate gradients",
                              "relaxation or automatic here: " + obstacle);
    if (parameters.method == Method::relaxation ||
        (parameters.method == Method::automatic && (!obstacle.empty() || relaxation_preferred)))
      return std::make_unique<DynamicRelaxation<dim>>(parameters, zones, integrator, time_step);
    return std::make_unique<ConjugateGradients<dim>>(parameters, zones, integrator, time_step);
  }

  template <int dim>
  std::pair<double, double>
  StaticSolver<dim>::squared_force_norms() const
  {
    double residual = 0, applied = 0;
    for (const IntegratedZone *zone : zones)
      {
        const auto [r, f] = zone->squared_force_norms();
        residual += r;
        applied += f;
      }
    return {residual, applied};
  }

  template <int dim>
  double
  StaticSolver<dim>::relative_residual() const
  {
    const auto [residual, applied] = squared_force_norms();
    const double reference         = std::max(largest_equilibrium_force, applied);
    // Without loads the equilibrium is the unloaded body: the residual is measured absolutely.
    return reference > 0 ? std::sqrt(residual / reference) : std::sqrt(residual);
  }

  template <int dim>
  void
  StaticSolver<dim>::remember_equilibrium()
  {
    largest_equilibrium_force = std::max(largest_equilibrium_force, squared_force_norms().second);
  }

  template <int dim>
  double
  StaticSolver<dim>::equilibrium_force_scale() const
  {
    return largest_equilibrium_force;
  }

  template <int dim>
  void
  StaticSolver<dim>::resume_equilibrium_force_scale(const double scale)
  {
    largest_equilibrium_force = scale;
    remember_equilibrium();
  }

  template <int dim>
  void
  StaticSolver<dim>::watch(const unsigned int iteration,
                           const double       residual,
                           const std::string &diverged_hint)
  {
    if (iteration <= 1)
      {
        smallest = progress_reference = std::numeric_limits<double>::infinity();
        last_progress                 = iteration;
      }
    // The last iteration at which the residual fell 1 % below the one of the iteration
    // before it that did so: a residual that stops falling has reached the round-off of the
    // forces (or a mode that does not settle).
    if (residual < 0.99 * progress_reference)
      {
        last_progress      = iteration;
        progress_reference = residual;
      }
    smallest = std::min(smallest, residual);
    if (iteration - last_progress > stall_iterations)
      {
        std::ostringstream message;
        message << "The static solve (" << name() << ") stalled: after " << iteration
                << " iterations the out-of-balance force has not fallen by 1 % in "
                << stall_iterations << " iterations; it is " << residual
                << " times the applied forces (least " << smallest
                << "), above Static solve/Tolerance = " << parameters.tolerance
                << ". Use a tolerance above the residual reached; a residual far above it "
                   "means a part that has no equilibrium (cracked off under a load: "
                   "drive a specimen by a prescribed displacement).";
        AssertThrow(false, ExcMessage(message.str()));
      }
    // A residual that grows by orders of magnitude beyond the least seen does not come back.
    if (!std::isfinite(residual) || residual > 1e6 * std::max(smallest, 1e-12))
      {
        std::ostringstream message;
        message << "The static solve (" << name() << ") diverged: after " << iteration
                << " iterations the out-of-balance force is " << residual
                << " times the applied forces (least " << smallest << "). " << diverged_hint
                << "A body that can move as a rigid body under a net load has no static "
                   "equilibrium: check that it is supported (a prescribed displacement).";
        AssertThrow(false, ExcMessage(message.str()));
      }
    if (iteration >= parameters.max_iterations && !(residual <= parameters.tolerance))
      {
        std::ostringstream message;
        message << "The static solve (" << name() << ") did not converge: after " << iteration
                << " iterations (Static solve/Maximum iterations) the out-of-balance force is "
                << residual << " times the applied forces, above Static solve/Tolerance = "
                << parameters.tolerance
                << ". Allow more iterations or a larger tolerance; a body that can move as a "
                   "rigid body under a net load has no static equilibrium.";
        AssertThrow(false, ExcMessage(message.str()));
      }
  }

  template <int dim>
  double
  StaticSolver<dim>::get_time_step() const
  {
    return time_step;
  }

  template <int dim>
  double
  DynamicRelaxation<dim>::velocity_factor(const double previous) const
  {
    double stiffness = 0, inertia = 0;
    for (const IntegratedZone *zone : this->zones)
      {
        const auto [k, m] = zone->relaxation_step_sums();
        stiffness += k;
        inertia += m;
      }
    // A step that did not move, or moved along a softening direction (bonds that gave way),
    // says nothing of the frequency: the last estimate stays.
    if (!(inertia > 0) || !(stiffness > 0))
      return previous;
    const double omega = std::sqrt(stiffness / inertia);
    return std::exp(-2. * omega * this->time_step);
  }

  template <int dim>
  typename DynamicRelaxation<dim>::Result
  DynamicRelaxation<dim>::solve(const Progress &progress)
  {
    // The residual is known after the first step only: the forces of the current time (a
    // clock moved on since the last evaluation, as between quasi-static increments) are
    // evaluated in it.
    double       factor    = 1.;
    double       residual  = std::numeric_limits<double>::infinity();
    unsigned int iteration = 0;
    while (!(residual <= this->parameters.tolerance))
      {
        for (IntegratedZone *zone : this->zones)
          zone->start_relaxation_step();
        this->integrator.relax(factor, this->time_step);
        factor   = velocity_factor(factor);
        residual = this->relative_residual();
        ++iteration;
        progress(iteration, residual);
        this->watch(iteration, residual, "Check Time/Time step against the stable step. ");
      }
    evaluate_at_rest();
    this->remember_equilibrium();
    return {iteration, this->relative_residual()};
  }

  template <int dim>
  void
  DynamicRelaxation<dim>::evaluate_at_rest()
  {
    // At an equilibrium of the relaxation the accelerations vanish: the step moves nothing
    // but by dt^2/2 times the residual.
    this->integrator.relax(0., this->time_step);
  }

  template <int dim>
  std::string
  DynamicRelaxation<dim>::name() const
  {
    return "relaxation";
  }

  template <int dim>
  double
  ConjugateGradients<dim>::squared_residual_norm() const
  {
    double sum = 0;
    for (const IntegratedZone *zone : this->zones)
      sum += zone->squared_residual_norm();
    return sum;
  }

  template <int dim>
  typename ConjugateGradients<dim>::Result
  ConjugateGradients<dim>::solve(const Progress &progress)
  {
    const auto for_each_zone = [&](const auto &action) {
      for (IntegratedZone *zone : this->zones)
        action(*zone);
    };
    unsigned int iteration = 0;
    const auto   evaluate  = [&] {
      evaluate_at_rest();
      ++iteration;
    };
    evaluate();
    double residual = this->relative_residual();
    progress(iteration, residual);
    this->watch(iteration, residual, "");
    // z . M z of the current residual; the trial move of the first iteration is that of a
    // relaxation step (dt^2 a), later the last step length (which keeps the extrapolation
    // short).
    double zmz     = 0;
    double trial   = this->time_step * this->time_step;
    bool   restart = true;
    while (!(residual <= this->parameters.tolerance))
      {
        if (restart)
          {
            zmz = squared_residual_norm();
            for_each_zone([&](IntegratedZone &zone) { zone.update_search_direction(0.); });
            restart = false;
          }
        for_each_zone([&](IntegratedZone &zone) {
          zone.start_relaxation_step();
          zone.move_along_search_direction(trial);
        });
        evaluate();
        // -trial p . M (z(u + trial p) - z(u)) = trial^2 p^T K p.
        double curvature = 0;
        for (const IntegratedZone *zone : this->zones)
          curvature += zone->relaxation_step_sums().first;
        if (!(curvature > 0))
          {
            std::ostringstream message;
            message << "The static solve (conjugate gradients) met a search direction along "
                       "which the stiffness is not positive (p^T K p = "
                    << curvature / (trial * trial) << ") after " << iteration
                    << " iterations: a rigid-body motion (a body without supports) or a "
                       "stiffness that is not symmetric. Use Static solve/Method = relaxation.";
            AssertThrow(false, ExcMessage(message.str()));
          }
        const double step = zmz * trial * trial / curvature;
        for_each_zone(
          [&](IntegratedZone &zone) { zone.extrapolate_relaxation_step(step / trial); });
        trial             = step;
        const double next = squared_residual_norm();
        residual          = this->relative_residual();
        if (residual <= this->parameters.tolerance)
          {
            // The extrapolated residual meets the tolerance: the true one decides.
            evaluate();
            residual = this->relative_residual();
            restart  = true;
          }
        else
          {
            for_each_zone([&](IntegratedZone &zone) { zone.update_search_direction(next / zmz); });
            zmz = next;
          }
        progress(iteration, residual);
        this->watch(iteration, residual, "");
      }
    // The last evaluation left the state at rest, with the residual as acceleration.
    this->remember_equilibrium();
    return {iteration, residual};
  }

  template <int dim>
  void
  ConjugateGradients<dim>::evaluate_at_rest()
  {
    // Not a relaxation step: at the constrained equilibrium the multiplier forces do not
    // vanish, and a step would move the overlap by the half of them that the explicit
    // correction leaves in the accelerations.
    this->integrator.project_residual(this->time_step);
  }

  template <int dim>
  std::string
  ConjugateGradients<dim>::name() const
  {
    return "conjugate gradients";
  }

  template class StaticSolver<2>;
  template class StaticSolver<3>;
  template class DynamicRelaxation<2>;
  template class DynamicRelaxation<3>;
  template class ConjugateGradients<2>;
  template class ConjugateGradients<3>;
} // namespace PeriArlequin
