#ifndef periarlequin_pd_pd_zone_h
#define periarlequin_pd_pd_zone_h

#include <periarlequin/base/parameters.h>
#include <periarlequin/base/problem_data.h>
#include <periarlequin/base/regions.h>
#include <periarlequin/pd/bond_families.h>
#include <periarlequin/pd/fracture_criterion.h>
#include <periarlequin/pd/ghost_exchange.h>
#include <periarlequin/pd/lattice.h>
#include <periarlequin/pd/material_model.h>
#include <periarlequin/pd/particle_contact.h>
#include <periarlequin/pd/particle_state.h>
#include <periarlequin/pd/pd_parameters.h>
#include <periarlequin/pd/prescribed_particles.h>
#include <periarlequin/time/integrated_zone.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/vector.h>
#include <deal.II/particles/particle_handler.h>

#include <array>
#include <functional>
#include <limits>
#include <memory>
#include <set>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  template <int dim>
  class Contact;

  /**
   * A bond next to the overlap broke (thrown on every rank). What happened (time and place)
   * is kept apart from what to do about it, so that a caller who knows more (an adaptive
   * zone: why its growth could not act) can give its own advice.
   */
  class ExcDamageNearOverlap : public ExceptionBase
  {
  public:
    ExcDamageNearOverlap(const std::string &statement, const std::string &advice)
      : statement(statement)
      , advice(advice)
    {}

    void
    print_info(std::ostream &out) const override
    {
      out << "    " << statement << ' ' << advice << std::endl;
    }

    /** What happened, when and where. */
    std::string statement;
    /** What to change. */
    std::string advice;
  };

  /**
   * The peridynamic particle zone: a regular lattice of spacing dx filling a union of boxes,
   * held in a Particles::ParticleHandler on the simulation's triangulation at the reference
   * positions (total Lagrangian: particles never move between cells). The owner of a
   * particle is the owner of its cell; ghost particles (one layer of ghost cells, so cells
   * must be at least a horizon wide) carry the displacements and model scalars of the
   * neighbours owned elsewhere.
   *
   * The zone puts together its parts: the Lattice (ids, positions, neighbours), the
   * GhostExchange (local numbering, owned particles first, then ghosts, and the ghost
   * updates), the ParticleState (kinematics), the BondFamilies (with pre-cracks and no-fail
   * regions), the material model and fracture criterion plugins and the
   * PrescribedParticles. Particle properties only carry data across ranks and to output.
   * extend() adds lattice sites between steps.
   *
   * Time integration is velocity Verlet, split as IntegratedZone says so that a coupled
   * integrator can interleave it with the FE zone.
   */
  template <int dim>
  class PDZone : public IntegratedZone
  {
  public:
    /** Which lattice sites hold a particle. */
    using SiteFilter = std::function<bool(const Point<dim> &)>;
    /** Selects cells by their iterator. */
    using CellFilter =
      std::function<bool(const typename Triangulation<dim>::active_cell_iterator &)>;
    /** The Arlequin blending weight alpha(x) (0: pure PD); evaluated on the threads. */
    using WeightFunction = std::function<double(const Point<dim> &)>;

    /**
     * A zone of the material @p model whose particles fill Peridynamics/Region, or, for a
     * coupled run, the sites that @p extent accepts (the PD region, the overlap and a layer
     * of slaves beyond it). Bonds break as @p fracture says (nullptr: never).
     */
    PDZone(parallel::distributed::Triangulation<dim> &triangulation,
           const Parameters::Peridynamics<dim>       &parameters,
           const Parameters::Material                &material,
           const Parameters::Geometry                &geometry,
           std::unique_ptr<PDMaterialModel<dim>>      model,
           std::unique_ptr<FractureCriterion<dim>>    fracture,
           const SiteFilter                          &extent = SiteFilter());

    /**
     * Arlequin weights, set before setup(): particle I has the mass (1 - alpha_I) rho V; its
     * strain energy enters with the weight 1 - alpha_I, inside the bond sums
     * (@p energy_blending: the forces are minus the derivative of the blended energy) or on
     * the node (the force (1 - alpha_I) f_I, eq. 55). Particles with 1 - alpha below
     * @p minimum_pd_weight are slaves: they complete the families of their neighbours and
     * follow the FE field, set by the coupling, which also carries their mass.
     */
    void
    set_blending(const WeightFunction &alpha,
                 const bool            energy_blending,
                 const double          minimum_pd_weight);

    /**
     * Weight of a cell for load balancing: 1000 (base) plus the bond count of the lattice
     * sites it will hold. Connect before any repartition.
     */
    unsigned int
    cell_weight(const typename Triangulation<dim>::cell_iterator &cell) const;

    /**
     * cell_weight() of a locally owned cell from the particles it holds now: what the load
     * of a rank is measured with, at the cost of a count per cell (no site search).
     */
    unsigned int
    cell_load(const typename Triangulation<dim>::active_cell_iterator &cell) const;

    /**
     * Is @p cell pure PD (no FE unknowns)? When the PD region holds its centre (on a mesh
     * file the region follows cell faces: check_region_follows_cells()).
     */
    bool
    contains_cell(const typename Triangulation<dim>::active_cell_iterator &cell) const;

    /**
     * The pure PD region becomes @p grown (an adaptive zone; Peridynamics/Region at the
     * start). Cells whose centre it contains are PD cells; call extend() for the particles.
     */
    void
    set_region(const Region<dim> &grown);

    /** The pure PD region now [m]. */
    const Region<dim> &
    get_region() const;

    /**
     * Are the cells general quadrilaterals or hexahedra (Geometry/Mesh file)? Then the cells
     * that join the region do so as cells, since boxes would not follow them.
     */
    bool
    has_general_cells() const;

    /**
     * Particles, ghosts, bonds, pre-cracks, model, initial state (without accelerations:
     * the integrator computes them once the coupling has set the slaves). @p data must
     * outlive the zone.
     */
    void
    setup(const ProblemData<dim> &data, const double time_step);

    std::string
    name() const override;
    /** u += dt v + dt^2/2 a,  v += dt/2 a (owned particles). */
    void
    predict(const double dt) override;
    /** Prescribed particles take their motion at @p time. */
    void
    impose_prescribed_motion(const double time) override;
    /** Bond breaking (fracture on), then the force densities of the current displacements. */
    void
    compute_forces(const double time) override;
    /** Accelerations of the free particles from the forces and the loads at @p time. */
    void
    compute_accelerations(const double time) override;
    /** v += dt/2 a, then the prescribed velocities of this step. */
    void
    correct(const double dt) override;
    /** Work of body forces and of the prescribed particles' reactions over the interval. */
    void
    account_work() override;
    void
    start_work_interval(const bool from_unloaded = false) override;

    /**
     * Internal force density of the current displacement (ghost exchange, model scalars,
     * forces) without breaking bonds; fills force_density and energy_density.
     */
    void
    compute_internal_forces();

    /** Stable step 2/sqrt(lambda_max) of the linearised PD operator (power iterations). */
    double
    estimate_stable_time_step(const unsigned int max_iterations);

    double
    kinetic_energy() const override;
    double
    strain_energy() const override;
    /** Sum of mass times velocity of the particles that carry their mass (not the slaves) [N s]. */
    Tensor<1, dim>
    linear_momentum() const;
    /** Kinetic and strain energy of the particles in @p region [J]. */
    std::pair<double, double>
    energies_in(const Region<dim> &region) const;
    /** Work of body forces and of the prescribed particles' reactions since the start. */
    double
    external_work() const override;
    void
    scale_velocities(const double factor) override;
    void
    start_relaxation_step() override;
    std::pair<double, double>
    relaxation_step_sums() const override;
    std::pair<double, double>
    squared_force_norms() const override;
    void
    take_projected_residual(const double dt) override;
    double
    squared_residual_norm() const override;
    void
    update_search_direction(const double beta) override;
    void
    move_along_search_direction(const double s) override;
    void
    extrapolate_relaxation_step(const double c) override;
    /**
     * Bonds do not break while @p suspended (a static solve under the loads of t = 0: the
     * equilibrium it seeks is that of the intact body).
     */
    void
    suspend_fracture(const bool suspended);
    /**
     * Break every intact bond that @p cracks cut (as Peridynamics/Pre-cracks would have at
     * the start), e.g. a crack released in a preloaded body; returns the bond ends cut on all
     * ranks (collective). The cut bonds count as new damage. @p parameter and @p value name
     * the cracks' parameter in the error raised if they cut a bond of the overlap or the
     * slave layer.
     */
    std::size_t
    cut_bonds(const std::vector<PreCrack<dim>> &cracks,
              const std::string                &parameter,
              const std::string                &value);
    types::particle_index
    n_global_particles() const;
    /** The sites of the lattice over the domain's box (the particles of pure PD there). */
    types::particle_index
    n_lattice_sites() const;
    /** Family sizes summed over all particles (each bond counted from both ends). */
    std::size_t
    n_global_bonds() const;
    /** Broken bonds counted from both ends. */
    std::size_t
    n_global_broken_bonds() const;
    /**
     * The reference positions of both ends of the bonds this rank broke in the last force
     * computation (a point may repeat): where damage is new, for the checks of an adaptive
     * zone. Over all ranks, the same points whatever the partition (a bond to a ghost,
     * broken on two ranks, gives its two ends on each).
     */
    const std::vector<Point<dim>> &
    new_damage_points() const;
    /** The fracture criterion's critical stretch (0 without fracture). */
    double
    get_critical_stretch() const;
    /** The contact between particles (Peridynamics/Particle contact), or nullptr if off. */
    const ParticleContact<dim> *
    get_particle_contact() const;
    /** Particles of all ranks that touched another in the last force evaluation. */
    unsigned int
    n_touching_particles() const;
    /**
     * Kinematic contact of the particles of the pure PD part (alpha = 0, neither slaves nor
     * prescribed) with the obstacle of @p model (one that acts on particles) after the trial
     * accelerations of every force evaluation; the present positions are checked against it
     * first (collective). nullptr: none. @p model must outlive its use here.
     */
    void
    set_obstacle(Contact<dim> *model);
    MPI_Comm
    get_communicator() const;
    const Parameters::Peridynamics<dim> &
    get_parameters() const;
    /** The box of the whole model (Geometry/Lower corner, Upper corner) [m]. */
    const Box<dim> &
    get_domain() const;

    /**
     * Copy displacement, velocity, damage and the model's particle scalars into the owned
     * particles' properties, for output; returns their names, component by component.
     */
    std::vector<std::string>
    store_output_properties();

    const Particles::ParticleHandler<dim> &
    get_particle_handler() const;

    /** Owned particles on this rank; their local numbers are [0, n). */
    unsigned int
    n_owned_particles() const;
    /** Reference positions, owned particles then ghosts [m]. */
    ArrayView<const Point<dim>>
    reference_positions() const;
    /** Particle ids (lattice site ids), owned particles then ghosts. */
    ArrayView<const types::particle_index>
    particle_ids() const;
    /** Displacements, velocities and accelerations, owned particles then ghosts. */
    const ParticleState<dim> &
    get_state() const;

    /**
     * @name What others may change of the particles' motion between the parts of a step
     * (owned particle @p i): the slaves follow the FE field, the multipliers correct the
     * overlap's velocities, the damping slows its fine-scale motion, an adaptive zone gives
     * new particles the FE field.
     */
    /** @{ */
    void
    set_displacement(const unsigned int i, const Tensor<1, dim> &displacement)
    {
      state.displacements()[i] = displacement;
    }
    void
    set_velocity_and_acceleration(const unsigned int    i,
                                  const Tensor<1, dim> &velocity,
                                  const Tensor<1, dim> &acceleration)
    {
      state.velocities()[i]    = velocity;
      state.accelerations()[i] = acceleration;
    }
    void
    set_kinematics(const unsigned int    i,
                   const Tensor<1, dim> &displacement,
                   const Tensor<1, dim> &velocity,
                   const Tensor<1, dim> &acceleration)
    {
      set_displacement(i, displacement);
      set_velocity_and_acceleration(i, velocity, acceleration);
    }
    /** v += @p velocity_change, a += @p acceleration_change. */
    void
    correct_motion(const unsigned int    i,
                   const Tensor<1, dim> &velocity_change,
                   const Tensor<1, dim> &acceleration_change)
    {
      state.velocities()[i] += velocity_change;
      state.accelerations()[i] += acceleration_change;
    }
    void
    add_to_velocity(const unsigned int i, const Tensor<1, dim> &velocity_change)
    {
      state.velocities()[i] += velocity_change;
    }
    void
    add_to_acceleration(const unsigned int i, const Tensor<1, dim> &acceleration_change)
    {
      state.accelerations()[i] += acceleration_change;
    }
    /** @} */
    /**
     * Let owned particle @p i settle into the PD state: from @p time on, a force density
     * @p force [N/m^dim] is added to its load and fades out with a half cosine over the
     * settling time (set_settling_time()). Its acceleration includes the force at once. An
     * adaptive zone gives it to new particles: they take the FE field, which is no PD
     * equilibrium where the PD state differs from the classical one (the surface layer of a
     * free or loaded edge), and a sudden change of force would make them overshoot. The
     * force's work counts as external work.
     */
    void
    start_settling(const unsigned int i, const Tensor<1, dim> &force, const double time);
    /** The time over which a settling force fades out [s]; 0 ends every settling. */
    void
    set_settling_time(const double duration);
    /**
     * Internal force density of the owned particles at the last force evaluation [N/m^dim];
     * 0 on particles of force weight 0 (slaves where alpha = 1 under force blending: their
     * force is not used, so not computed).
     */
    ArrayView<const Tensor<1, dim>>
    force_densities() const;
    /**
     * Strain energy density of the owned particles (blended if energy blending) [J/m^dim]; 0
     * where the force density is not computed.
     */
    ArrayView<const double>
    energy_densities() const;
    /**
     * The material model's particle scalars (PDMaterialModel::n_particle_scalars() per
     * particle, owned then ghosts) at the last force evaluation.
     */
    ArrayView<const double>
    particle_scalars() const;
    const PDMaterialModel<dim> &
    get_material_model() const;
    /** Blending weight alpha of owned and ghost particles. */
    ArrayView<const double>
    blending_weights() const;
    /** Does a prescribed region or a displacement boundary layer hold owned particle @p i? */
    bool
    is_prescribed(const unsigned int i) const;
    /**
     * Call @p visit(support, d, reaction, displacement) for every prescribed component d of
     * an owned particle: its support (PrescribedParticles::for_each_support_component()),
     * the support reaction of the last step and the displacement [N, m].
     */
    template <typename Visitor>
    void
    for_each_support_component(const Visitor &visit) const
    {
      const auto u = state.displacements();
      prescribed.for_each_support_component(
        [&](const unsigned int i, const unsigned int d, const unsigned int support) {
          visit(support, d, applied_force[i][d], u[i][d]);
        });
    }
    /** Is owned particle @p i a slave (1 - alpha below Coupling/Minimum PD weight)? */
    bool
    is_slave(const unsigned int i) const
    {
      return slave[i];
    }
    const BondFamilies<dim> &
    get_bonds() const;

    /**
     * The owned particles whose force densities the first evaluation after the last
     * extend() computed (the others kept theirs, see open_growth_window()); all owned
     * particles if it evaluated them all.
     */
    unsigned int
    n_evaluated_after_growth() const
    {
      return evaluated_after_growth;
    }

    /** Lattice cell volume dx^dim [m^dim]. */
    double
    particle_volume() const
    {
      return volume;
    }
    /** Mass of owned particle @p i, (1 - alpha_I) rho V [kg]. */
    double
    particle_mass(const unsigned int i) const
    {
      return material.density * volume * mass_weight[i];
    }
    /** Blended internal force on owned particle @p i [N] (a slave's feeds the FE nodes). */
    Tensor<1, dim>
    blended_force(const unsigned int i) const;
    /**
     * Load on owned particle @p i at @p time [N]: body force and boundary tractions (t / dx
     * on the particles within dx of a loaded face) times (1 - alpha_I) V. A slave's load is
     * carried by the FE nodes (SlaveLayer::add_loads()).
     */
    Tensor<1, dim>
    blended_load(const unsigned int i, const double time) const;

    /** Cell and unit-cell location of each owned particle, in local order. */
    std::vector<std::pair<typename Triangulation<dim>::active_cell_iterator, Point<dim>>>
    owned_particle_locations() const;

    /**
     * Multilinear interpolation weights of the lattice at @p x: the local indices (owned or
     * ghost) of the surrounding particles and their weights, renormalised over the sites that
     * hold a particle.
     */
    std::vector<std::pair<unsigned int, double>>
    lattice_interpolation(const Point<dim> &x) const;

    /** Copy a per-particle field of owned particles to the ghosts (see GhostExchange). */
    void
    update_ghosts(ArrayView<double> values, const unsigned int n_per_particle);
    /** Copy the owned displacements to the ghosts. */
    void
    update_ghost_displacements();

    /**
     * Add particles between steps at the lattice sites of locally owned cells that
     * @p grown_extent accepts and that hold none yet; the zone's extent becomes
     * @p grown_extent, which must accept every site that holds a particle (particles are
     * never removed). Existing particles keep their kinematics and their broken bonds; ghosts,
     * bonds (with pre-cracks and no-fail regions), model constants, blending weights and
     * prescribed particles are rebuilt as set-up builds them. Returns, for every owned
     * particle, its local number before (numbers::invalid_unsigned_int: a new particle, at
     * rest and undeformed, for the caller to set its state).
     * Only the cells that @p may_hold_new_sites accepts are searched for new sites (by
     * default all: a growth that knows where the extent grew costs what changed).
     * A repartition in between must have been completed by unpack_after_repartition().
     */
    std::vector<unsigned int>
    extend(const SiteFilter &grown_extent, const CellFilter &may_hold_new_sites = CellFilter());

    /**
     * Before Triangulation::repartition(): attach the particles and the state they carry
     * (displacement, velocity, acceleration, applied force and the ids of the particles at
     * the far end of their broken bonds) to their cells, to follow them to their new owners.
     */
    void
    prepare_for_repartition();
    /**
     * After Triangulation::repartition(): receive the particles and their state, and rebuild
     * ghosts, bonds, weights, model and prescribed particles as setup() builds them. The
     * particle set and every particle's state are those before the repartition.
     */
    void
    unpack_after_repartition();

    /** Before Triangulation::save(): attach the particles and their state to their cells. */
    void
    prepare_for_serialization();
    /**
     * Instead of setup(), after Triangulation::load() (and the FE zone's deserialize()): the
     * particles and their state from the checkpoint, with the region of the saved run
     * (set_region()), and what setup() builds.
     */
    void
    setup_from_checkpoint(const ProblemData<dim> &data, const double time_step);
    /** This rank's share of external_work(), and its restoration from a checkpoint [J]. */
    double
    local_external_work() const;
    void
    set_local_external_work(const double work_so_far);

  private:
    /** The weight of a cell holding @p n_particles particles (cell_weight(), cell_load()). */
    unsigned int
    weight_of_cell_with(const unsigned int n_particles) const;

    /**
     * The box whose lattice sites may belong to @p cell: the cell itself (half-open) for the
     * box mesh, its bounding box for a general mesh.
     */
    std::pair<Point<dim>, Point<dim>>
    cell_bounds(const typename Triangulation<dim>::cell_iterator &cell) const;
    /**
     * Does the site at @p x (found in cell_bounds()) belong to @p cell? Always for the box
     * mesh; for a general mesh, if the cell holds it and, for a site on its boundary, no cell
     * of smaller CellId around it does: each site in exactly one cell.
     */
    bool
    owns_site(const typename Triangulation<dim>::active_cell_iterator &cell,
              const Point<dim>                                        &x) const;
    /**
     * On a general mesh the PD zone takes no boundary layers: a clear error if a particle
     * that is not a slave lies within @p depth of a boundary with a traction or displacement.
     */
    void
    check_clear_of_loaded_boundaries(const double depth) const;
    /**
     * On a general mesh: a clear error if a cell lies across the boundary of the PD region
     * (its FE unknowns and the blending would disagree there).
     */
    void
    check_region_follows_cells() const;
    /** The least width of @p cell (between opposite faces) [m]. */
    double
    cell_width(const typename Triangulation<dim>::active_cell_iterator &cell) const;
    /** The problem data and time step kept, the particle handler on the mesh, empty. */
    void
    initialize_particle_handler(const ProblemData<dim> &data, const double time_step);
    /** Properties per particle in the particle handler (for output). */
    unsigned int
    n_particle_properties() const;
    /** The particles of @p cell and their state, packed for another rank or a file. */
    std::vector<char>
    pack_particle_state(const typename Triangulation<dim>::cell_iterator &cell) const;
    /** Register pack_particle_state() with the triangulation. */
    void
    attach_particle_state();
    /**
     * After the particle handler received its particles: their state from the data that
     * attach_particle_state() registered, then what setup() builds.
     */
    void
    receive_particle_state();
    /**
     * Insert a particle at every site of a locally owned cell (that @p cells accepts, if
     * given) that @p accept takes, given its position and lattice id.
     */
    void
    insert_particles(const std::function<bool(const Point<dim> &, types::particle_index)> &accept,
                     const CellFilter &cells = CellFilter());
    /** The particles held before a rebuild that inserts particles, as the bonds need them. */
    struct HeldBefore
    {
      /** Owned, then ghost particles. */
      std::vector<types::particle_index> ids;
      /** Whose bonds could not break (unbreakable_particles()). */
      std::vector<bool> no_fail;
      /** Blending weights. */
      std::vector<double> alpha;
    };
    /**
     * Local numbers, ghosts, bonds, weights, model and prescribed particles; the bonds between
     * the particle ids of a pair in @p broken start broken. With @p before (the zone grew),
     * the bond families that cannot have changed are kept.
     */
    void
    build_particle_structures(const typename BondFamilies<dim>::IdPairs &broken = {},
                              const HeldBefore                          *before = nullptr);
    /**
     * Per owned and ghost particle, whether its bonds cannot break: in the overlap and the slave
     * layer (the coupling assumes a continuum there), in Peridynamics/No-fail region, or in
     * a traction layer (Peridynamics/Unbreakable traction layer).
     */
    std::vector<bool>
    unbreakable_particles() const;
    void
    check_horizon_covered() const;
    /**
     * Before anything is filled: refuse a lattice whose ids do not fit the particle index
     * type, a horizon whose stencil is absurdly large, and a zone whose particles and bonds
     * would not fit the memory of the ranks' nodes (Lattice spacing, Horizon factor, Region
     * named with the counts and the memory). @p coupled: the zone reaches
     * Peridynamics::coupled_particle_reach() beyond its region.
     */
    void
    check_lattice_fits(const bool coupled) const;
    void
    compute_blending_weights();
    /**
     * The particles within one lattice spacing of a face with a traction, which carry it as
     * the force density t / dx, and the non-slave particles within two bond reaches
     * (2 delta + dx) of a face with a displacement condition, which follow it.
     */
    void
    find_boundary_layers();
    /**
     * The faces (bit b for boundary b) with a traction whose layer holds a particle at @p x:
     * the sites within dx of the lattice's face (none on a mesh file, where the PD zone
     * carries no boundary condition).
     */
    std::uint8_t
    traction_layers_at(const Point<dim> &x) const;
    /**
     * The intact bonds of the pure PD particles one bond away from the overlap or the slave
     * layer (whose own bonds cannot break); a pre-crack that cuts bonds there is an error.
     */
    void
    find_bonds_near_overlap();
    /**
     * Stop with a message naming @p time and the place if one of the bonds @p broken (those
     * that broke in this step) is near the overlap: the watched bonds were intact when they
     * were found, so only the new breaks need a look.
     */
    void
    check_damage_near_overlap(const double time, const std::vector<StoredBond> &broken) const;
    /** Body force plus boundary tractions per unit volume on owned particle @p i [N/m^dim]. */
    Tensor<1, dim>
    load_density(const unsigned int i, const double time) const;
    void
    set_initial_state();
    /** Model scalars (owned, then ghosts) of the current displacements. */
    void
    update_model_scalars();
    /**
     * Tell the bonds which pair forces are used, and list the owned particles whose force is
     * not (unforced), after the bonds were built.
     */
    void
    restrict_force_pass();
    /** Copy the owned particles' model scalars to the ghosts. */
    void
    share_model_scalars();
    /**
     * Model scalars (unless @p scalars_current: computed for these displacements and bond
     * states already) and forces of the current displacements.
     */
    void
    evaluate_model(const bool scalars_current = false);
    /**
     * After extend(): let the next evaluation compute the scalars and forces near the
     * particles that the growth changed only (the bonds' windows, see
     * StencilLayout::restrict_to_window()); the others keep the values extend() carried over,
     * which are those of a full evaluation: the same displacements, bonds, weights and sum
     * order. Not under particle contact (its forces are added to all particles) or a fracture
     * criterion other than the critical stretch (it tests every bond); collective.
     */
    void
    open_growth_window();
    /**
     * The particles that may touch the obstacle: those of the pure PD part within its reach
     * at the end of the step; with @p next, their positions then if nothing pushed them,
     * X + u + dt v + dt^2 a, else their present positions.
     */
    void
    find_obstacle_candidates(const bool next);
    /** The obstacle's pushes added to the trial accelerations. */
    void
    push_off_obstacle();

    parallel::distributed::Triangulation<dim> &triangulation;
    const Parameters::Peridynamics<dim>       &parameters;
    const Parameters::Material                 material;
    const MPI_Comm                             communicator;
    MappingQ<dim>                              mapping;
    /**
     * The mesh came from a file (Geometry/Mesh file): cells are general quadrilaterals or
     * hexahedra, a lattice site belongs to the cell that holds it (owns_site()), not to the
     * axis-aligned box of a cell.
     */
    bool general_cells;
    /** While particles are inserted into a general mesh: the cells around each vertex. */
    std::vector<std::set<typename Triangulation<dim>::active_cell_iterator>> vertex_to_cells;
    /** The particles the particle handler's storage was last reserved for. */
    std::size_t                             reserved_particles = 0;
    Particles::ParticleHandler<dim>         particle_handler;
    GhostExchange<dim>                      ghosts;
    ParticleState<dim>                      state;
    BondFamilies<dim>                       bonds;
    std::unique_ptr<PDMaterialModel<dim>>   model;
    std::unique_ptr<FractureCriterion<dim>> fracture;
    std::unique_ptr<ParticleContact<dim>>   contact;
    /** The obstacle of Contact/Model, if it acts on particles (set_obstacle()). */
    Contact<dim> *obstacle = nullptr;
    /**
     * Scratch of push_off_obstacle(): which particles lie in the obstacle's reach, the
     * candidates among them, their positions, masses and pushes.
     */
    std::vector<unsigned char>  obstacle_near;
    std::vector<unsigned int>   obstacle_candidates;
    std::vector<Point<dim>>     obstacle_positions;
    std::vector<double>         obstacle_masses;
    std::vector<Tensor<1, dim>> obstacle_pushes;
    PrescribedParticles<dim>    prescribed;
    SiteFilter                  extent;
    /** The pure PD region (Peridynamics/Region, grown by set_region()). */
    Region<dim>             region;
    Box<dim>                domain;
    WeightFunction          blending_weight;
    bool                    energy_blending = false;
    double                  minimum_weight  = 1.;
    const ProblemData<dim> *problem_data    = nullptr;
    Lattice<dim>            lattice;
    /** The lattice cell volume dx^dim [m^dim], asked for in loops over particles. */
    const double volume;
    double       time_step = 0;

    /** Model outputs of owned particles, and its particle scalars (owned and ghosts). */
    std::vector<Tensor<1, dim>> force_density;
    std::vector<double>         energy_density, model_scalars;
    /** Blending weight alpha and strain-energy weight inside the sums (owned and ghost);
     * nodal force weight, mass weight and slave flag (owned). */
    std::vector<double>        alpha, state_weight, force_weight, mass_weight;
    std::vector<unsigned char> slave;

    /**
     * Settling force density and its start time of the owned particles (empty while no
     * particle settles), see start_settling(), and the latest start: every force has faded
     * out a settling time after it.
     */
    std::vector<Tensor<1, dim>> settling_force;
    std::vector<double>         settling_start;
    double                      settling_time         = 0;
    double                      latest_settling_start = -std::numeric_limits<double>::infinity();
    /** Weight of the settling force of owned particle @p i at @p time (1 at its start). */
    double
    settling_weight(const unsigned int i, const double time) const;
    /**
     * (particle next to the overlap, stored bond index) of the bonds watched for damage, in
     * the order of their stored indices.
     */
    std::vector<std::pair<unsigned int, std::size_t>> bonds_near_overlap;
    bool                                              checks_overlap = false;
    /**
     * Owned particles of force weight 0: their force and energy densities are not computed
     * (the force pass skips their bonds where no other end needs them) and are set to 0.
     */
    std::vector<unsigned int> unforced;
    /** See new_damage_points(). */
    std::vector<Point<dim>> new_damage;
    /**
     * After extend() until the next evaluation or prediction (growth_window_pending): per
     * owned and ghost particle, whether the growth made it or changed its blending weight or
     * no-fail flag (open_growth_window()); unknown where a particle left the rank.
     */
    std::vector<bool> changed_by_growth;
    bool              growth_changes_known  = false;
    bool              growth_window_pending = false;
    /** See n_evaluated_after_growth(). */
    unsigned int evaluated_after_growth = 0;
    /** Handle of the particle state attached to the cells during a repartition. */
    unsigned int state_handle = numbers::invalid_unsigned_int;
    /**
     * Per owned particle, the ids of the other ends of its broken bonds, made when the state
     * is attached: a bond between two owned particles is stored at one end only, but both
     * ends may go to different ranks, and each needs to know it is broken.
     */
    std::vector<std::vector<types::particle_index>> broken_partners;
    /** Scratch of load_density(), called per particle and step: no allocation there. */
    mutable Vector<double> load_value = Vector<double>(dim);
    /** Of each owned particle, the faces whose traction it carries (bit b: boundary id b). */
    std::vector<std::uint8_t> traction_faces;
    /** Blended load densities of the loaded particles in this step [N/m^dim] (scratch). */
    std::vector<Tensor<1, dim>> load_values;
    /** Applied force (loads plus support reactions) of owned particles [N]. */
    std::vector<Tensor<1, dim>> applied_force, previous_applied_force, previous_displacement;
    /** Displacements and accelerations of the owned particles before a relaxation step. */
    std::vector<Tensor<1, dim>> relaxation_displacement, relaxation_acceleration;
    /** The search direction of a static solve by conjugate gradients, owned particles. */
    std::vector<Tensor<1, dim>> search_direction;
    double                      work        = 0;
    bool                        tracks_work = false;
    /** See suspend_fracture(). */
    bool fracture_suspended = false;
  };
} // namespace PeriArlequin

#endif
