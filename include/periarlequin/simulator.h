#ifndef periarlequin_simulator_h
#define periarlequin_simulator_h

#include <periarlequin/adaptivity/pd_zone_growth.h>
#include <periarlequin/base/parameters.h>
#include <periarlequin/base/problem_data.h>
#include <periarlequin/coupling/blending_field.h>
#include <periarlequin/coupling/coupling.h>
#include <periarlequin/fe/fe_zone.h>
#include <periarlequin/io/checkpoint.h>
#include <periarlequin/io/energy_history.h>
#include <periarlequin/io/fe_output.h>
#include <periarlequin/io/line_samples.h>
#include <periarlequin/io/pd_output.h>
#include <periarlequin/pd/pd_zone.h>
#include <periarlequin/postprocess/postprocessor.h>
#include <periarlequin/time/predictor_corrector.h>
#include <periarlequin/time/static_solver.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <cstdint>
#include <memory>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * Runs one case described by a parameter file: builds the mesh and the zones (FE where no
   * PD region covers a cell's centre, PD particles in the PD region), checks the time step
   * against the stable steps of both, integrates in time with velocity Verlet and writes
   * fields, energies and progress. The zones own their state; PredictorCorrector steps them.
   * With Coupling/Method set, the zones overlap and are glued by that Coupling inside the
   * predictor-corrector step of eq. 58-69; otherwise a case is pure FE or pure PD, or has
   * independent FE and PD bodies.
   */
  namespace Parameters
  {
    /** The top level of a parameter file: the space dimension. */
    struct Run
    {
      unsigned int dimension = 2;

      void
      entries(ParameterEntries &entries);
    };

    /** Subsection "Postprocess": the postprocessors, by registered name. */
    template <int dim>
    struct Postprocess
    {
      std::string postprocessors = "energies, monitor region energies, constraint residuals";

      void
      entries(ParameterEntries &entries);
    };

    /** Subsection "Contact": the contact model, by registered name. */
    template <int dim>
    struct ContactModel
    {
      std::string model = "none";

      void
      entries(ParameterEntries &entries);
    };
  } // namespace Parameters

  template <int dim>
  class Simulator
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    /** Declare every parameter of a simulation in @p dim dimensions, documented. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Parse (and validate) a parameter handler filled by declare_parameters(). */
    Simulator(ParameterHandler &prm, const MPI_Comm communicator);
    ~Simulator();

    /**
     * Mesh, zones, DoFs, matrices, coupling, initial state and every check that needs them
     * (the PD region in the domain, the horizon covered by the ghost layer, the overlap, the
     * stable step). Writes no file: `periarlequin --check` runs it.
     */
    void
    setup();

    /** setup() if not done yet, then output files and the time loop to the end time. */
    void
    run();

    /**
     * The static equilibrium under the loads of the current time (dynamic relaxation, bonds
     * do not break), left at rest, then Static solve/Released cracks cut; run() calls it
     * first with Time/Integration = static then explicit. Prints the iterations and the
     * residual reached; throws if it does not converge.
     */
    typename StaticSolver<dim>::Result
    solve_static();

    /**
     * One step of the time integrator from the current state, then grow_pd_zone() and
     * check_fe_strain(). With Time/Integration = quasi-static, one load increment instead
     * (solve_increment()).
     */
    void
    advance();

    /**
     * Time/Integration = quasi-static: the clock on by Static solve/Load step (at the first
     * call, which run() makes, it stays at t = 0), the equilibrium under its loads, then rounds of
     * bond breaking (the bonds beyond their limit at equilibrium break together) each followed by a
     * new equilibrium, until a round breaks none.
     */
    void
    solve_increment();

    /**
     * With fracture in a coupled run, every Coupling/Strain check interval steps: the FE
     * field's largest principal strain at the cell centres over the critical stretch
     * (collective; 0 without a critical stretch). The FE zone cannot break: where the ratio
     * reaches 1, PD might crack where the run cannot, and rank 0 warns with the time and the
     * place (again when the ratio has grown by 10 %).
     */
    double
    check_fe_strain();

    /**
     * Between steps, with an adaptive PD zone: every Adaptive PD zone/Check interval steps,
     * and in every step that broke a bond near an FE cell, the FE cells that the conversion
     * criterion flags or that lie near the new damage become pure PD (PDZoneGrowth::grow());
     * the coupling is rebuilt and the accelerations recomputed. Then rebalance() with
     * Adaptive PD zone/Load imbalance tolerance. Returns the number of cells converted (over
     * all ranks).
     */
    unsigned int
    grow_pd_zone();

    /**
     * Repartition the cells with the weights of the initial partition when the most loaded
     * rank's load exceeds the mean by more than the fraction @p tolerance (grow_pd_zone()
     * asks with Adaptive PD zone/Load imbalance tolerance): particles with their state and
     * broken bonds, and the FE field, follow their cells; the coupling is rebuilt. The state
     * is unchanged, so the run goes on as without it, up to the order of sums. Returns
     * whether it repartitioned; on one rank it never does. Needs a PD zone.
     */
    bool
    rebalance(const double tolerance);
    /** Largest load of a rank over the mean load, minus one [-]. */
    double
    load_imbalance() const;
    /** Repartitions done by rebalance() since the start. */
    unsigned int
    n_repartitions() const;

    /**
     * Write a checkpoint of the current state (collective): the mesh with the FE field and
     * the particles with their state and broken bonds attached to its cells, and, from rank
     * 0, the clock, the PD region, the energy history, the .pvd records and the
     * postprocessors' states, into the slot of CheckpointSlots that the last checkpoint did
     * not use. run() calls it as the subsection Checkpoint says.
     */
    void
    write_checkpoint();

    /** Cells converted to PD since the start, over all ranks. */
    unsigned int
    n_converted_cells() const;
    /**
     * Sum over the conversions of the change of the total (kinetic plus strain) energy that
     * each caused [J]: the PD and classical energies of a state differ, so a conversion is not
     * energy-neutral.
     */
    double
    conversion_energy_change() const;

    /** The coupling, or nullptr for an uncoupled case. */
    Coupling<dim> *
    get_coupling();
    const Coupling<dim> *
    get_coupling() const;

    /** The communicator of the run. */
    MPI_Comm
    get_communicator() const;
    /** Does the case have FE cells? */
    bool
    has_fe_zone() const;
    /** The FE zone; only valid if has_fe_zone(). */
    FEZone<dim> &
    get_fe_zone();
    const FEZone<dim> &
    get_fe_zone() const;
    /** The PD zone, or nullptr if the case has none. */
    PDZone<dim> *
    get_pd_zone();
    const PDZone<dim> *
    get_pd_zone() const;
    /** The contact model (Contact/Model), or nullptr. */
    const Contact<dim> *
    get_contact() const;
    /** Where the pure-PD energies are measured (Output/Monitor region). */
    const Region<dim> &
    get_monitor_region() const;
    /** The number of steps taken. */
    unsigned int
    get_step_number() const;
    /** The number of steps of the run (Time/End time over Time/Time step). */
    unsigned int
    get_n_steps() const;
    const Parameters::Output &
    get_output_parameters() const;
    const ProblemData<dim> &
    get_problem_data() const;
    const EnergyHistory &
    get_energy_history() const;
    const VectorType &
    get_displacement() const;
    const VectorType &
    get_velocity() const;
    const VectorType &
    get_acceleration() const;
    double
    get_time() const;
    double
    get_time_step() const;
    double
    get_stable_time_step() const;

  private:
    /**
     * The static equilibrium under the loads of the current time, bonds unbroken, left at
     * rest (one StaticSolver kept for the run); progress lines on rank 0.
     */
    typename StaticSolver<dim>::Result
    relax_to_equilibrium();
    /**
     * The solver of Static solve/Method, at set-up: a method the case does not allow is
     * refused before anything runs.
     */
    void
    create_static_solver();
    /**
     * The step of the clock: Time/Time step, or Static solve/Load step for a quasi-static
     * run.
     */
    double
    clock_step() const;
    /**
     * With Time/Integration = static then explicit or quasi-static, at the end of setup(): refuse a
     * body without supports whose loads do not balance (a rigid motion that never settles). Such a
     * body is taken one relaxation step from rest to measure its net force.
     */
    void
    check_static_equilibrium_exists();
    // The stages of setup() (source/simulator/setup.cc).
    /**
     * The coarse mesh: the box of Geometry, or the Gmsh file of Geometry/Mesh file (then the
     * corners become its bounding box).
     */
    void
    make_coarse_mesh();
    /** BlendingField::check_against_mesh() with the cell size and points of this mesh. */
    void
    check_blending_against_mesh();
    /** The PD zone's object (no particles yet) and the cell weights of the partition. */
    void
    create_pd_zone();
    /** The FE zone's DoFs and matrices, with the blending weights of the coupling. */
    void
    setup_fe_zone();
    /** FE stable step, initial (or checkpointed) state, contact. */
    void
    initialize_fe_zone(const double dt);
    /** Particles, bonds and state (or the checkpoint's), coupling operators, stable step. */
    void
    initialize_pd_zone(const double dt);
    /** Refuse a time step above the estimated stable step. */
    void
    check_time_step() const;
    /** The zones in the integrator's order, the number of steps, the integrator. */
    void
    create_integrator();
    /** What the case is, on rank 0. */
    void
    print_summary() const;
    void
    print_pd_summary() const;

    // Resuming from a checkpoint (source/simulator/checkpoint.cc).
    /** read_checkpoint(), then the mesh and each cell's owner in the checkpointed run. */
    void
    load_checkpointed_mesh();
    /** The checkpoint's (grown) PD region. */
    void
    restore_pd_region();
    void
    restore_fe_state();
    /** The particles of the checkpoint and each rank's share of the external work. */
    void
    restore_pd_state(const double dt);
    /** The integrator at the checkpoint's step, the counters, the partition. */
    void
    resume_run();
    void
    print_resume_summary() const;

    /** Repartition with the cell weights: zones' state moved, coupling rebuilt. */
    void
    repartition_zones();
    /** After resuming on as many ranks as the checkpoint: the cells back to their owners. */
    void
    restore_saved_partition();
    /** After the zones or their partition changed: contact and coupling built again. */
    void
    rebuild_coupling();
    /**
     * What to change when damage reaches the overlap of an adaptive zone: its growth could
     * not act, and an FE strain past the critical stretch (check_fe_strain()) may be why.
     */
    std::string
    adaptive_zone_advice() const;
    /** Output directory, energy history file and FE output writer. */
    void
    prepare_output();
    /** A row of the history: step, time and the postprocessors' columns. */
    void
    record_statistics();
    /** Throw a clear error if the state (measured by an energy) is no longer finite. */
    void
    check_finite(const double energy) const;
    /** Kinetic energy of both zones. */
    double
    kinetic_energy() const;
    void
    write_output();
    /** Is a checkpoint due after this step (Checkpoint/Interval, Wall time interval)? */
    bool
    checkpoint_due();
    /**
     * Read, check and broadcast the newest checkpoint's record (Checkpoint/Resume); a clear
     * error for a corrupt one or one written with other parameters.
     */
    void
    read_checkpoint();
    /** After prepare_output() of a resumed run: history, .pvd records, postprocessors. */
    void
    restore_outputs();
    void
    report_progress(const bool force);

    const MPI_Comm     communicator;
    ConditionalOStream pcout;
    /** Local timings; statistics over ranks are gathered at the end of run(). */
    TimerOutput timer;

    Parameters::Geometry         geometry;
    Parameters::Material         material;
    Parameters::FiniteElements   fe_parameters;
    Parameters::Time             time_parameters;
    Parameters::StaticSolve<dim> static_parameters;
    /** Has the static solve of Time/Integration run? */
    bool static_solved = false;
    /** Relaxation steps of this run's static solves (each also evaluates the forces). */
    std::uint64_t relaxation_steps = 0;
    /** Has a quasi-static run solved for the loads of t = 0? */
    bool quasi_static_started = false;
    /** The solver of static and quasi-static equilibria (created at the first). */
    std::unique_ptr<StaticSolver<dim>> static_solver;
    Parameters::Output                 output_parameters;
    Parameters::Checkpoint             checkpoint_parameters;
    /** The parameters a checkpoint must agree with (checkpointed_parameters()). */
    std::vector<std::string> physics_parameters;
    /** What a checkpoint holds besides the cell data; set while resuming from one. */
    struct CheckpointRecord;
    std::unique_ptr<CheckpointRecord> resumed;
    std::string                       resume_directory;
    double                            last_checkpoint_wall_time = 0.;
    /** The largest FE strain ratio check_fe_strain() warned about, when and where. */
    double     warned_strain_ratio = 0.;
    double     warned_strain_time  = 0.;
    Point<dim> warned_strain_place;
    /** While resuming: each cell's owner in the checkpointed run (by active cell index). */
    std::vector<unsigned int> saved_owner;
    /** Cell weights that replace the PD ones while not empty (restore_saved_partition()). */
    std::vector<unsigned int>     partition_weights;
    Parameters::Peridynamics<dim> pd_parameters;
    Parameters::Coupling          coupling_parameters;
    ProblemData<dim>              problem_data;
    /** Where the pure-PD energies are measured. */
    Region<dim> monitor_region;
    /** Output/Sample line, or nullptr. */
    std::unique_ptr<LineSamples<dim>> line_samples;

    parallel::distributed::Triangulation<dim> triangulation;
    std::unique_ptr<FEZone<dim>>              fe_zone;
    std::unique_ptr<PDZone<dim>>              pd_zone;
    std::unique_ptr<BlendingField<dim>>       blending;
    std::unique_ptr<Coupling<dim>>            coupling;
    std::unique_ptr<FEOutput<dim>>            fe_output;
    std::unique_ptr<PDOutput<dim>>            pd_output;
    std::unique_ptr<PDMaterialModel<dim>>     pd_material;
    std::unique_ptr<FractureCriterion<dim>>   fracture_criterion;
    std::string                               contact_model;
    std::unique_ptr<Contact<dim>>             contact;
    /** The growth of an adaptive PD zone (nullptr: a fixed zone). */
    std::unique_ptr<PDZoneGrowth<dim>>               zone_growth;
    std::vector<std::unique_ptr<Postprocessor<dim>>> postprocessors;
    std::unique_ptr<EnergyHistory>                   energy_history;
    std::unique_ptr<PredictorCorrector<dim>>         integrator;
    /** The zones the case has, PD before FE (the order energies are summed in). */
    std::vector<IntegratedZone *> zones;

    unsigned int n_steps          = 0;
    unsigned int repartitions     = 0;
    double       stable_time_step = 0.;
    bool         setup_done       = false;
    Timer        wall_clock;
    double       last_progress_time = 0.;
    /** The step run() started from (0, or a checkpoint's step). */
    unsigned int first_step = 0;
  };
} // namespace PeriArlequin

#endif
