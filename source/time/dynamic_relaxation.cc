#include <periarlequin/time/dynamic_relaxation.h>

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
                  "Relaxation steps allowed before the static solve gives up and says which "
                  "residual it reached. A step costs about one explicit time step; the "
                  "iterations needed grow with the body's size over the time step (several "
                  "times the longitudinal wave's transit in steps) [-].");
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
  DynamicRelaxation<dim>::DynamicRelaxation(const Parameters::StaticSolve<dim>  &parameters,
                                            const std::vector<IntegratedZone *> &zones,
                                            PredictorCorrector<dim>             &integrator,
                                            const double                         time_step)
    : parameters(parameters)
    , zones(zones)
    , integrator(integrator)
    , time_step(time_step)
  {}

  template <int dim>
  double
  DynamicRelaxation<dim>::velocity_factor(const double previous) const
  {
    double stiffness = 0, inertia = 0;
    for (const IntegratedZone *zone : zones)
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
    return std::exp(-2. * omega * time_step);
  }

  template <int dim>
  std::pair<double, double>
  DynamicRelaxation<dim>::squared_force_norms() const
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
  DynamicRelaxation<dim>::relative_residual() const
  {
    const auto [residual, applied] = squared_force_norms();
    const double reference         = std::max(largest_equilibrium_force, applied);
    // Without loads the equilibrium is the unloaded body: the residual is measured absolutely.
    return reference > 0 ? std::sqrt(residual / reference) : std::sqrt(residual);
  }

  template <int dim>
  void
  DynamicRelaxation<dim>::remember_equilibrium()
  {
    largest_equilibrium_force = std::max(largest_equilibrium_force, squared_force_norms().second);
  }

  template <int dim>
  typename DynamicRelaxation<dim>::Result
  DynamicRelaxation<dim>::solve(const Progress &progress)
  {
    // The residual is known after the first step only: the forces of the current time (a
    // clock moved on since the last evaluation, as between quasi-static increments) are
    // evaluated in it.
    double factor   = 1.;
    double residual = std::numeric_limits<double>::infinity();
    double smallest = residual;
    // The last iteration at which the residual fell 1 % below the one of the iteration
    // before it that did so: a residual that stops falling has reached the round-off of the
    // forces (or a mode that does not settle).
    unsigned int last_progress      = 0;
    double       progress_reference = residual;
    unsigned int iteration;
    for (iteration = 0;
         iteration < parameters.max_iterations && !(residual <= parameters.tolerance);
         ++iteration)
      {
        for (IntegratedZone *zone : zones)
          zone->start_relaxation_step();
        integrator.relax(factor, time_step);
        factor   = velocity_factor(factor);
        residual = relative_residual();
        if (residual < 0.99 * progress_reference)
          {
            last_progress      = iteration;
            progress_reference = residual;
          }
        smallest = std::min(smallest, residual);
        progress(iteration + 1, residual);
        if (iteration - last_progress > stall_iterations)
          {
            std::ostringstream message;
            message << "The static solve stalled: after " << iteration + 1
                    << " iterations the out-of-balance force has not fallen by 1 % in "
                    << stall_iterations << " iterations; it is " << residual
                    << " times the applied forces (least " << smallest
                    << "), above Static solve/Tolerance = " << parameters.tolerance
                    << ". Use a tolerance above the residual reached; a residual far above it "
                       "means a part that has no equilibrium (cracked off under a load: "
                       "drive a specimen by a prescribed displacement).";
            AssertThrow(false, ExcMessage(message.str()));
          }
        // A residual that grows by orders of magnitude beyond the least seen does not
        // come back: a step beyond the stable one, or a body with a rigid motion under load.
        if (!std::isfinite(residual) || residual > 1e6 * std::max(smallest, 1e-12))
          {
            std::ostringstream message;
            message << "The static solve diverged: after " << iteration + 1
                    << " iterations the out-of-balance force is " << residual
                    << " times the applied forces (least " << smallest
                    << "). Check Time/Time step against the stable step, and that the "
                       "body is supported (a prescribed displacement): a body that can move "
                       "as a rigid body under a net load has no static equilibrium.";
            AssertThrow(false, ExcMessage(message.str()));
          }
      }
    if (!(residual <= parameters.tolerance))
      {
        std::ostringstream message;
        message << "The static solve did not converge: after " << iteration
                << " iterations (Static solve/Maximum iterations) the out-of-balance force is "
                << residual << " times the applied forces, above Static solve/Tolerance = "
                << parameters.tolerance
                << ". Allow more iterations or a larger tolerance; a body that can move as a "
                   "rigid body under a net load has no static equilibrium.";
        AssertThrow(false, ExcMessage(message.str()));
      }
    // At rest in the equilibrium found.
    integrator.relax(0., time_step);
    remember_equilibrium();
    return {iteration, relative_residual()};
  }

  template <int dim>
  double
  DynamicRelaxation<dim>::get_time_step() const
  {
    return time_step;
  }

  template class DynamicRelaxation<2>;
  template class DynamicRelaxation<3>;
} // namespace PeriArlequin
