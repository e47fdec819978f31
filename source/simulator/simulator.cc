#include <periarlequin/simulator.h>
#include <periarlequin/simulator/checkpoint_record.h>

#include <deal.II/base/quadrature_lib.h>

#include <algorithm>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <sstream>

namespace PeriArlequin
{
  namespace
  {
    /**
     * What to do where the FE strain exceeds the critical stretch: with a fixed zone, give
     * that place to PD; with an adaptive one, let a strain criterion convert it (earlier).
     */
    template <int dim>
    std::string
    fe_strain_advice(const PDZoneGrowth<dim> *growth)
    {
      if (!growth)
        return "Put that place in the PD region (Peridynamics/Region), or let an adaptive zone "
               "grow there (Adaptive PD zone/Conversion criterion = damage distance, strain).";
      if (!growth->uses_criterion("strain"))
        return "Add the strain criterion (Adaptive PD zone/Conversion criterion = damage "
               "distance, strain): it converts the cells whose FE strain nears the critical "
               "stretch.";
      return "Let the strain criterion convert earlier (a lower Adaptive PD zone/strain/"
             "Fraction of critical stretch).";
    }
  } // namespace

  template <int dim>
  void
  Simulator<dim>::run()
  {
    if (!setup_done)
      setup();
    prepare_output();
    const auto due = [&](const unsigned int interval) {
      return interval > 0 && (get_step_number() % interval == 0 || get_step_number() == n_steps);
    };

    if (!resumed && !static_solved &&
        time_parameters.integration == Parameters::Integration::static_then_explicit)
      solve_static();
    // A quasi-static run starts from the equilibrium of t = 0 (with its cracks).
    if (!resumed && !quasi_static_started &&
        time_parameters.integration == Parameters::Integration::quasi_static)
      solve_increment();
    if (resumed)
      restore_outputs();
    else
      {
        if (due(output_parameters.energy_interval))
          record_statistics();
        if (due(output_parameters.output_interval))
          write_output();
      }

    wall_clock.restart();
    last_checkpoint_wall_time = 0;
    first_step                = get_step_number();
    bool checkpointed         = false;
    while (get_step_number() < n_steps)
      {
        advance();
        if (due(output_parameters.energy_interval))
          record_statistics();
        if (due(output_parameters.output_interval))
          write_output();
        checkpointed = checkpoint_due();
        if (checkpointed)
          write_checkpoint();
        report_progress(get_step_number() == n_steps);
      }
    if (checkpoint_parameters.at_end && !checkpointed)
      write_checkpoint();
    const double loop_time = wall_clock.wall_time();
    check_finite(kinetic_energy());
    // A quasi-static run's work is its static-solve iterations.
    const bool quasi_static = time_parameters.integration == Parameters::Integration::quasi_static;
    const std::uint64_t steps_run =
      quasi_static ? relaxation_steps : static_cast<std::uint64_t>(n_steps - first_step);
    if (quasi_static)
      pcout << "Quasi-static: " << n_steps - first_step << " increments, " << steps_run
            << " static-solve iterations in " << loop_time << " s";
    else
      pcout << "Time loop: " << steps_run << " steps in " << loop_time << " s";
    if (fe_zone)
      pcout << ", " << static_cast<double>(fe_zone->n_dofs()) * steps_run / loop_time
            << " FE DoF-steps/s";
    if (pd_zone)
      pcout << ", " << static_cast<double>(pd_zone->n_global_bonds()) * steps_run / loop_time
            << " PD bond-updates/s";
    pcout << std::endl;
    if (zone_growth && pd_zone && !quasi_static && steps_run > 0)
      {
        // What decides whether the adaptive zone pays on this case: how near it came to the
        // particles of pure PD, and what growing it cost.
        const auto   times = timer.get_summary_data(TimerOutput::total_wall_time);
        const auto   found = times.find("PD zone growth");
        const double growth =
          Utilities::MPI::max(found == times.end() ? 0. : found->second, communicator);
        const auto   pure_pd_sites = pd_zone->n_lattice_sites();
        const double share = static_cast<double>(pd_zone->n_global_particles()) / pure_pd_sites;
        const double spent = loop_time > 0 ? growth / loop_time : 0.;
        pcout << "Adaptive PD zone: " << pd_zone->n_global_particles() << " particles at the end, "
              << std::lround(100. * share) << " % of the " << pure_pd_sites
              << " lattice sites of the domain's box (pure PD); "
              << zone_growth->n_converted_cells() << " cells converted; growing the zone took "
              << std::lround(100. * spent) << " % of the time loop.";
        if (share > 0.5 && spent > 0.2)
          pcout << " With more than half of pure PD's particles and a fifth of the loop spent "
                   "growing, pure PD (Coupling/Method = none, Peridynamics/Region over the "
                   "domain) may be as fast on this case.";
        pcout << std::endl;
      }
    // Warnings scroll by in a long run: the largest is repeated where the run ends.
    if (warned_strain_ratio >= 1.)
      pcout << "FE strain: the largest the run warned about, " << warned_strain_ratio
            << " times the critical stretch at t = " << warned_strain_time << " s at ("
            << warned_strain_place
            << ") m. The FE zone cannot break: a crack PD would start there is missing from "
               "this answer. "
            << fe_strain_advice(zone_growth.get()) << std::endl;
    if (output_parameters.print_timing)
      timer.print_wall_time_statistics(communicator);
  }

  template <int dim>
  void
  Simulator<dim>::create_static_solver()
  {
    // Without a coupling (whose multiplier matrix is built for the time step) the relaxation
    // needs no accuracy in time: it steps at 0.9 of the estimated stable step.
    const double step     = coupling ? time_parameters.time_step :
                                       std::max(time_parameters.time_step, 0.9 * stable_time_step);
    std::string  obstacle = coupling ? coupling->conjugate_gradient_obstacle() : "";
    if (pd_zone && pd_zone->get_particle_contact())
      obstacle = "Peridynamics/Particle contact: contact forces switch on and off, they derive "
                 "from no quadratic energy";
    // The explicit loop holds the coupling's constraint on the velocities only: it keeps at
    // rest the relaxation's equilibrium, not the constrained one of conjugate gradients, from
    // which it would drift. A preload for it is therefore relaxed.
    const bool before_explicit_loop =
      coupling && time_parameters.integration == Parameters::Integration::static_then_explicit;
    static_solver = StaticSolver<dim>::create(static_parameters,
                                              zones,
                                              *integrator,
                                              step,
                                              obstacle,
                                              before_explicit_loop);
  }

  template <int dim>
  typename StaticSolver<dim>::Result
  Simulator<dim>::relax_to_equilibrium()
  {
    TimerOutput::Scope scope(timer, "static solve");
    // A checkpoint of a quasi-static run holds an equilibrium: it counts among those found,
    // with those its first part found.
    if (resumed && relaxation_steps == 0)
      static_solver->resume_equilibrium_force_scale(resumed->equilibrium_force_scale);
    if (pd_zone)
      pd_zone->suspend_fracture(true);
    Timer        clock;
    double       last_report = 0;
    const double interval    = output_parameters.progress_interval;
    const auto   result =
      static_solver->solve([&](const unsigned int iteration, const double residual) {
        // Rank 0's clock decides for all, as for the progress of the time loop.
        const double wall = Utilities::MPI::broadcast(communicator, clock.wall_time(), 0);
        if (interval > 0 && wall - last_report >= interval)
          {
            last_report = wall;
            pcout << "  static solve (" << static_solver->name() << "): iteration " << iteration
                  << ", |M a| / |F| = " << residual << ", wall " << std::fixed
                  << std::setprecision(1) << wall << " s" << std::defaultfloat
                  << std::setprecision(6) << std::endl;
          }
      });
    if (pd_zone)
      pd_zone->suspend_fracture(false);
    relaxation_steps += result.iterations + 1;
    return result;
  }

  template <int dim>
  typename StaticSolver<dim>::Result
  Simulator<dim>::solve_static()
  {
    if (!setup_done)
      setup();
    Timer clock;
    // The work that stores the strain energy: the trapezoid from the unloaded body is exact
    // for the linear response of intact bonds.
    integrator->start_work_interval(true);
    const auto result = relax_to_equilibrium();
    integrator->account_work();
    static_solved        = true;
    double strain_energy = 0;
    for (const IntegratedZone *zone : zones)
      strain_energy += zone->strain_energy();
    pcout << "  static solve: equilibrium after " << result.iterations << " iterations ("
          << static_solver->name() << ") of " << static_solver->get_time_step()
          << " s, |M a| / |F| = " << result.relative_residual << " (Static solve/Tolerance "
          << static_parameters.tolerance << "), strain energy " << strain_energy << " J, "
          << clock.wall_time() << " s" << std::endl;
    if (!static_parameters.released_cracks.empty())
      {
        AssertThrow(pd_zone,
                    ExcMessage("Invalid input: parameter 'Static solve/Released cracks' = '" +
                               static_parameters.released_cracks_text +
                               "'; allowed: empty without a PD zone (Peridynamics/Region), "
                               "since FE cells cannot break"));
        const std::size_t cut = pd_zone->cut_bonds(static_parameters.released_cracks,
                                                   "Static solve/Released cracks",
                                                   static_parameters.released_cracks_text);
        pcout << "  released cracks: " << cut << " bond ends cut" << std::endl;
      }
    return result;
  }

  template <int dim>
  void
  Simulator<dim>::check_static_equilibrium_exists()
  {
    bool supported = fe_zone && !fe_zone->get_prescribed_dofs().empty();
    if (pd_zone)
      for (unsigned int i = 0; i < pd_zone->n_owned_particles() && !supported; ++i)
        supported = pd_zone->is_prescribed(i);
    if (Utilities::MPI::logical_or(supported, communicator))
      return;
    // Without supports the loads must balance. From rest, one relaxation step without
    // damping gives each node dt/2 (a_0 + a_1): the momentum it makes is dt times the net
    // force (the internal forces add up to nothing), with no guess at the loads' functions.
    const double dt = time_parameters.time_step;
    integrator->relax(1., dt);
    Tensor<1, dim> momentum;
    if (fe_zone)
      momentum += fe_zone->linear_momentum();
    if (pd_zone)
      momentum += pd_zone->linear_momentum();
    double applied = 0;
    for (const IntegratedZone *zone : zones)
      applied += zone->squared_force_norms().second;
    const double net = momentum.norm() / dt;
    if (net > 1e-6 * std::sqrt(applied))
      {
        std::ostringstream allowed;
        allowed << "explicit for a body without supports whose loads do not balance (net force "
                << net << (dim == 2 ? " N/m" : " N")
                << "): it has no static equilibrium. Prescribe a "
                   "displacement somewhere (Boundary conditions, Peridynamics/Prescribed "
                   "region) or balance the loads";
        throw_invalid_parameter("Time/Integration",
                                selection_name(time_parameters.integration,
                                               Parameters::integration_names),
                                allowed.str());
      }
  }

  template <int dim>
  void
  Simulator<dim>::solve_increment()
  {
    // The first solve, for the loads of t = 0, starts from the unloaded body.
    integrator->start_work_interval(!quasi_static_started);
    // The first call solves for the loads of t = 0, the next ones for those of the clock's
    // next step.
    if (quasi_static_started)
      integrator->advance_clock();
    quasi_static_started    = true;
    unsigned int iterations = relax_to_equilibrium().iterations;
    unsigned int rounds     = 0;
    std::size_t  new_breaks = 0;
    if (pd_zone && pd_parameters.fracture)
      for (std::size_t broken = pd_zone->n_global_broken_bonds();; ++rounds)
        {
          // One more force evaluation at rest, with fracture on: the force pass breaks the
          // bonds beyond their limit in the equilibrium.
          static_solver->evaluate_at_rest();
          ++relaxation_steps;
          const std::size_t now = pd_zone->n_global_broken_bonds();
          if (now == broken)
            break;
          new_breaks += now - broken;
          broken = now;
          // A crack that runs in this increment grows the zone round by round, as a
          // dynamic one does step by step (its damage near an FE cell triggers a growth).
          if (zone_growth)
            grow_pd_zone();
          iterations += relax_to_equilibrium().iterations;
        }
    if (output_parameters.progress_interval > 0)
      pcout << "  increment " << get_step_number() << ", t = " << get_time() << " s: " << iterations
            << " static-solve iterations"
            << (rounds > 0 ? ", " + std::to_string(new_breaks) + " bond ends broke in " +
                               std::to_string(rounds) + " rounds" :
                             "")
            << std::endl;
    integrator->account_work();
  }

  template <int dim>
  void
  Simulator<dim>::advance()
  {
    try
      {
        if (time_parameters.integration == Parameters::Integration::quasi_static)
          solve_increment();
        else
          integrator->step();
        if (zone_growth)
          grow_pd_zone();
      }
    catch (const ExcDamageNearOverlap &stop)
      {
        if (!zone_growth)
          throw;
        AssertThrow(false, ExcDamageNearOverlap(stop.statement, adaptive_zone_advice()));
      }
    const unsigned int interval = coupling_parameters.strain_check_interval;
    if (interval > 0 && get_step_number() % interval == 0)
      check_fe_strain();
  }

  template <int dim>
  double
  Simulator<dim>::check_fe_strain()
  {
    if (!coupling || !pd_zone || !(pd_zone->get_critical_stretch() > 0))
      return 0.;
    const double            critical = pd_zone->get_critical_stretch();
    std::vector<Point<dim>> where;
    // At the cell centres: the mean strain of a cell, as a bond about a cell long sees it.
    const std::vector<double> strain = fe_zone->largest_principal_strains(QMidpoint<dim>(), &where);
    const auto                largest = std::max_element(strain.begin(), strain.end());
    const double              local =
      largest == strain.end() ? -std::numeric_limits<double>::infinity() : *largest;
    const double global = Utilities::MPI::max(local, communicator);
    const double ratio  = global / critical;
    if (ratio < 1. || ratio < 1.1 * warned_strain_ratio)
      return ratio;
    // The place from the lowest rank that holds the largest strain.
    const unsigned int rank =
      Utilities::MPI::min(local == global ? Utilities::MPI::this_mpi_process(communicator) :
                                            std::numeric_limits<unsigned int>::max(),
                          communicator);
    const Point<dim> place =
      Utilities::MPI::broadcast(communicator,
                                local == global ? where[largest - strain.begin()] : Point<dim>(),
                                rank);
    warned_strain_ratio = ratio;
    warned_strain_time  = get_time();
    warned_strain_place = place;
    pcout << "Warning: at t = " << get_time() << " s the FE field's strain reaches " << ratio
          << " times the critical stretch " << critical << " at (" << place
          << ") m. The FE zone cannot break: PD might crack there, this run cannot. "
          << fe_strain_advice(zone_growth.get()) << std::endl;
    return ratio;
  }

  template <int dim>
  unsigned int
  Simulator<dim>::grow_pd_zone()
  {
    TimerOutput::Scope            scope(timer, "PD zone growth");
    const std::vector<Point<dim>> new_damage = zone_growth->take_new_damage(*fe_zone, *pd_zone);
    if (new_damage.empty() && !zone_growth->due(get_step_number()))
      return 0;
    const unsigned int n_cells = zone_growth->grow(
      *fe_zone,
      *pd_zone,
      *blending,
      [this]() {
        rebuild_coupling();
        integrator->initialize();
      },
      timer,
      new_damage,
      get_time());
    if (n_cells == 0)
      return 0;
    if (output_parameters.progress_interval > 0)
      pcout << "  step " << get_step_number() << ": " << n_cells << " FE cells became PD"
            << (new_damage.empty() ? "" : " (damage near the overlap)") << "; now "
            << pd_zone->n_global_particles() << " particles, " << fe_zone->n_dofs() << " FE DoFs"
            << std::endl;
    rebalance(zone_growth->imbalance_tolerance());
    return n_cells;
  }

  template <int dim>
  std::string
  Simulator<dim>::adaptive_zone_advice() const
  {
    std::ostringstream advice;
    advice << "The adaptive zone grows ahead of running cracks (damage within "
           << zone_growth->trigger_distance()
           << " m of an FE cell converts the cells around it in the step it appears), so this "
              "damage started next to the overlap, not in a crack that ran into it.";
    if (warned_strain_ratio >= 1.)
      advice << " The FE field's strain reached " << warned_strain_ratio
             << " times the critical stretch at t = " << warned_strain_time << " s at ("
             << warned_strain_place
             << ") m: the FE zone cannot break, so the load that PD would relieve by cracking "
                "there stays in the body and can break bonds where the PD zone meets it.";
    // The start-up notes name settings that can cause this (new particles that do not
    // settle, a criterion that misses cracks away from damage).
    const std::vector<std::string> &notes = zone_growth->get_notes();
    for (const std::string &note : notes)
      advice << " Note: " << note;
    if (!zone_growth->uses_criterion("strain") && notes.empty())
      advice << " " << fe_strain_advice(zone_growth.get());
    else if (zone_growth->uses_criterion("strain"))
      advice << " " << fe_strain_advice(zone_growth.get())
             << " Or widen the band (Coupling/Overlap width).";
    return advice.str();
  }

  template <int dim>
  void
  Simulator<dim>::rebuild_coupling()
  {
    if (contact && fe_zone)
      contact->initialize(*fe_zone);
    if (coupling)
      coupling->initialize(*blending, *fe_zone, *pd_zone, time_parameters.time_step);
  }

  template <int dim>
  double
  Simulator<dim>::load_imbalance() const
  {
    AssertThrow(pd_zone, ExcMessage("The load of a rank is measured with PD cell weights."));
    std::uint64_t local = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        local += pd_zone->cell_load(cell);
    const std::uint64_t largest = Utilities::MPI::max(local, communicator);
    const std::uint64_t total   = Utilities::MPI::sum(local, communicator);
    return static_cast<double>(largest) * Utilities::MPI::n_mpi_processes(communicator) /
             static_cast<double>(total) -
           1.;
  }

  template <int dim>
  bool
  Simulator<dim>::rebalance(const double tolerance)
  {
    AssertThrow(pd_zone, ExcMessage("Simulator::rebalance() needs a PD zone."));
    if (Utilities::MPI::n_mpi_processes(communicator) == 1 || load_imbalance() <= tolerance)
      return false;
    repartition_zones();
    ++repartitions;
    return true;
  }

  template <int dim>
  void
  Simulator<dim>::repartition_zones()
  {
    TimerOutput::Scope scope(timer, "repartition");
    if (fe_zone)
      fe_zone->prepare_for_repartition();
    pd_zone->prepare_for_repartition();
    triangulation.repartition();
    if (fe_zone)
      fe_zone->unpack_after_repartition();
    pd_zone->unpack_after_repartition();
    // The state moved unchanged (with the accelerations the coupling corrected), so the
    // integrator is not initialized again.
    rebuild_coupling();
  }

  template <int dim>
  unsigned int
  Simulator<dim>::n_repartitions() const
  {
    return repartitions;
  }

  template <int dim>
  unsigned int
  Simulator<dim>::n_converted_cells() const
  {
    return zone_growth ? zone_growth->n_converted_cells() : 0;
  }

  template <int dim>
  double
  Simulator<dim>::conversion_energy_change() const
  {
    return zone_growth ? zone_growth->energy_change() : 0.;
  }

  template <int dim>
  unsigned int
  Simulator<dim>::get_step_number() const
  {
    return integrator->get_time().get_step_number();
  }

  template <int dim>
  FEZone<dim> &
  Simulator<dim>::get_fe_zone()
  {
    return *fe_zone;
  }

  template <int dim>
  const FEZone<dim> &
  Simulator<dim>::get_fe_zone() const
  {
    return *fe_zone;
  }

  template <int dim>
  Coupling<dim> *
  Simulator<dim>::get_coupling()
  {
    return coupling.get();
  }

  template <int dim>
  const Coupling<dim> *
  Simulator<dim>::get_coupling() const
  {
    return coupling.get();
  }

  template <int dim>
  bool
  Simulator<dim>::has_fe_zone() const
  {
    return fe_zone != nullptr;
  }

  template <int dim>
  const PDZone<dim> *
  Simulator<dim>::get_pd_zone() const
  {
    return pd_zone.get();
  }

  template <int dim>
  const Contact<dim> *
  Simulator<dim>::get_contact() const
  {
    return contact.get();
  }

  template <int dim>
  const Region<dim> &
  Simulator<dim>::get_monitor_region() const
  {
    return monitor_region;
  }

  template <int dim>
  unsigned int
  Simulator<dim>::get_n_steps() const
  {
    return n_steps;
  }

  template <int dim>
  const Parameters::Output &
  Simulator<dim>::get_output_parameters() const
  {
    return output_parameters;
  }

  template <int dim>
  PDZone<dim> *
  Simulator<dim>::get_pd_zone()
  {
    return pd_zone.get();
  }

  template <int dim>
  const ProblemData<dim> &
  Simulator<dim>::get_problem_data() const
  {
    return problem_data;
  }

  template <int dim>
  const EnergyHistory &
  Simulator<dim>::get_energy_history() const
  {
    return *energy_history;
  }

  template <int dim>
  const typename Simulator<dim>::VectorType &
  Simulator<dim>::get_displacement() const
  {
    return fe_zone->get_state().displacement;
  }

  template <int dim>
  const typename Simulator<dim>::VectorType &
  Simulator<dim>::get_velocity() const
  {
    return fe_zone->get_state().velocity;
  }

  template <int dim>
  const typename Simulator<dim>::VectorType &
  Simulator<dim>::get_acceleration() const
  {
    return fe_zone->get_state().acceleration;
  }

  template <int dim>
  double
  Simulator<dim>::get_time() const
  {
    return integrator->get_time().get_current_time();
  }

  template <int dim>
  double
  Simulator<dim>::get_time_step() const
  {
    return time_parameters.time_step;
  }

  template <int dim>
  MPI_Comm
  Simulator<dim>::get_communicator() const
  {
    return communicator;
  }

  template <int dim>
  double
  Simulator<dim>::clock_step() const
  {
    return time_parameters.integration == Parameters::Integration::quasi_static ?
             static_parameters.load_step :
             time_parameters.time_step;
  }

  template <int dim>
  double
  Simulator<dim>::get_stable_time_step() const
  {
    return stable_time_step;
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace PeriArlequin
