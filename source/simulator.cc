#include <periarlequin/coupling/interpolation_operator.h>
#include <periarlequin/simulator.h>

#include <deal.II/base/function.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <cmath>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <iomanip>
#include <limits>
#include <sstream>
#include <unordered_map>

namespace PeriArlequin
{
  template <int dim>
  struct Simulator<dim>::CheckpointRecord
  {
    std::string              format    = "PeriArlequin checkpoint 1";
    unsigned int             dimension = dim;
    std::vector<std::string> parameters;
    unsigned int             n_ranks = 0;
    unsigned int             step    = 0;
    /** The pure PD region (grown by an adaptive zone). */
    Region<dim>              pd_region;
    unsigned int             converted_cells = 0, repartitions = 0;
    double                   conversion_energy = 0, fe_work = 0;
    /** Each rank's share of the PD zone's external work [J]. */
    std::vector<double>      pd_work;
    std::vector<std::string> history_names;
    std::vector<std::vector<double>>            history_rows;
    std::vector<std::pair<double, std::string>> fe_records, pd_records;
    std::vector<std::string>                    postprocessor_states;
    /** The other files of the checkpoint (the mesh and its cell data) and their checksums. */
    std::vector<std::pair<std::string, std::uint64_t>> files;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &format &dimension &parameters &n_ranks &step &pd_region &converted_cells
        &repartitions &conversion_energy &fe_work &pd_work &history_names &history_rows
          &fe_records &pd_records &postprocessor_states &files;
    }
  };

  template <int dim>
  Simulator<dim>::~Simulator() = default;

  template <int dim>
  void
  Simulator<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension of the run (2: plane stress or plane strain, 3).");
    Parameters::Geometry::declare_parameters(prm);
    Parameters::Material::declare_parameters(prm);
    Parameters::FiniteElements::declare_parameters(prm);
    Parameters::Time::declare_parameters(prm);
    Parameters::Output::declare_parameters(prm);
    Parameters::Checkpoint::declare_parameters(prm);
    Parameters::Peridynamics<dim>::declare_parameters(prm);
    Parameters::Coupling::declare_parameters(prm);
    ProblemData<dim>::declare_parameters(prm);
    prm.enter_subsection("Postprocess");
    prm.declare_entry("List of postprocessors",
                      "energies, monitor region energies, constraint residuals",
                      Patterns::MultipleSelection(PostprocessorRegistry<dim>::names()),
                      "Postprocessors that add columns to the energy history (CSV) at every "
                      "recorded step (Output/Energy interval), by registered name:" +
                        PostprocessorRegistry<dim>::documentation() +
                        "\nA postprocessor's own parameters are in the subsection of its "
                        "name.");
    PostprocessorRegistry<dim>::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Contact");
    prm.declare_entry("Model",
                      "none",
                      Patterns::Selection("none|" + ContactRegistry<dim>::names()),
                      "Contact of the FE boundary with an obstacle, by registered name (none: "
                      "no contact):" +
                        ContactRegistry<dim>::documentation() +
                        "\nA model's own parameters are in the subsection of its name.");
    ContactRegistry<dim>::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Adaptive PD zone");
    prm.declare_entry("Conversion criterion",
                      "none",
                      Patterns::Selection("none|" + ConversionCriterionRegistry<dim>::names()),
                      "Which FE cells become PD during the run, by registered name (none: the "
                      "PD zone is fixed):" +
                        ConversionCriterionRegistry<dim>::documentation() +
                        "\nNeeds a coupled case whose overlap is a band (Coupling/Overlap "
                        "width). A criterion's own parameters are in the subsection of its "
                        "name.");
    prm.declare_entry("Check interval",
                      "10",
                      Patterns::Integer(1),
                      "Ask the criterion every this many steps [-].");
    prm.declare_entry("Load imbalance tolerance",
                      "0.1",
                      Patterns::Double(0),
                      "After a conversion on several ranks, repartition the cells (with the "
                      "weights of the initial partition: particles times family size, plus a "
                      "share per cell) when the most loaded rank carries more than (1 + this) "
                      "times the mean load; particles, broken bonds and the FE field follow "
                      "their cells. 0: after every conversion [-].");
    ConversionCriterionRegistry<dim>::declare_parameters(prm);
    prm.leave_subsection();
  }

  template <int dim>
  Simulator<dim>::Simulator(ParameterHandler &prm, const MPI_Comm communicator)
    : communicator(communicator)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(communicator) == 0)
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    , triangulation(communicator)
  {
    AssertThrow(prm.get_integer("Dimension") == dim,
                ExcMessage("The parameters declare Dimension = " + prm.get("Dimension") +
                           " but are run by a " + std::to_string(dim) + "D simulator."));
    geometry.parse_parameters(prm, dim);
    material.parse_parameters(prm);
    fe_parameters.parse_parameters(prm);
    time_parameters.parse_parameters(prm);
    output_parameters.parse_parameters(prm);
    checkpoint_parameters.parse_parameters(prm);
    physics_parameters = checkpointed_parameters(prm);
    pd_parameters.parse_parameters(prm);
    coupling_parameters.parse_parameters(prm);
    problem_data.parse_parameters(prm);
    if (!pd_parameters.region.empty())
      {
        prm.enter_subsection("Peridynamics");
        pd_material = PDMaterialRegistry<dim>::create(pd_parameters.material_model, prm);
        if (pd_parameters.fracture)
          fracture_criterion =
            FractureCriterionRegistry<dim>::create(pd_parameters.fracture_criterion, prm);
        prm.leave_subsection();
      }
    prm.enter_subsection("Contact");
    contact_model = prm.get("Model");
    if (contact_model != "none")
      contact = ContactRegistry<dim>::create(contact_model, prm);
    prm.leave_subsection();
    prm.enter_subsection("Adaptive PD zone");
    const std::string conversion = prm.get("Conversion criterion");
    conversion_interval          = prm.get_integer("Check interval");
    imbalance_tolerance          = prm.get_double("Load imbalance tolerance");
    if (conversion != "none")
      {
        if (!coupling_parameters.coupled() || !(coupling_parameters.overlap_width > 0))
          throw_invalid_parameter("Adaptive PD zone/Conversion criterion",
                                  conversion,
                                  "none, unless the zones are coupled (Coupling/Method) across "
                                  "a band that can move with the PD region (Coupling/Overlap "
                                  "width > 0)");
        if (!geometry.mesh_file.empty())
          throw_invalid_parameter("Adaptive PD zone/Conversion criterion",
                                  conversion,
                                  "none with Geometry/Mesh file: converted cells join the PD "
                                  "region as boxes, which only the cells of the box mesh are");
        conversion_criterion = ConversionCriterionRegistry<dim>::create(conversion, prm);
      }
    prm.leave_subsection();
    prm.enter_subsection("Postprocess");
    for (const auto &name : Utilities::split_string_list(prm.get("List of postprocessors")))
      postprocessors.push_back(PostprocessorRegistry<dim>::create(name, prm));
    prm.leave_subsection();
    if (coupling_parameters.coupled())
      {
        // Quadratic shape functions integrate to zero against alpha next to the alpha = 0
        // edge, so the blended lumped masses of eq. 50 vanish there.
        if (fe_parameters.degree != 1)
          throw_invalid_parameter("Finite elements/Polynomial degree",
                                  fe_parameters.degree,
                                  "1 when the zones are coupled (Coupling/Method = " +
                                    coupling_parameters.method +
                                    "): the alpha-weighted lumped masses of higher degrees "
                                    "vanish at the edge of the overlap");
        prm.enter_subsection("Coupling");
        coupling =
          CouplingRegistry<dim>::create(coupling_parameters.method, prm, coupling_parameters);
        prm.leave_subsection();
        blending = std::make_unique<BlendingField<dim>>(coupling_parameters,
                                                        coupling->blending_profile(),
                                                        pd_parameters.region);
      }
    monitor_region = output_parameters.monitor_region.empty() ?
                       pd_parameters.region :
                       Region<dim>::parse(output_parameters.monitor_region,
                                          "Output/Monitor region");
    if (!output_parameters.sample_line.empty())
      {
        const auto [a, b] =
          parse_segment<dim>(output_parameters.sample_line, "Output/Sample line");
        line_samples = std::make_unique<LineSamples<dim>>(
          a, b, output_parameters, pd_parameters.lattice_spacing, communicator);
      }
  }

  template <int dim>
  void
  Simulator<dim>::setup()
  {
    TimerOutput::Scope scope(timer, "setup");
    make_coarse_mesh();
    if (checkpoint_parameters.resume)
      {
        read_checkpoint();
        triangulation.load(resume_directory + "mesh");
        // The owner of each cell in the checkpointed run (the first data attached).
        const unsigned int handle = triangulation.register_data_attach(
          [](const typename Triangulation<dim>::cell_iterator &,
             const typename Triangulation<dim>::CellStatus) {
            return std::vector<char>(sizeof(unsigned int));
          },
          /*returns_variable_size_data=*/false);
        saved_owner.assign(triangulation.n_active_cells(), 0);
        triangulation.notify_ready_to_unpack(
          handle,
          [this](const typename Triangulation<dim>::cell_iterator &cell,
                 const typename Triangulation<dim>::CellStatus,
                 const boost::iterator_range<std::vector<char>::const_iterator> &data) {
            saved_owner[cell->active_cell_index()] =
              Utilities::unpack<unsigned int>(data.begin(), data.end(), false);
          });
      }
    else
      triangulation.refine_global(geometry.global_refinements);
    if (blending)
      check_blending_against_mesh();

    if (!pd_parameters.region.empty())
      {
        typename PDZone<dim>::SiteFilter extent;
        if (blending)
          {
            // Particles fill the PD region and the overlap, plus the slaves: every site within
            // two bond reaches (delta + dx/2) of them, so that no weighted particle has a cut
            // family and neither has any of its neighbours, whose dilatation enters its force.
            const double reach =
              2. * (pd_parameters.horizon() + 0.5 * pd_parameters.lattice_spacing) * (1. + 1e-10);
            extent = [this, reach](const Point<dim> &x) {
              return blending->distance_to_pd_part(x) <= reach;
            };
          }
        pd_zone = std::make_unique<PDZone<dim>>(
          triangulation,
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
          {
            if (blending && blending->is_band())
              blending->set_pd_region(resumed->pd_region);
            pd_zone->set_region(resumed->pd_region);
          }
        // Balance particles x family size (and FE cells) across ranks before DoFs exist (a
        // checkpoint keeps its partition, rebalanced below on another number of ranks).
        triangulation.signals.weight.connect(
          [this](const typename Triangulation<dim>::cell_iterator &cell,
                 const typename Triangulation<dim>::CellStatus) {
            return partition_weights.empty() ? pd_zone->cell_weight(cell) :
                                               partition_weights[cell->active_cell_index()];
          });
        if (!resumed)
          triangulation.repartition();
      }
    bool has_fe_cells = false;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && !(pd_zone && pd_zone->contains_cell(cell)))
        has_fe_cells = true;
    if (Utilities::MPI::logical_or(has_fe_cells, communicator))
      setup_fe_zone();

    const double dt  = time_parameters.time_step;
    stable_time_step = std::numeric_limits<double>::max();
    if (fe_zone)
      {
        stable_time_step =
          fe_zone->estimate_stable_time_step(time_parameters.stability_iterations);
        fe_zone->initialize_state(problem_data, dt);
        if (resumed)
          {
            fe_zone->deserialize();
            fe_zone->set_external_work(resumed->fe_work);
          }
        if (contact)
          {
            contact->initialize(*fe_zone);
            fe_zone->set_contact(contact.get());
          }
      }
    else if (contact)
      throw_invalid_parameter("Contact/Model",
                              contact_model,
                              "none: contact acts on FE boundary nodes and this case has no "
                              "FE cells");
    if (pd_zone)
      {
        if (resumed)
          {
            pd_zone->setup_from_checkpoint(problem_data, dt);
            const unsigned int rank = Utilities::MPI::this_mpi_process(communicator);
            // On another number of ranks the work so far is rank 0's.
            const bool same_ranks =
              resumed->pd_work.size() == Utilities::MPI::n_mpi_processes(communicator);
            double share = 0;
            if (same_ranks)
              share = resumed->pd_work[rank];
            else if (rank == 0)
              for (const double w : resumed->pd_work)
                share += w;
            pd_zone->set_local_external_work(share);
          }
        else
          pd_zone->setup(problem_data, dt);
        if (blending)
          coupling->initialize(*blending, *fe_zone, *pd_zone, dt);
        if (conversion_criterion)
          conversion_criterion->initialize(*fe_zone, *pd_zone);
        stable_time_step =
          std::min(stable_time_step,
                   pd_zone->estimate_stable_time_step(time_parameters.stability_iterations));
      }
    if (dt > stable_time_step)
      {
        std::ostringstream allowed;
        allowed << "a value <= the estimated stable step " << stable_time_step
                << " s (2/sqrt(lambda_max(M^-1 K)) of this discretisation and material)";
        throw_invalid_parameter("Time/Time step", dt, allowed.str());
      }

    if (pd_zone)
      zones.push_back(pd_zone.get());
    if (fe_zone)
      zones.push_back(fe_zone.get());
    n_steps = static_cast<unsigned int>(
      std::ceil(time_parameters.end_time / time_parameters.time_step - 1e-9));
    integrator = std::make_unique<PredictorCorrector<dim>>(
      zones, coupling.get(), dt, n_steps, timer);
    if (resumed)
      {
        integrator->resume_at(resumed->step);
        converted_cells   = resumed->converted_cells;
        conversion_energy = resumed->conversion_energy;
        repartitions      = resumed->repartitions;
        // load() cut the cells evenly by count: on as many ranks as the checkpointed run,
        // its partition again (so the run goes on bit for bit), on another number, the
        // balance of the cell weights.
        if (pd_zone && resumed->n_ranks == Utilities::MPI::n_mpi_processes(communicator))
          restore_saved_partition();
        else if (pd_zone)
          rebalance(0.);
        saved_owner.clear();
      }
    else
      integrator->initialize();

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
          << "  time step " << dt << " s, estimated stable step " << stable_time_step
          << " s, longitudinal wave speed " << material.longitudinal_wave_speed(dim)
          << " m/s" << std::endl;
    if (pd_zone && Utilities::MPI::n_mpi_processes(communicator) > 1)
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
    if (pd_zone)
      pcout << "  PD force kernel: "
            << (Utilities::MPI::min(int(pd_zone->get_bonds().uses_stencil()), communicator) ?
                  "lattice stencil" :
                  Utilities::MPI::max(int(pd_zone->get_bonds().uses_stencil()), communicator) ?
                  "lattice stencil on some ranks, bond lists on others" :
                  "bond lists")
            << std::endl;
    if (pd_zone && pd_parameters.fracture)
      {
        pcout << "  fracture criterion: " << pd_parameters.fracture_criterion;
        if (pd_zone->get_critical_stretch() > 0)
          pcout << ", critical stretch " << pd_zone->get_critical_stretch();
        pcout << std::endl;
      }
    if (coupling)
      {
        const auto [n_overlap, n_slaves] = coupling->n_coupled_particles();
        pcout << "  Arlequin coupling: " << n_overlap << " PD nodes in the overlap, "
              << n_slaves << " slave particles, " << coupling->n_multipliers()
              << " multipliers" << std::endl;
        if (pd_parameters.fracture && coupling_parameters.blending != Parameters::Blending::force)
          pcout << "  Note: with fracture, prefer 'Coupling/Blending = force': the ghost forces "
                   "of the other blendings stretch the bonds next to the slaves up to twice "
                   "as far as the FE field does (tests/coupling/overlap_stretch)."
                << std::endl;
      }
    if (resumed)
      pcout << "  resumed from " << resume_directory << " at step " << resumed->step
            << ", t = " << integrator->get_time().get_current_time() << " s (written on "
            << resumed->n_ranks << " rank(s))" << std::endl;
    setup_done = true;
  }

  template <int dim>
  void
  Simulator<dim>::setup_fe_zone()
  {
    fe_zone = std::make_unique<FEZone<dim>>(triangulation, fe_parameters, material);
    // Integral blending weighs mass and stiffness with alpha; force blending weighs the
    // stiffness per node later; under a step profile the FE keeps its full mass and stiffness.
    using Parameters::Blending;
    const bool     integral_mass =
      blending && coupling->blending_profile() == BlendingProfile::linear;
    const bool     integral_stiffness =
      integral_mass && coupling_parameters.blending != Blending::force;
    const auto     one   = [](const Point<dim> &) { return 1.; };
    const auto     alpha = [this](const Point<dim> &x) { return blending->value(x); };
    using Weight = typename FEZone<dim>::WeightFunction;
    fe_zone->setup(integral_mass ? Weight(alpha) : Weight(one),
                   integral_stiffness ? Weight(alpha) : Weight(one),
                   [this](const auto &cell) { return !(pd_zone && pd_zone->contains_cell(cell)); });
  }

  template <int dim>
  void
  Simulator<dim>::advance()
  {
    integrator->step();
    if (conversion_criterion && get_step_number() % conversion_interval == 0)
      grow_pd_zone();
  }

  template <int dim>
  unsigned int
  Simulator<dim>::grow_pd_zone()
  {
    TimerOutput::Scope scope(timer, "PD zone growth");
    std::vector<bool>  convert(triangulation.n_active_cells(), false);
    conversion_criterion->mark_cells(*fe_zone, *pd_zone, convert);
    // Each converted cell as its lower and upper corner, gathered from all ranks.
    std::vector<Point<dim>> local_corners;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && convert[cell->active_cell_index()] &&
          !pd_zone->contains_cell(cell))
        {
          local_corners.push_back(cell->vertex(0));
          local_corners.push_back(cell->vertex(GeometryInfo<dim>::vertices_per_cell - 1));
        }
    std::vector<Box<dim>> boxes;
    for (const auto &corners : Utilities::MPI::all_gather(communicator, local_corners))
      for (unsigned int k = 0; k < corners.size(); k += 2)
        boxes.push_back({corners[k], corners[k + 1]});
    if (boxes.empty())
      return 0;

    const double energy_before = kinetic_energy() + fe_zone->strain_energy() +
                                 pd_zone->strain_energy();
    const Tensor<1, dim> momentum_before =
      fe_zone->linear_momentum() + pd_zone->linear_momentum();
    // The mass each particle carries itself (a slave's is lumped on the FE nodes), by id.
    std::unordered_map<types::particle_index, double> mass_before;
    for (unsigned int i = 0; i < pd_zone->n_owned_particles(); ++i)
      mass_before[pd_zone->particle_ids()[i]] =
        pd_zone->is_slave(i) ? 0. : pd_zone->particle_mass(i);
    blending->add_to_pd_region(boxes);
    pd_zone->set_region(blending->pd_region());
    // The particles of the grown zone (the reach of setup()); the new ones take the FE
    // field, which still lives in the converted cells.
    const double reach =
      2. * (pd_parameters.horizon() + 0.5 * pd_parameters.lattice_spacing) * (1. + 1e-10);
    const std::vector<unsigned int> added = pd_zone->extend(
      [this, reach](const Point<dim> &x) { return blending->distance_to_pd_part(x) <= reach; });
    InterpolationOperator<dim> interpolation;
    interpolation.reinit(*fe_zone, *pd_zone, added);
    auto &fe_state = fe_zone->get_state();
    auto &pd_state = pd_zone->get_state();
    for (const auto &[fe_field, pd_field] :
         {std::make_pair(&fe_state.displacement, pd_state.displacements()),
          std::make_pair(&fe_state.velocity, pd_state.velocities()),
          std::make_pair(&fe_state.acceleration, pd_state.accelerations())})
      {
        fe_field->update_ghost_values();
        for (unsigned int r = 0; r < added.size(); ++r)
          pd_field[added[r]] = interpolation.interpolate(*fe_field, r);
      }
    pd_zone->update_ghost_displacements();

    fe_zone->restrict_to(
      [this](const auto &cell) { return !pd_zone->contains_cell(cell); });
    rebuild_coupling();
    integrator->initialize();

    // The lumped FE masses and the particle masses integrate the blending weight with
    // different quadratures, so the mass that left the FE nodes differs slightly from the
    // mass the particles gained: the free particles that gained mass take the momentum
    // difference, with one velocity increment.
    std::vector<unsigned int> gained;
    double                    gained_mass = 0;
    const auto                ids         = pd_zone->particle_ids();
    for (unsigned int i = 0; i < pd_zone->n_owned_particles(); ++i)
      if (!pd_zone->is_slave(i) && !pd_zone->is_prescribed(i))
        {
          const auto   found = mass_before.find(ids[i]);
          const double m     = pd_zone->particle_mass(i);
          if (found == mass_before.end() || m > found->second)
            {
              gained.push_back(i);
              gained_mass += m;
            }
        }
    gained_mass = Utilities::MPI::sum(gained_mass, communicator);
    if (gained_mass > 0)
      {
        const Tensor<1, dim> correction =
          (momentum_before - fe_zone->linear_momentum() - pd_zone->linear_momentum()) /
          gained_mass;
        for (const unsigned int i : gained)
          pd_state.velocities()[i] += correction;
      }

    const double energy_after = kinetic_energy() + fe_zone->strain_energy() +
                                pd_zone->strain_energy();
    conversion_energy += energy_after - energy_before;
    converted_cells += boxes.size();
    if (output_parameters.progress_interval > 0)
      pcout << "  step " << get_step_number() << ": " << boxes.size()
            << " FE cells became PD; now " << pd_zone->n_global_particles() << " particles, "
            << fe_zone->n_dofs() << " FE DoFs" << std::endl;
    rebalance(imbalance_tolerance);
    return boxes.size();
  }

  template <int dim>
  void
  Simulator<dim>::rebuild_coupling()
  {
    if (contact)
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
        local += pd_zone->cell_weight(cell);
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
  void
  Simulator<dim>::restore_saved_partition()
  {
    // Cell weights under which p4est cuts the curve of cells exactly where the checkpointed
    // run owned them: each saved rank's cells weigh S in all (S = the largest saved count;
    // q = S / n per cell and one more for the first S mod n of them), so every cut falls on
    // a block boundary, whichever side of it p4est gives a cell on the cut.
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    std::vector<std::uint64_t> local_count(n_ranks, 0);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        ++local_count[saved_owner[cell->active_cell_index()]];
    std::vector<std::uint64_t> count(n_ranks, 0), before(n_ranks, 0);
    MPI_Allreduce(local_count.data(), count.data(), n_ranks, MPI_UINT64_T, MPI_SUM, communicator);
    MPI_Exscan(local_count.data(), before.data(), n_ranks, MPI_UINT64_T, MPI_SUM, communicator);
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      std::fill(before.begin(), before.end(), 0);
    const std::uint64_t block = *std::max_element(count.begin(), count.end());
    partition_weights.assign(triangulation.n_active_cells(), 0);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int owner = saved_owner[cell->active_cell_index()];
          partition_weights[cell->active_cell_index()] =
            block / count[owner] + (before[owner]++ < block % count[owner] ? 1 : 0);
        }
    repartition_zones();
    partition_weights.clear();
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
    return converted_cells;
  }

  template <int dim>
  double
  Simulator<dim>::conversion_energy_change() const
  {
    return conversion_energy;
  }

  template <int dim>
  unsigned int
  Simulator<dim>::get_step_number() const
  {
    return integrator->get_time().get_step_number();
  }

  template <int dim>
  void
  Simulator<dim>::prepare_output()
  {
    if (output_parameters.output_interval > 0 || output_parameters.energy_interval > 0)
      {
        if (Utilities::MPI::this_mpi_process(communicator) == 0)
          std::filesystem::create_directories(output_parameters.directory);
        MPI_Barrier(communicator);
      }
    energy_history = std::make_unique<EnergyHistory>(
      output_parameters.energy_interval > 0 ?
        output_parameters.directory + "/" + output_parameters.base_name + "_energy.csv" :
        std::string(),
      communicator);
    if (fe_zone)
      fe_output = std::make_unique<FEOutput<dim>>(*fe_zone, output_parameters);
    if (pd_zone)
      pd_output = std::make_unique<PDOutput<dim>>(*pd_zone, output_parameters);
  }

  template <int dim>
  void
  Simulator<dim>::record_statistics()
  {
    TimerOutput::Scope scope(timer, "energies");
    double             energy = 0;
    for (const IntegratedZone *zone : zones)
      energy += zone->kinetic_energy() + zone->strain_energy();
    check_finite(energy);
    energy_history->add_value("step", get_step_number());
    energy_history->add_value("time", get_time());
    for (const auto &postprocessor : postprocessors)
      postprocessor->execute(*this, *energy_history);
    energy_history->end_row();
  }

  template <int dim>
  void
  Simulator<dim>::check_finite(const double energy) const
  {
    if (std::isfinite(energy))
      return;
    std::ostringstream message;
    message << "The solution is not finite at step " << get_step_number() << " (t = " << get_time()
            << " s): an unstable time step, or initial data, loads or boundary values that "
               "evaluate to NaN or infinity.";
    AssertThrow(false, ExcMessage(message.str()));
  }

  template <int dim>
  double
  Simulator<dim>::kinetic_energy() const
  {
    double sum = 0;
    for (const IntegratedZone *zone : zones)
      sum += zone->kinetic_energy();
    return sum;
  }

  template <int dim>
  void
  Simulator<dim>::write_output()
  {
    TimerOutput::Scope scope(timer, "output");
    if (fe_output)
      fe_output->write(get_step_number(), get_time(), get_displacement(), get_velocity());
    if (pd_output)
      pd_output->write(get_step_number(), get_time());
    if (line_samples)
      line_samples->write(get_step_number(), fe_zone.get(), pd_zone.get());
  }

  template <int dim>
  void
  Simulator<dim>::report_progress(const bool force)
  {
    if (output_parameters.progress_interval <= 0)
      return;
    // The clocks of the ranks differ, and the finiteness check below is collective: rank 0's
    // clock decides for all.
    const double wall = Utilities::MPI::broadcast(communicator, wall_clock.wall_time(), 0);
    if (!force && wall - last_progress_time < output_parameters.progress_interval)
      return;
    last_progress_time = wall;
    // Energies may not be recorded: make sure the state is finite when progress is shown.
    check_finite(kinetic_energy());
    const unsigned int n = get_step_number();
    const double remaining = n > first_step ? wall * (n_steps - n) / (n - first_step) : 0.;
    pcout << "  step " << n << "/" << n_steps << ", t = " << std::setprecision(4)
          << std::scientific << get_time() << " s, wall " << std::fixed << std::setprecision(1)
          << wall << " s, about " << remaining << " s to go" << std::defaultfloat
          << std::setprecision(6) << std::endl;
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
        const auto visit = [&](const auto &self, const unsigned int d) -> void {
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

  template <int dim>
  bool
  Simulator<dim>::checkpoint_due()
  {
    const unsigned int interval = checkpoint_parameters.interval;
    if (interval > 0 && get_step_number() % interval == 0)
      return true;
    if (checkpoint_parameters.wall_time_interval > 0)
      {
        // Rank 0's clock decides, so that every rank writes.
        const double wall = Utilities::MPI::broadcast(communicator, wall_clock.wall_time(), 0);
        return wall - last_checkpoint_wall_time >= checkpoint_parameters.wall_time_interval;
      }
    return false;
  }

  template <int dim>
  void
  Simulator<dim>::write_checkpoint()
  {
    TimerOutput::Scope scope(timer, "checkpoint");
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      std::filesystem::create_directories(output_parameters.directory);
    CheckpointSlots    slots(output_parameters.directory, output_parameters.base_name, communicator);
    const std::string  slot = slots.begin_writing();
    const unsigned int rank = Utilities::MPI::this_mpi_process(communicator);
    triangulation.register_data_attach(
      [rank](const typename Triangulation<dim>::cell_iterator &,
             const typename Triangulation<dim>::CellStatus) {
        return Utilities::pack(rank, false);
      },
      /*returns_variable_size_data=*/false);
    if (fe_zone)
      fe_zone->prepare_for_serialization();
    if (pd_zone)
      pd_zone->prepare_for_serialization();
    triangulation.save(slot + "mesh");

    const std::vector<double> pd_work = Utilities::MPI::gather(
      communicator, pd_zone ? pd_zone->local_external_work() : 0., 0);
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        CheckpointRecord record;
        record.parameters = physics_parameters;
        record.n_ranks    = Utilities::MPI::n_mpi_processes(communicator);
        record.step       = get_step_number();
        if (pd_zone)
          record.pd_region = pd_zone->get_region();
        record.converted_cells   = converted_cells;
        record.repartitions      = repartitions;
        record.conversion_energy = conversion_energy;
        record.fe_work           = fe_zone ? fe_zone->external_work() : 0.;
        record.pd_work           = pd_work;
        if (energy_history)
          {
            record.history_names = energy_history->column_names();
            record.history_rows  = energy_history->rows();
          }
        if (fe_output)
          record.fe_records = fe_output->get_series().get_records();
        if (pd_output)
          record.pd_records = pd_output->get_series().get_records();
        for (const auto &postprocessor : postprocessors)
          record.postprocessor_states.push_back(postprocessor->save_state());
        record.files = file_checksums(slot, "state");

        std::ostringstream bytes;
        {
          boost::archive::binary_oarchive archive(bytes);
          archive << record;
        }
        const std::string payload = bytes.str();
        std::ofstream     file(slot + "state", std::ios::binary);
        const std::uint64_t header[2] = {payload.size(), checksum(payload)};
        file.write(reinterpret_cast<const char *>(header), sizeof(header));
        file.write(payload.data(), payload.size());
        file.flush();
        AssertThrow(file, ExcMessage("Cannot write the checkpoint record " + slot + "state"));
      }
    slots.commit();
    pcout << "  step " << get_step_number() << ": checkpoint written to " << slot << std::endl;
    last_checkpoint_wall_time = Utilities::MPI::broadcast(communicator, wall_clock.wall_time(), 0);
  }

  template <int dim>
  void
  Simulator<dim>::read_checkpoint()
  {
    const CheckpointSlots slots(output_parameters.directory,
                                output_parameters.base_name,
                                communicator);
    resume_directory = slots.newest();
    const std::string file_name = resume_directory + "state";
    const auto corrupt = [&](const std::string &what) {
      AssertThrow(false,
                  ExcMessage("Invalid input: parameter 'Checkpoint/Resume' = true, but the "
                             "checkpoint " + resume_directory + " is corrupt (" + what +
                             "); allowed: a checkpoint that a run wrote completely (delete "
                             "this slot and its pointer to start afresh)."));
    };
    std::string payload;
    bool        intact = false;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::ifstream file(file_name, std::ios::binary);
        std::uint64_t header[2] = {0, 0};
        if (file.read(reinterpret_cast<char *>(header), sizeof(header)) &&
            header[0] < (std::uint64_t(1) << 40))
          {
            payload.resize(header[0]);
            intact = file.read(payload.data(), payload.size()) && checksum(payload) == header[1];
          }
      }
    if (!Utilities::MPI::broadcast(communicator, intact, 0))
      corrupt("its record " + file_name + " is missing, truncated, or fails its checksum");
    payload = Utilities::MPI::broadcast(communicator, payload, 0);

    resumed = std::make_unique<CheckpointRecord>();
    const std::string format = resumed->format;
    try
      {
        std::istringstream              bytes(payload);
        boost::archive::binary_iarchive archive(bytes);
        archive >> *resumed;
      }
    catch (const std::exception &error)
      {
        corrupt(error.what());
      }
    if (resumed->format != format || resumed->dimension != dim)
      corrupt("written by another version or for another dimension");
    // The mesh and cell-data files, against the checksums the record took after writing them.
    std::string damaged_file;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        const auto found = file_checksums(resume_directory, "state");
        for (const auto &[name, sum] : resumed->files)
          {
            const auto here = std::find_if(found.begin(), found.end(), [&](const auto &f) {
              return f.first == name;
            });
            if (here == found.end() || here->second != sum)
              {
                damaged_file = name;
                break;
              }
          }
      }
    damaged_file = Utilities::MPI::broadcast(communicator, damaged_file, 0);
    if (!damaged_file.empty())
      corrupt("its file " + damaged_file + " is missing or fails its checksum");
    // The first parameter that differs, named with both values.
    const auto &saved = resumed->parameters;
    for (unsigned int k = 0; k < std::max(saved.size(), physics_parameters.size()); ++k)
      {
        const std::string was  = k < saved.size() ? saved[k] : "(absent)";
        const std::string here = k < physics_parameters.size() ? physics_parameters[k] : "(absent)";
        if (was != here)
          AssertThrow(false,
                      ExcMessage("Invalid input: parameter 'Checkpoint/Resume' = true, but "
                                 "the checkpoint in " + resume_directory +
                                 " was written with '" + was + "' where this run has '" +
                                 here + "'; allowed: the parameters of the checkpointed run "
                                 "(only the subsections Output and Checkpoint and Time/End "
                                 "time may change)."));
      }
    AssertThrow(static_cast<std::uint64_t>(resumed->step) * time_parameters.time_step <=
                  time_parameters.end_time * (1 + 1e-12),
                ExcMessage("Invalid input: parameter 'Time/End time' = " +
                           std::to_string(time_parameters.end_time) +
                           "; allowed: not before the checkpoint's step " +
                           std::to_string(resumed->step) + "."));
  }

  template <int dim>
  void
  Simulator<dim>::restore_outputs()
  {
    energy_history->restore(resumed->history_names, resumed->history_rows);
    if (fe_output)
      fe_output->get_series().restore(resumed->fe_records);
    if (pd_output)
      pd_output->get_series().restore(resumed->pd_records);
    AssertThrow(resumed->postprocessor_states.size() == postprocessors.size(),
                ExcMessage("The checkpoint holds another number of postprocessors."));
    for (unsigned int k = 0; k < postprocessors.size(); ++k)
      postprocessors[k]->load_state(resumed->postprocessor_states[k]);
  }

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
    const unsigned int steps_run = n_steps - first_step;
    pcout << "Time loop: " << steps_run << " steps in " << loop_time << " s";
    if (fe_zone)
      pcout << ", " << static_cast<double>(fe_zone->n_dofs()) * steps_run / loop_time
            << " FE DoF-steps/s";
    if (pd_zone)
      pcout << ", " << static_cast<double>(pd_zone->n_global_bonds()) * steps_run / loop_time
            << " PD bond-updates/s";
    pcout << std::endl;
    if (output_parameters.print_timing)
      timer.print_wall_time_statistics(communicator);
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
  double
  Simulator<dim>::get_stable_time_step() const
  {
    return stable_time_step;
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace PeriArlequin
