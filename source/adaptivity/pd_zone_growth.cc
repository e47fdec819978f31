#include <periarlequin/adaptivity/pd_zone_growth.h>
#include <periarlequin/base/gather.h>
#include <periarlequin/coupling/interpolation_operator.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <optional>
#include <sstream>
#include <utility>

namespace PeriArlequin
{
  namespace Parameters
  {
    template <int dim>
    void
    AdaptivePDZone<dim>::entries(ParameterEntries &entries)
    {
      entries.add("Conversion criterion",
                  conversion_criterion,
                  Patterns::MultipleSelection("none|" + ConversionCriterionRegistry<dim>::names()),
                  "Which FE cells become PD during the run: none (the PD zone is fixed) or a "
                  "comma-separated list of registered names, whose flags add up (a cell "
                  "converts if any criterion flags it):" +
                    ConversionCriterionRegistry<dim>::documentation() +
                    "\n'damage distance, strain' follows running cracks and catches those that "
                    "start away from damage (where the FE strain nears the critical stretch). "
                    "Needs a coupled case whose overlap is a band (Coupling/Overlap width). A "
                    "criterion's own parameters are in the subsection of its name.");
      entries.add("Check interval",
                  check_interval,
                  Patterns::Integer(1),
                  "Ask the criterion every this many steps. Damage near an FE cell grows "
                  "the zone in the step it appears whatever this is; with the damage distance "
                  "criterion, the automatic distance grows with it (fewer, larger growths) "
                  "[-].");
      entries.add("Load imbalance tolerance",
                  imbalance_tolerance,
                  Patterns::Double(0),
                  "After a conversion on several ranks, repartition the cells (with the "
                  "weights of the initial partition: particles times family size, plus a "
                  "share per cell) when the most loaded rank carries more than (1 + this) "
                  "times the mean load; particles, broken bonds and the FE field follow "
                  "their cells. 0: after every conversion [-].");
      entries.add("Settling time",
                  settling_time,
                  Patterns::Double(),
                  "New particles take the FE field, which is no PD equilibrium where the PD "
                  "state differs from the classical one (the surface layer of a free or a "
                  "loaded edge, a steep wave); switched to the PD forces at once, they would "
                  "overshoot, by enough to break bonds in a brittle material under a strong "
                  "wave. Instead, each new pure-PD particle carries the difference between "
                  "the FE and the PD acceleration as a force that fades out (half a cosine) "
                  "over this time, so it settles into the PD state smoothly. The forces add "
                  "up to zero (momentum is kept); their work counts as external work. 0 (the "
                  "default): automatic, ten times the time a longitudinal wave needs to cross "
                  "a horizon (several periods of the surface layer's vibration); negative: "
                  "none, the new particles take the PD forces at once [s].");
      entries.add("Lead distance",
                  lead_distance,
                  Patterns::Double(),
                  "A growth also converts the FE cells within this distance of the running "
                  "damage, the bonds broken since the previous growth: the running crack "
                  "tips (crack faces further behind lie deep in the PD zone). All running "
                  "tips take their lead in the same growth, so the tips of a branching crack "
                  "or of several cracks share growths, and they run for several check "
                  "intervals before the zone must grow again: fewer growths for a wider zone "
                  "around the crack paths. Cells within the overlap width of the boundary "
                  "are left to the damage. 0 (the default): automatic, twice the conversion "
                  "distance (trigger distance plus c_s dt Check interval); negative: no "
                  "lead, a growth converts the flagged cells only [m].");
    }
    template struct AdaptivePDZone<2>;
    template struct AdaptivePDZone<3>;
  } // namespace Parameters

  namespace
  {
    /** Sort @p points lexicographically and drop repeated ones. */
    template <int dim>
    void
    sort_and_unique(std::vector<Point<dim>> &points)
    {
      std::sort(points.begin(), points.end(), [](const Point<dim> &a, const Point<dim> &b) {
        for (unsigned int d = 0; d < dim; ++d)
          if (a[d] != b[d])
            return a[d] < b[d];
        return false;
      });
      points.erase(std::unique(points.begin(), points.end()), points.end());
    }
  } // namespace

  template <int dim>
  void
  PDZoneGrowth<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Adaptive PD zone");
    ParameterEntries::declare_here<Parameters::AdaptivePDZone<dim>>(prm);
    ConversionCriterionRegistry<dim>::declare_parameters(prm);
    prm.leave_subsection();
  }

  template <int dim>
  std::unique_ptr<PDZoneGrowth<dim>>
  PDZoneGrowth<dim>::create(ParameterHandler                    &prm,
                            const Parameters::Coupling          &coupling,
                            const Parameters::Peridynamics<dim> &pd_parameters)
  {
    prm.enter_subsection("Adaptive PD zone");
    Parameters::AdaptivePDZone<dim> parameters;
    ParameterEntries::parse_here(prm, parameters, "Adaptive PD zone/");
    std::unique_ptr<PDZoneGrowth<dim>> growth;
    const std::string                 &name  = parameters.conversion_criterion;
    const std::vector<std::string>     names = Utilities::split_string_list(name);
    if (names.size() > 1 && std::find(names.begin(), names.end(), "none") != names.end())
      throw_invalid_parameter("Adaptive PD zone/Conversion criterion",
                              name,
                              "none alone, or a list of registered criteria");
    if (name != "none")
      {
        if (!coupling.coupled() || !(coupling.overlap_width > 0))
          throw_invalid_parameter("Adaptive PD zone/Conversion criterion",
                                  name,
                                  "none, unless the zones are coupled (Coupling/Method) across "
                                  "a band that can move with the PD region (Coupling/Overlap "
                                  "width > 0)");
        std::vector<std::unique_ptr<ConversionCriterion<dim>>> criteria;
        for (const std::string &criterion : names)
          criteria.push_back(ConversionCriterionRegistry<dim>::create(criterion, prm));
        growth =
          std::make_unique<PDZoneGrowth<dim>>(parameters, std::move(criteria), pd_parameters);
      }
    prm.leave_subsection();
    return growth;
  }

  template <int dim>
  PDZoneGrowth<dim>::PDZoneGrowth(const Parameters::AdaptivePDZone<dim>                 &parameters,
                                  std::vector<std::unique_ptr<ConversionCriterion<dim>>> criteria,
                                  const Parameters::Peridynamics<dim> &parameters_of_pd)
    : parameters(parameters)
    , criteria(std::move(criteria))
    , particle_reach(parameters_of_pd.coupled_particle_reach())
  {}

  template <int dim>
  bool
  PDZoneGrowth<dim>::uses_criterion(const std::string &name) const
  {
    const std::vector<std::string> names =
      Utilities::split_string_list(parameters.conversion_criterion);
    return std::find(names.begin(), names.end(), name) != names.end();
  }

  template <int dim>
  double
  PDZoneGrowth<dim>::trigger_distance() const
  {
    return context.trigger_distance;
  }

  template <int dim>
  void
  PDZoneGrowth<dim>::initialize(const FEZone<dim>      &fe_zone,
                                PDZone<dim>            &pd_zone,
                                const ProblemData<dim> &data,
                                const double            time_step,
                                const bool              dynamic)
  {
    const auto                 &pd       = pd_zone.get_parameters();
    const Parameters::Material &material = fe_zone.get_material();
    context.time_step                    = time_step;
    context.check_interval               = parameters.check_interval;
    context.trigger_distance             = 2. * (pd.horizon() + 0.5 * pd.lattice_spacing) +
                               material.longitudinal_wave_speed(dim) * time_step;
    context.crack_speed_bound = material.shear_wave_speed();
    context.lead_distance     = parameters.lead_distance == 0 ? 2. * context.conversion_distance() :
                                                                std::max(parameters.lead_distance, 0.);
    // A horizon over the longitudinal wave speed: the time scale of the surface layer.
    const double horizon_time = pd.horizon() / material.longitudinal_wave_speed(dim);
    context.settling_time     = !dynamic                      ? 0. :
                                parameters.settling_time == 0 ? 10. * horizon_time :
                                                                std::max(parameters.settling_time, 0.);
    pd_zone.set_settling_time(context.settling_time);

    notes.clear();
    if (pd.fracture && Utilities::split_string_list(parameters.conversion_criterion) ==
                         std::vector<std::string>{"damage distance"})
      notes.emplace_back(
        "'damage distance' converts cells around damage only: a crack that starts away from "
        "it (at a far free edge under reflected tension, inside a struck region) happens in "
        "FE, where nothing breaks (the FE strain check warns where the FE strain reaches the "
        "critical stretch). 'Conversion criterion = damage distance, strain' also converts "
        "the cells whose strain nears the critical stretch.");
    if (dynamic && context.settling_time < 5. * horizon_time)
      {
        std::ostringstream note;
        note << "new particles that settle over less than five horizons over c_L ("
             << 5. * horizon_time
             << " s here; 0 when they do not settle) overshoot the PD state of free and "
                "loaded edges and of strong waves, by enough to break bonds in brittle "
                "materials (Adaptive PD zone/Settling time; 0 is the automatic "
             << 10. * horizon_time << " s).";
        notes.push_back(note.str());
      }
    for (unsigned int b = 0; b < ProblemData<dim>::n_boundaries; ++b)
      if (data.boundary_conditions[b].type != BoundaryType::free)
        context.loaded_boundaries.insert(b);
    for (const auto &criterion : criteria)
      criterion->initialize(fe_zone, pd_zone, context);

    boundary_vertices.clear();
    for (const auto &cell : fe_zone.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            for (const unsigned int v : face->vertex_indices())
              boundary_vertices.push_back(face->vertex(v));
    boundary_vertices = internal::gather_points(boundary_vertices, pd_zone.get_communicator());
    sort_and_unique(boundary_vertices);

    loaded_faces.clear();
    if (pd_zone.has_general_cells())
      {
        std::vector<Point<dim>> centres;
        std::vector<double>     radii;
        for (const auto &cell : fe_zone.get_dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary() && context.loaded_boundaries.count(face->boundary_id()))
                {
                  centres.push_back(face->center());
                  radii.push_back(0.5 * face->diameter());
                }
        const MPI_Comm communicator = pd_zone.get_communicator();
        centres                     = internal::gather_points(centres, communicator);
        radii                       = gather_values(radii, communicator);
        for (unsigned int f = 0; f < centres.size(); ++f)
          loaded_faces.emplace_back(centres[f], radii[f]);
        if (!loaded_faces.empty())
          {
            std::ostringstream note;
            note << "on a mesh file the PD zone carries no traction or displacement: the "
                    "cells within the overlap width and two bond reaches ("
                 << particle_reach
                 << " m) of a loaded boundary stay FE, and a crack that runs there stops "
                    "the run at the overlap.";
            notes.push_back(note.str());
          }
      }
  }

  template <int dim>
  const GrowthContext &
  PDZoneGrowth<dim>::get_context() const
  {
    return context;
  }

  template <int dim>
  const std::vector<std::string> &
  PDZoneGrowth<dim>::get_notes() const
  {
    return notes;
  }

  template <int dim>
  std::vector<Point<dim>>
  PDZoneGrowth<dim>::take_new_damage(const FEZone<dim> &fe_zone, const PDZone<dim> &pd_zone)
  {
    const MPI_Comm          communicator = pd_zone.get_communicator();
    std::vector<Point<dim>> damage       = pd_zone.new_damage_points();
    if (!Utilities::MPI::logical_or(!damage.empty(), communicator))
      return {};
    sort_and_unique(damage);
    if (context.lead_distance > 0)
      {
        running_damage.insert(running_damage.end(), damage.begin(), damage.end());
        // A tip particle breaks bonds in many steps: keep each position once.
        if (running_damage.size() > 2 * running_damage_compacted + 1024)
          {
            sort_and_unique(running_damage);
            running_damage_compacted = running_damage.size();
          }
      }
    damage = internal::gather_points(damage, communicator);
    std::vector<bool> near(fe_zone.get_dof_handler().get_triangulation().n_active_cells(), false);
    internal::mark_cells_near(fe_zone, damage, context.trigger_distance, near);
    const bool any = std::find(near.begin(), near.end(), true) != near.end();
    if (!Utilities::MPI::logical_or(any, communicator))
      return {};
    return damage;
  }

  template <int dim>
  bool
  PDZoneGrowth<dim>::due(const unsigned int step) const
  {
    return step % parameters.check_interval == 0;
  }

  template <int dim>
  Region<dim>
  PDZoneGrowth<dim>::flagged_cells(const FEZone<dim>      &fe_zone,
                                   const PDZone<dim>      &pd_zone,
                                   std::vector<Point<dim>> new_damage,
                                   const double            band_width) const
  {
    const auto       &triangulation = fe_zone.get_dof_handler().get_triangulation();
    std::vector<bool> convert(triangulation.n_active_cells(), false);
    for (const auto &criterion : criteria)
      criterion->mark_cells(fe_zone, pd_zone, convert);
    if (!new_damage.empty())
      internal::mark_cells_near(fe_zone, new_damage, context.conversion_distance(), convert);
    if (context.lead_distance > 0)
      add_lead(fe_zone, pd_zone, band_width, convert);
    // The cell's box nearer than the clearance to a face's centre less its half diameter:
    // a lower bound of the distance to the face, so no kept cell is too close.
    const double clearance = band_width + particle_reach;
    if (!loaded_faces.empty())
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() && convert[cell->active_cell_index()])
          {
            const auto     corners = cell->bounding_box().get_boundary_points();
            const Box<dim> box{corners.first, corners.second};
            for (const auto &[centre, radius] : loaded_faces)
              if (box.distance(centre) - radius < clearance)
                {
                  convert[cell->active_cell_index()] = false;
                  break;
                }
          }
    // Each converted cell as its vertices.
    std::vector<Point<dim>> local_vertices;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && convert[cell->active_cell_index()] &&
          !pd_zone.contains_cell(cell))
        for (const unsigned int v : cell->vertex_indices())
          local_vertices.push_back(cell->vertex(v));
    Region<dim>            flagged;
    constexpr unsigned int n = GeometryInfo<dim>::vertices_per_cell;
    for (const auto &vertices :
         Utilities::MPI::all_gather(pd_zone.get_communicator(), local_vertices))
      for (unsigned int k = 0; k < vertices.size(); k += n)
        if (pd_zone.has_general_cells())
          {
            CellShape<dim> cell;
            std::copy(vertices.begin() + k, vertices.begin() + k + n, cell.vertices.begin());
            flagged.cells.push_back(cell);
          }
        else
          flagged.boxes.push_back({vertices[k], vertices[k + n - 1]});
    return flagged;
  }

  template <int dim>
  void
  PDZoneGrowth<dim>::add_lead(const FEZone<dim> &fe_zone,
                              const PDZone<dim> &pd_zone,
                              const double       band_width,
                              std::vector<bool> &convert) const
  {
    const MPI_Comm communicator = pd_zone.get_communicator();
    bool           any          = false;
    for (const auto &cell : fe_zone.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && convert[cell->active_cell_index()] &&
          !pd_zone.contains_cell(cell))
        any = true;
    if (!Utilities::MPI::logical_or(any, communicator))
      return;
    // Every tip that ran since the previous growth takes its lead now, not only those that
    // asked for this growth: the tips of a branching crack, or of several cracks, then share
    // a growth instead of asking for one each. Crack faces that broke further behind the tips
    // lie deep in the PD zone, with no FE cell within the lead.
    std::vector<bool> lead(convert.size(), false);
    internal::mark_cells_near(fe_zone,
                              gather_running_damage(communicator),
                              context.lead_distance,
                              lead);
    // Cells within the band width of the boundary are left to the damage: in PD the surface
    // layer of a free or a loaded edge carries other strains than the continuum (the surface
    // effect), and a growth that no damage asks for should not put it in or next to the band.
    std::vector<bool> near_boundary(convert.size(), false);
    internal::mark_cells_near(fe_zone, boundary_vertices, band_width, near_boundary);
    for (const auto &cell : fe_zone.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && lead[cell->active_cell_index()] &&
          !near_boundary[cell->active_cell_index()])
        convert[cell->active_cell_index()] = true;
  }

  template <int dim>
  unsigned int
  PDZoneGrowth<dim>::grow(FEZone<dim>                   &fe_zone,
                          PDZone<dim>                   &pd_zone,
                          BlendingField<dim>            &blending,
                          const std::function<void()>   &rebuild_coupling,
                          TimerOutput                   &timer,
                          const std::vector<Point<dim>> &new_damage,
                          const double                   time)
  {
    Region<dim> flagged;
    {
      TimerOutput::Scope scope(timer, "growth: criteria");
      flagged = flagged_cells(fe_zone, pd_zone, new_damage, blending.overlap_width(Point<dim>()));
    }
    const unsigned int n_flagged = flagged.n_pieces();
    if (n_flagged == 0)
      return 0;
    const MPI_Comm communicator  = pd_zone.get_communicator();
    unsigned int   fe_cells_left = 0;
    for (const auto &cell : fe_zone.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0 &&
          !flagged.contains(cell->center()))
        ++fe_cells_left;
    if (Utilities::MPI::sum(fe_cells_left, communicator) == 0)
      {
        std::ostringstream message;
        message << "At t = " << time << " s the adaptive PD zone would take the last " << n_flagged
                << " FE cells: the PD zone has outgrown the FE zone, and a coupled run needs "
                   "an FE zone to couple to. This case needs PD everywhere: run it as pure PD "
                   "(Coupling/Method = none, Peridynamics/Region over the whole domain).";
        AssertThrow(false, ExcMessage(message.str()));
      }
    std::optional<TimerOutput::Scope> phase;
    phase.emplace(timer, "growth: PD zone");

    const auto total_energy = [&]() {
      return pd_zone.kinetic_energy() + fe_zone.kinetic_energy() + fe_zone.strain_energy() +
             pd_zone.strain_energy();
    };
    const double         energy_before   = total_energy();
    const Tensor<1, dim> momentum_before = fe_zone.linear_momentum() + pd_zone.linear_momentum();
    // The mass each particle carries itself (a slave's is lumped on the FE nodes).
    std::vector<double> mass_before(pd_zone.n_owned_particles());
    for (unsigned int i = 0; i < mass_before.size(); ++i)
      mass_before[i] = pd_zone.is_slave(i) ? 0. : pd_zone.particle_mass(i);
    blending.add_to_pd_region(flagged);
    pd_zone.set_region(blending.pd_region());
    // The particles of the grown zone (the reach of the set-up); the new ones take the FE
    // field, which still lives in the converted cells.
    // The extent grew within the band and the particle reach of the converted cells only.
    const double                    reach = blending.overlap_width(Point<dim>()) + particle_reach;
    const std::vector<Box<dim>>     flagged_bounds = flagged.piece_bounds();
    const std::vector<unsigned int> previous       = pd_zone.extend(
      [&](const Point<dim> &x) {
        return blending.distance_to_pd_part(x, 2. * particle_reach) <= particle_reach;
      },
      [&](const auto &cell) {
        const auto     corners = cell->bounding_box().get_boundary_points();
        const Box<dim> cell_box{corners.first, corners.second};
        for (const Box<dim> &bounds : flagged_bounds)
          if (cell_box.gap(bounds).norm() <= reach * (1. + 1e-12))
            return true;
        return false;
      });
    std::vector<unsigned int> added;
    for (unsigned int i = 0; i < previous.size(); ++i)
      if (previous[i] == numbers::invalid_unsigned_int)
        added.push_back(i);
    InterpolationOperator<dim> interpolation;
    interpolation.reinit(fe_zone, pd_zone, added);
    const auto &fe_state = fe_zone.get_state();
    for (const auto *field : {&fe_state.displacement, &fe_state.velocity, &fe_state.acceleration})
      field->update_ghost_values();
    for (unsigned int r = 0; r < added.size(); ++r)
      pd_zone.set_kinematics(added[r],
                             interpolation.interpolate(fe_state.displacement, r),
                             interpolation.interpolate(fe_state.velocity, r),
                             interpolation.interpolate(fe_state.acceleration, r));
    pd_zone.update_ghost_displacements();
    // The accelerations of the FE field (new particles) and of the state before (the others).
    const auto                        a = pd_zone.get_state().accelerations();
    const std::vector<Tensor<1, dim>> acceleration_before(a.begin(),
                                                          a.begin() + pd_zone.n_owned_particles());

    phase.emplace(timer, "growth: FE zone");
    fe_zone.restrict_to([&](const auto &cell) { return !pd_zone.contains_cell(cell); });
    phase.emplace(timer, "growth: coupling and accelerations");
    rebuild_coupling();
    phase.reset();

    // The lumped FE masses and the particle masses integrate the blending weight with
    // different quadratures, so the mass that left the FE nodes differs slightly from the
    // mass the particles gained: the free particles that gained mass take the momentum
    // difference, with one velocity increment.
    std::vector<unsigned int> gained;
    double                    gained_mass = 0;
    for (unsigned int i = 0; i < pd_zone.n_owned_particles(); ++i)
      if (!pd_zone.is_slave(i) && !pd_zone.is_prescribed(i))
        {
          const double m = pd_zone.particle_mass(i);
          if (previous[i] == numbers::invalid_unsigned_int || m > mass_before[previous[i]])
            {
              gained.push_back(i);
              gained_mass += m;
            }
        }
    gained_mass = Utilities::MPI::sum(gained_mass, communicator);
    if (gained_mass > 0)
      {
        const Tensor<1, dim> correction =
          (momentum_before - fe_zone.linear_momentum() - pd_zone.linear_momentum()) / gained_mass;
        for (const unsigned int i : gained)
          pd_zone.add_to_velocity(i, correction);
      }

    if (context.settling_time > 0)
      settle_new_particles(pd_zone, previous, acceleration_before, time);

    conversion_energy += total_energy() - energy_before;
    converted_cells += n_flagged;
    running_damage.clear();
    running_damage_compacted = 0;
    return n_flagged;
  }

  template <int dim>
  void
  PDZoneGrowth<dim>::settle_new_particles(PDZone<dim>                       &pd_zone,
                                          const std::vector<unsigned int>   &previous,
                                          const std::vector<Tensor<1, dim>> &acceleration_before,
                                          const double                       time) const
  {
    // The new pure-PD particles (a weighted one is held to the FE field by the coupling); the
    // force density that gives them back the acceleration of the FE field, without its
    // mass-weighted mean, so that the forces do not change the momentum.
    const auto                  a      = pd_zone.get_state().accelerations();
    const auto                  alpha  = pd_zone.blending_weights();
    const double                volume = pd_zone.particle_volume();
    std::vector<unsigned int>   settling;
    std::vector<Tensor<1, dim>> force;
    Tensor<1, dim>              total_force;
    double                      total_mass = 0;
    for (unsigned int i = 0; i < pd_zone.n_owned_particles(); ++i)
      if (previous[i] == numbers::invalid_unsigned_int && alpha[i] == 0 && !pd_zone.is_slave(i) &&
          !pd_zone.is_prescribed(i))
        {
          const double mass = pd_zone.particle_mass(i);
          settling.push_back(i);
          force.push_back((mass / volume) * (acceleration_before[i] - a[i]));
          total_force += volume * force.back();
          total_mass += mass;
        }
    const MPI_Comm communicator = pd_zone.get_communicator();
    total_mass                  = Utilities::MPI::sum(total_mass, communicator);
    if (total_mass == 0)
      return;
    const Tensor<1, dim> mean_acceleration =
      Utilities::MPI::sum(total_force, communicator) / total_mass;
    for (unsigned int s = 0; s < settling.size(); ++s)
      {
        const unsigned int i = settling[s];
        pd_zone.start_settling(i,
                               force[s] - (pd_zone.particle_mass(i) / volume) * mean_acceleration,
                               time);
      }
  }

  template <int dim>
  unsigned int
  PDZoneGrowth<dim>::n_converted_cells() const
  {
    return converted_cells;
  }

  template <int dim>
  double
  PDZoneGrowth<dim>::energy_change() const
  {
    return conversion_energy;
  }

  template <int dim>
  std::vector<Point<dim>>
  PDZoneGrowth<dim>::gather_running_damage(const MPI_Comm communicator) const
  {
    return internal::gather_points(running_damage, communicator);
  }

  template <int dim>
  void
  PDZoneGrowth<dim>::restore(const unsigned int             cells,
                             const double                   energy,
                             const std::vector<Point<dim>> &damage)
  {
    converted_cells          = cells;
    conversion_energy        = energy;
    running_damage           = damage;
    running_damage_compacted = running_damage.size();
  }

  template <int dim>
  double
  PDZoneGrowth<dim>::imbalance_tolerance() const
  {
    return parameters.imbalance_tolerance;
  }

  template class PDZoneGrowth<2>;
  template class PDZoneGrowth<3>;
} // namespace PeriArlequin
