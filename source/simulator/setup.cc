#include <periarlequin/simulator.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace PeriArlequin
{
  template <int dim>
  void
  Simulator<dim>::setup()
  {
    TimerOutput::Scope scope(timer, "setup");
    make_coarse_mesh();
    if (checkpoint_parameters.resume)
      load_checkpointed_mesh();
    else
      triangulation.refine_global(geometry.global_refinements);
    if (blending)
      check_blending_against_mesh();
    if (!pd_parameters.region.empty())
      create_pd_zone();
    bool has_fe_cells = false;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && !(pd_zone && pd_zone->contains_cell(cell)))
        has_fe_cells = true;
    if (Utilities::MPI::logical_or(has_fe_cells, communicator))
      setup_fe_zone();

    const double dt  = time_parameters.time_step;
    stable_time_step = std::numeric_limits<double>::max();
    if (fe_zone)
      initialize_fe_zone(dt);
    else if (contact && !contact->acts_on_particles())
      throw_invalid_parameter("Contact/Model",
                              contact_model,
                              "none, or a model that acts on PD particles (rigid projectile): "
                              "this one acts on FE boundary nodes and the case has no FE cells");
    if (pd_zone)
      initialize_pd_zone(dt);
    else if (contact && contact->needs_particles())
      throw_invalid_parameter("Contact/Model",
                              contact_model,
                              "a model of FE contact (rigid wall, elastic target, rigid "
                              "projectile): this one acts between PD particles and FE faces "
                              "and the case has no PD zone (Peridynamics/Region)");
    check_time_step();
    create_integrator();
    if (time_parameters.integration != Parameters::Integration::explicit_dynamics)
      {
        create_static_solver();
        if (!resumed)
          check_static_equilibrium_exists();
      }
    print_summary();
    setup_done = true;
  }

  template <int dim>
  void
  Simulator<dim>::create_pd_zone()
  {
    typename PDZone<dim>::SiteFilter extent;
    if (blending)
      {
        // Particles fill the PD region and the overlap, plus the slaves.
        const double reach = pd_parameters.coupled_particle_reach();
        extent             = [this, reach](const Point<dim> &x) {
          return blending->distance_to_pd_part(x, 2. * reach) <= reach;
        };
      }
    pd_zone = std::make_unique<PDZone<dim>>(triangulation,
                                            pd_parameters,
                                            material,
                                            geometry,
                                            std::move(pd_material),
                                            std::move(fracture_criterion),
                                            extent);
    if (blending)
      pd_zone->set_blending([this](const Point<dim> &x) { return blending->value(x); },
                            coupling_parameters.blending == Parameters::Blending::energy,
                            coupling_parameters.minimum_pd_weight);
    if (resumed)
      restore_pd_region();
    // Balance particles x family size (and FE cells) across ranks before DoFs exist (a
    // checkpoint keeps its partition, rebalanced by resume_run() on another number of ranks).
    triangulation.signals.weight.connect(
      [this](const typename Triangulation<dim>::cell_iterator &cell,
             const typename Triangulation<dim>::CellStatus) {
        return partition_weights.empty() ? pd_zone->cell_weight(cell) :
                                           partition_weights[cell->active_cell_index()];
      });
    if (!resumed)
      triangulation.repartition();
  }

  template <int dim>
  void
  Simulator<dim>::setup_fe_zone()
  {
    fe_zone = std::make_unique<FEZone<dim>>(triangulation, fe_parameters, material);
    // Integral blending weighs mass and stiffness with alpha; force blending weighs the
    // stiffness per node later; under a step profile the FE keeps its full mass and stiffness.
    using Parameters::Blending;
    const bool integral_mass = blending && coupling->blending_profile() == BlendingProfile::linear;
    const bool integral_stiffness =
      integral_mass && coupling_parameters.blending != Blending::force;
    const auto one   = [](const Point<dim> &) { return 1.; };
    const auto alpha = [this](const Point<dim> &x) { return blending->value(x); };
    using Weight     = typename FEZone<dim>::WeightFunction;
    fe_zone->setup(integral_mass ? Weight(alpha) : Weight(one),
                   integral_stiffness ? Weight(alpha) : Weight(one),
                   [this](const auto &cell) { return !(pd_zone && pd_zone->contains_cell(cell)); });
  }

  template <int dim>
  void
  Simulator<dim>::initialize_fe_zone(const double dt)
  {
    stable_time_step = fe_zone->estimate_stable_time_step(time_parameters.stability_iterations);
    fe_zone->initialize_state(problem_data, dt);
    if (resumed)
      restore_fe_state();
    if (contact)
      {
        contact->initialize(*fe_zone);
        fe_zone->set_contact(contact.get());
      }
  }

  template <int dim>
  void
  Simulator<dim>::initialize_pd_zone(const double dt)
  {
    if (resumed)
      restore_pd_state(dt);
    else
      pd_zone->setup(problem_data, dt);
    if (blending)
      coupling->initialize(*blending, *fe_zone, *pd_zone, dt);
    if (zone_growth)
      zone_growth->initialize(*fe_zone,
                              *pd_zone,
                              problem_data,
                              dt,
                              time_parameters.integration != Parameters::Integration::quasi_static);
    stable_time_step =
      std::min(stable_time_step,
               pd_zone->estimate_stable_time_step(time_parameters.stability_iterations));
    if (contact && contact->acts_on_particles())
      pd_zone->set_obstacle(contact.get());
  }

  template <int dim>
  void
  Simulator<dim>::check_time_step() const
  {
    const double dt = time_parameters.time_step;
    if (dt > stable_time_step)
      {
        std::ostringstream allowed;
        allowed << "a value <= the estimated stable step " << stable_time_step
                << " s (2/sqrt(lambda_max(M^-1 K)) of this discretisation and material)";
        throw_invalid_parameter("Time/Time step", dt, allowed.str());
      }
    const double damped_step =
      coupling ? coupling->stable_time_step(stable_time_step) : stable_time_step;
    if (dt > damped_step)
      {
        std::ostringstream allowed;
        allowed << "a value <= " << damped_step << " s, the estimated stable step "
                << stable_time_step
                << " s lowered by the fine-scale damping taken at the half-step velocity "
                   "(Coupling/Damping integration = half step): lower the time step or "
                   "Coupling/Damping constant, widen the overlap, or set Coupling/Damping "
                   "integration = implicit";
        throw_invalid_parameter("Time/Time step", dt, allowed.str());
      }
    if (contact)
      contact->check_time_step(dt);
  }

  template <int dim>
  void
  Simulator<dim>::create_integrator()
  {
    // The FE zone first: contact between PD particles and FE faces moves both sides when the
    // PD zone pushes its particles, once the FE accelerations are complete.
    if (fe_zone)
      zones.push_back(fe_zone.get());
    if (pd_zone)
      zones.push_back(pd_zone.get());
    // A moving obstacle (a projectile) steps with the zones, after those it touches.
    if (auto *moving_obstacle = dynamic_cast<IntegratedZone *>(contact.get()))
      zones.push_back(moving_obstacle);
    n_steps = static_cast<unsigned int>(std::ceil(time_parameters.end_time / clock_step() - 1e-9));
    integrator = std::make_unique<PredictorCorrector<dim>>(zones,
                                                           coupling.get(),
                                                           clock_step(),
                                                           n_steps,
                                                           timer);
    if (resumed)
      resume_run();
    else
      {
        // A static solve starts from the displacements of t = 0 as given: its bonds break
        // only in equilibrium.
        const bool hold_bonds =
          pd_zone && time_parameters.integration != Parameters::Integration::explicit_dynamics;
        if (hold_bonds)
          pd_zone->suspend_fracture(true);
        integrator->initialize();
        if (hold_bonds)
          pd_zone->suspend_fracture(false);
      }
  }

  template <int dim>
  void
  Simulator<dim>::print_summary() const
  {
    const double dt = time_parameters.time_step;
    pcout << "PeriArlequin " << dim << "D"
          << (dim == 2 ? (material.planar_model == Parameters::PlanarModel::plane_stress ?
                            " (plane stress)" :
                            " (plane strain)") :
                         "")
          << ": " << triangulation.n_global_active_cells() << " cells, "
          << (fe_zone ? fe_zone->n_dofs() : 0) << " FE DoFs, "
          << (pd_zone ? pd_zone->n_global_particles() : 0) << " PD particles ("
          << (pd_zone ? pd_zone->n_global_bonds() : 0) << " bonds) on "
          << Utilities::MPI::n_mpi_processes(communicator) << " rank(s) x "
          << MultithreadInfo::n_threads() << " thread(s)\n"
          << "  time step " << dt << " s";
    if (time_parameters.integration == Parameters::Integration::quasi_static)
      pcout << ", quasi-static: " << n_steps << " load increments of " << clock_step() << " s to "
            << time_parameters.end_time << " s";
    else
      pcout << " (" << n_steps << " steps to " << time_parameters.end_time << " s)";
    pcout << ", estimated stable step " << stable_time_step << " s, longitudinal wave speed "
          << material.longitudinal_wave_speed(dim) << " m/s" << std::endl;
    if (pd_zone)
      print_pd_summary();
    if (coupling)
      {
        const auto [n_overlap, n_slaves] = coupling->n_coupled_particles();
        pcout << "  Arlequin coupling: " << n_overlap << " PD nodes in the overlap, " << n_slaves
              << " slave particles, " << coupling->n_multipliers() << " multipliers" << std::endl;
        if (pd_parameters.fracture && coupling_parameters.blending != Parameters::Blending::force)
          pcout << "  Note: with fracture, prefer 'Coupling/Blending = force': the ghost forces "
                   "of the other blendings stretch the bonds next to the slaves up to twice "
                   "as far as the FE field does (tests/coupling/overlap_stretch)."
                << std::endl;
        if (static_solver && static_solver->name() == "relaxation")
          pcout << "  Note: the relaxation finds the rest state of the explicit loop, whose "
                   "multipliers hold the zones' velocities together, not their displacements: "
                   "the displacement mismatch in the band is left free. With 'Coupling/Blending "
                   "= energy' a plate under uniform tension then stretches 11 % (a 5 mm band) "
                   "to 20 % (10 mm) more than the continuum; force blending holds uniform "
                   "tension within 0.7 %, but its weighted nodal forces do not add up to zero "
                   "where the stress varies across the band: the supports of a coupled "
                   "cantilever in bending took 76-85 % of its load (postprocessor 'support "
                   "reactions'). Energy blending with 'Static solve/Method = conjugate "
                   "gradients' holds the displacements together: uniform tension within 0.3 % "
                   "(the state a quasi-static run takes by default; an explicit loop that "
                   "follows it does not stay at rest)."
                << std::endl;
      }
    if (resumed)
      print_resume_summary();
  }

  template <int dim>
  void
  Simulator<dim>::print_pd_summary() const
  {
    if (Utilities::MPI::n_mpi_processes(communicator) > 1)
      {
        // What a step's two ghost updates bring in: displacements and the model's scalars.
        const unsigned int n_ghosts =
          pd_zone->reference_positions().size() - pd_zone->n_owned_particles();
        const unsigned int values = dim + pd_zone->get_material_model().n_particle_scalars();
        pcout << "  PD ghost particles: " << Utilities::MPI::sum(n_ghosts, communicator)
              << " in all, at most " << Utilities::MPI::max(n_ghosts, communicator)
              << " on a rank (" << 8e-3 * values * Utilities::MPI::max(n_ghosts, communicator)
              << " kB received a step)" << std::endl;
      }
    const int uses_stencil = pd_zone->get_bonds().uses_stencil();
    pcout << "  PD force kernel: "
          << (Utilities::MPI::min(uses_stencil, communicator) ?
                "lattice stencil" :
              Utilities::MPI::max(uses_stencil, communicator) ?
                "lattice stencil on some ranks, bond lists on others" :
                "bond lists")
          << std::endl;
    {
      // Slaves whose force is not used (force weight 0) are skipped by the force pass.
      const auto [all, forced]    = uses_stencil ?
                                      pd_zone->get_bonds().stencil_layout().visited_slots() :
                                      std::pair<std::size_t, std::size_t>(0, 0);
      const double visited_all    = Utilities::MPI::sum(double(all), communicator),
                   visited_forced = Utilities::MPI::sum(double(forced), communicator);
      if (visited_forced < visited_all)
        pcout << "  PD force pass: " << 100. * (1. - visited_forced / visited_all)
              << " % of the bond slots skipped (their pair forces are not used)" << std::endl;
    }
    if (pd_parameters.fracture)
      {
        pcout << "  fracture criterion: " << pd_parameters.fracture_criterion;
        if (pd_zone->get_critical_stretch() > 0)
          pcout << ", critical stretch " << pd_zone->get_critical_stretch();
        pcout << std::endl;
      }
    if (zone_growth)
      {
        const GrowthContext &growth = zone_growth->get_context();
        pcout << "  adaptive PD zone: damage within " << growth.trigger_distance
              << " m of an FE cell grows it in the same step, converting the FE cells within "
              << growth.conversion_distance() << " m of the new damage (a crack at the shear "
              << "speed " << growth.crack_speed_bound << " m/s runs "
              << growth.crack_speed_bound * growth.time_step * growth.check_interval
              << " m between two checks); every growth also converts the FE cells "
              << "within " << growth.lead_distance
              << " m of the bonds broken since the previous one (the lead); new particles "
              << (growth.settling_time > 0 ? "settle over " : "do not settle");
        if (growth.settling_time > 0)
          pcout << growth.settling_time << " s";
        pcout << std::endl;
        for (const std::string &note : zone_growth->get_notes())
          pcout << "  Note: " << note << std::endl;
      }
  }

  template <int dim>
  void
  Simulator<dim>::make_coarse_mesh()
  {
    if (geometry.mesh_file.empty())
      {
        Point<dim>                p1, p2;
        std::vector<unsigned int> cells(dim);
        for (unsigned int d = 0; d < dim; ++d)
          {
            p1[d]    = geometry.lower_corner[d];
            p2[d]    = geometry.upper_corner[d];
            cells[d] = geometry.subdivisions[d];
          }
        GridGenerator::subdivided_hyper_rectangle(triangulation, cells, p1, p2, true);
        return;
      }

    std::ifstream file(geometry.mesh_file);
    if (!file)
      throw_invalid_parameter("Geometry/Mesh file",
                              geometry.mesh_file,
                              "a readable Gmsh .msh file (a relative path is read from the "
                              "parameter file's directory)");
    // Read into a serial triangulation first: p4est takes quadrilaterals and hexahedra only.
    Triangulation<dim> coarse;
    GridIn<dim>        grid_in(coarse);
    try
      {
        grid_in.read_msh(file);
      }
    catch (const std::exception &error)
      {
        throw_invalid_parameter("Geometry/Mesh file",
                                geometry.mesh_file,
                                std::string("a mesh that deal.II's GridIn::read_msh reads (Gmsh "
                                            "format 2 or 4, ASCII); reading it said: ") +
                                  error.what());
      }
    if (!coarse.all_reference_cells_are_hyper_cube())
      throw_invalid_parameter("Geometry/Mesh file",
                              geometry.mesh_file,
                              dim == 2 ? "a mesh of quadrilaterals (recombine the triangles in "
                                         "Gmsh: Recombine Surface)" :
                                         "a mesh of hexahedra");
    triangulation.copy_triangulation(coarse);
    // The PD lattice is anchored at the mesh's bounding box.
    const auto &vertices = triangulation.get_vertices();
    const auto &used     = triangulation.get_used_vertices();
    for (unsigned int d = 0; d < dim; ++d)
      {
        geometry.lower_corner[d] = std::numeric_limits<double>::max();
        geometry.upper_corner[d] = std::numeric_limits<double>::lowest();
      }
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (used[v])
        for (unsigned int d = 0; d < dim; ++d)
          {
            geometry.lower_corner[d] = std::min(geometry.lower_corner[d], vertices[v][d]);
            geometry.upper_corner[d] = std::max(geometry.upper_corner[d], vertices[v][d]);
          }
  }

  template <int dim>
  void
  Simulator<dim>::check_blending_against_mesh()
  {
    Tensor<1, dim>          cell_size;
    std::vector<Point<dim>> points;
    if (geometry.mesh_file.empty())
      {
        // The box: its cells' size and its half-cell grid of points.
        std::array<unsigned int, dim> n_cells;
        for (unsigned int d = 0; d < dim; ++d)
          {
            n_cells[d]   = geometry.subdivisions[d] << geometry.global_refinements;
            cell_size[d] = (geometry.upper_corner[d] - geometry.lower_corner[d]) / n_cells[d];
          }
        std::array<unsigned int, dim> index;
        const auto                    visit = [&](const auto &self, const unsigned int d) -> void {
          if (d == dim)
            {
              Point<dim> p;
              for (unsigned int e = 0; e < dim; ++e)
                p[e] = geometry.lower_corner[e] + 0.5 * index[e] * cell_size[e];
              points.push_back(p);
              return;
            }
          for (index[d] = 0; index[d] <= 2 * n_cells[d]; ++index[d])
            self(self, d + 1);
        };
        visit(visit, 0);
      }
    else
      {
        // A mesh file: the largest extent of the cells in each direction, over all ranks,
        // and the vertices and centres of this rank's cells.
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const BoundingBox<dim> box = cell->bounding_box();
              for (unsigned int d = 0; d < dim; ++d)
                cell_size[d] = std::max(cell_size[d], box.side_length(d));
              for (const unsigned int v : cell->vertex_indices())
                points.push_back(cell->vertex(v));
              points.push_back(cell->center());
            }
        for (unsigned int d = 0; d < dim; ++d)
          cell_size[d] = Utilities::MPI::max(cell_size[d], communicator);
      }
    blending->check_against_mesh(cell_size, points);
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace PeriArlequin
