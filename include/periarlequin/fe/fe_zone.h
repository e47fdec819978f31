#ifndef periarlequin_fe_fe_zone_h
#define periarlequin_fe_fe_zone_h

#include <periarlequin/base/parameters.h>
#include <periarlequin/base/problem_data.h>
#include <periarlequin/base/separable_field.h>
#include <periarlequin/fe/contact.h>
#include <periarlequin/fe/mapping_without_similarity.h>
#include <periarlequin/fe/owned_rows_matrix.h>
#include <periarlequin/time/integrated_zone.h>

#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The classical (finite-element) zone: vector FE_Q displacements on the cells where the
   * continuum lives and FE_Nothing elsewhere (an hp DoFHandler, so a pure PD region carries no
   * FE unknowns), a lumped mass and the blended stiffness K_alpha = int alpha B^T D B, assembled
   * once because the material is linear. The zone owns the FE state (displacement, velocity,
   * acceleration) and steps it with velocity Verlet, split as IntegratedZone says so that the
   * coupling can act between the parts; boundary displacements are imposed here, and the work
   * of loads and support reactions is accounted here.
   */
  template <int dim>
  class FEZone : public IntegratedZone
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;
    using CellPredicate =
      std::function<bool(const typename Triangulation<dim>::active_cell_iterator &)>;

    /** A displacement component prescribed on a boundary, at a locally owned DoF. */
    struct PrescribedDoF
    {
      unsigned int local_index;
      unsigned int component;
      unsigned int boundary_id;
      Point<dim>   location;
      /** The boundary's function as a SeparableField (or nullptr), and its spatial value here. */
      const SeparableField<dim> *separable     = nullptr;
      double                     spatial_value = 0;
    };

    /** Nodal displacement, velocity and acceleration (owned and ghost DoFs). */
    struct State
    {
      VectorType displacement, velocity, acceleration;
    };

    FEZone(const parallel::distributed::Triangulation<dim> &triangulation,
           const Parameters::FiniteElements                &fe_parameters,
           const Parameters::Material                      &material);

    /** A weight field in space (the Arlequin alpha, or 1). */
    using WeightFunction = std::function<double(const Point<dim> &)>;

    /**
     * Distribute DoFs (FE_Q on cells where @p in_fe_zone holds, FE_Nothing on the others),
     * then assemble the lumped mass int alpha rho N_I (and the body force) with the
     * @p mass_weight and the stiffness int alpha B^T D B with the @p stiffness_weight (both
     * alpha(x) for integral blending, 1 for a pure FE problem). The weight functions must
     * outlive the zone.
     */
    void
    setup(const WeightFunction &mass_weight,
          const WeightFunction &stiffness_weight,
          const CellPredicate  &in_fe_zone);

    /**
     * Between steps, turn the FE cells that @p in_fe_zone no longer accepts into FE_Nothing
     * (an adaptive PD zone took them; a cell never returns to FE): DoFs are distributed
     * again, mass and stiffness assembled with the weight functions of setup() (whose values
     * may have changed), and the displacement, velocity, acceleration and applied force keep
     * their values at the remaining nodes, as a solution transfer across the hp change does
     * for nodal elements. The prescribed DoFs are found again and the work done so far is
     * kept. Nodal force weights and contact must be set again by their owners.
     */
    void
    restrict_to(const CellPredicate &in_fe_zone);

    /**
     * Before Triangulation::repartition(): attach the displacement, velocity, acceleration and
     * applied force to their cells (a solution transfer), to follow them to their new owners.
     */
    void
    prepare_for_repartition();
    /**
     * After Triangulation::repartition(): DoFs, mass and stiffness on the new partition and
     * the state received; as after restrict_to(), nodal force weights and contact must
     * be set again by their owners.
     */
    void
    unpack_after_repartition();

    /** Before Triangulation::save(): attach the state vectors of prepare_for_repartition(). */
    void
    prepare_for_serialization();
    /**
     * After Triangulation::load() and setup() (with the FE cells of the saved run) and
     * initialize_state(): the state vectors from the checkpoint.
     */
    void
    deserialize();
    /** Restore the work done so far (from a checkpoint) [J]. */
    void
    set_external_work(const double work_so_far);

    /**
     * Initial displacement and velocity from the problem's initial data at t = 0, and the
     * prescribed boundary DoFs (their motion by central differences over @p time_step).
     * @p data must outlive the zone. Call after setup().
     */
    void
    initialize_state(const ProblemData<dim> &data, const double time_step);

    std::string
    name() const override;
    void
    predict(const double dt) override;
    void
    impose_prescribed_motion(const double time) override;
    /**
     * F_int = K_alpha u, weighted per node when nodal force weights are set (force
     * blending), and F_ext (body force, tractions) at @p time; F_interface set to zero.
     */
    void
    compute_forces(const double time) override;
    /**
     * What a coupling adds to between compute_forces() and compute_accelerations(): the
     * interface forces F_interface (energy blending: the PD slaves' forces N^T f) ...
     */
    VectorType &
    interface_forces();
    /** ... and the applied forces F_ext (the slaves' loads: they count in the work). */
    VectorType &
    applied_forces();
    /** The applied forces of the last step: at a prescribed DoF, the support reaction. */
    const VectorType &
    applied_forces() const;
    /**
     * a = M^-1 (F_ext - F_int + F_interface), then contact, then the prescribed DoFs (their
     * applied force takes the support reaction).
     */
    void
    compute_accelerations(const double time) override;
    void
    correct(const double dt) override;
    void
    account_work() override;
    void
    start_work_interval(const bool from_unloaded = false) override;
    double
    kinetic_energy() const override;
    /** 1/2 u . F_int of the last computed forces. */
    double
    strain_energy() const override;
    /** Sum of lumped mass times nodal velocity [N s] (a coupling's lumped slave masses too). */
    Tensor<1, dim>
    linear_momentum() const;
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

    const State &
    get_state() const;

    /**
     * @name What others may change of the nodes' motion between the parts of a step (locally
     * owned DoF @p i, local index): the bad coupling's FE slaves follow the PD lattice, the
     * multipliers correct the overlap's velocities.
     */
    /** @{ */
    void
    set_displacement(const unsigned int i, const double displacement)
    {
      state.displacement.local_element(i) = displacement;
    }
    void
    set_velocity_and_acceleration(const unsigned int i,
                                  const double       velocity,
                                  const double       acceleration)
    {
      state.velocity.local_element(i)     = velocity;
      state.acceleration.local_element(i) = acceleration;
    }
    /** v += @p velocity_change, a += @p acceleration_change. */
    void
    correct_motion(const unsigned int i,
                   const double       velocity_change,
                   const double       acceleration_change)
    {
      state.velocity.local_element(i) += velocity_change;
      state.acceleration.local_element(i) += acceleration_change;
    }
    /** @} */
    /** The locally owned DoFs whose displacement is prescribed. */
    const std::vector<PrescribedDoF> &
    get_prescribed_dofs() const;

    /** Force blending: F_int,I is multiplied by @p weights[I] (owned DoFs, local order). */
    void
    set_nodal_force_weights(const std::vector<double> &weights);

    /**
     * Contact forces from @p contact (nullptr: none) at every force evaluation, after the
     * trial accelerations; they count as applied force in the work. @p contact must outlive
     * the zone.
     */
    void
    set_contact(Contact<dim> *contact);

    /** The locally owned DoFs (local indices), their support points and components. */
    void
    support_points(std::vector<unsigned int> &local_dofs,
                   std::vector<Point<dim>>   &points,
                   std::vector<unsigned int> &components) const;

    /** A locally owned cell with FE DoFs and the unit coordinates of a point in it. */
    using PointLocation = std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>;

    /**
     * Where @p point lies if a locally owned cell with FE DoFs holds it (within 1e-10 in
     * unit coordinates), else nothing.
     */
    std::optional<PointLocation>
    locate(const Point<dim> &point) const;

    /** The vector field @p ghosted (with up-to-date ghost entries) at @p location. */
    Tensor<1, dim>
    point_value(const VectorType &ghosted, const PointLocation &location) const;

    /** Shape a vector with the locally owned and ghost DoFs of this zone. */
    void
    initialize_vector(VectorType &vector) const;

    /**
     * Shape a matrix with the coupling pattern of the FE DoFs (entries between DoFs of a
     * common cell), zero, writable in the rows of locally relevant DoFs.
     */
    void
    reinit_matrix(TrilinosWrappers::SparseMatrix &matrix) const;

    /** Internal force K_alpha u (owned entries). */
    void
    compute_internal_force(const VectorType &displacement, VectorType &force) const;

    /** External force at time @p time: alpha-weighted body force plus boundary tractions. */
    void
    compute_external_force(const ProblemData<dim> &data,
                           const double            time,
                           VectorType             &force) const;

    /** Nodal interpolation of a dim-component function. */
    void
    interpolate(const Function<dim> &function, VectorType &vector) const;

    /** The locally owned DoFs whose displacement is prescribed by a boundary condition. */
    std::vector<PrescribedDoF>
    prescribed_dofs(const ProblemData<dim> &data) const;
    /** prescribed and is_prescribed_dof from the boundary conditions of @p data. */
    void
    find_prescribed_dofs(const ProblemData<dim> &data);

    /**
     * Largest stable step of the explicit central-difference/velocity-Verlet scheme,
     * 2 / sqrt(lambda_max(M^-1 K_alpha)), with lambda_max from at most @p max_iterations power
     * iterations on the symmetric M^-1/2 K M^-1/2 (stopped at a relative change of 1e-6).
     * The start vector depends on DoF positions only, so the estimate is independent of the
     * partition.
     */
    double
    estimate_stable_time_step(const unsigned int max_iterations) const;

    const DoFHandler<dim> &
    get_dof_handler() const;
    const VectorType &
    lumped_mass() const;
    /** Add @p extra to the lumped mass (a coupling lumps masses that move with the nodes). */
    void
    add_lumped_mass(const VectorType &extra);
    const Parameters::Material &
    get_material() const;
    types::global_dof_index
    n_dofs() const;

    /**
     * The largest principal strain of the displacement field in each locally owned cell with
     * FE unknowns (index: active cell index; -infinity elsewhere): the largest over the
     * @p points of the cell (a quadrature's points on the reference cell), each the stretch
     * of the worst-aligned bond the field would impose (small strain). If @p where is given,
     * it receives the point of each maximum.
     */
    std::vector<double>
    largest_principal_strains(const Quadrature<dim>   &points,
                              std::vector<Point<dim>> *where = nullptr) const;

  private:
    /** FE indices from fe_cells, DoFs, matrix and vector layouts, mass and stiffness. */
    void
    distribute_and_assemble();
    /** The vectors a change of the FE cells or of their owners keeps. */
    std::vector<VectorType *>
    carried_vectors();
    /** carried_vectors() with their ghosts updated, and a new solution_transfer for them. */
    std::vector<const VectorType *>
    ghosted_carried_vectors();
    /**
     * After the DoFs changed and carried_vectors() were filled: the other vectors laid out
     * anew, ghosts updated, prescribed DoFs found again, nodal force weights dropped.
     */
    void
    reset_after_dof_change();
    void
    assemble_mass_and_stiffness();

    const parallel::distributed::Triangulation<dim> &triangulation;
    const Parameters::Material                       material;
    const MPI_Comm                                   communicator;
    hp::FECollection<dim>                            fe_collection;
    hp::QCollection<dim>                             cell_quadrature;
    hp::QCollection<dim - 1>                         face_quadrature;
    MappingWithoutSimilarity<dim>                    mapping;
    DoFHandler<dim>                                  dof_handler;
    IndexSet                                         locally_owned_dofs;
    IndexSet                                         locally_relevant_dofs;
    /** K_alpha, its owned rows (the products run on threads). */
    OwnedRowsMatrix stiffness_matrix;
    VectorType      mass;
    /** The vector component of each owned DoF, in local order. */
    std::vector<unsigned char> owned_dof_component;
    WeightFunction             mass_weight, stiffness_weight;
    /** The cells that carry FE_Q (the others carry FE_Nothing). */
    CellPredicate                                                             fe_cells;
    std::unique_ptr<parallel::distributed::SolutionTransfer<dim, VectorType>> solution_transfer;

    const ProblemData<dim> *problem_data = nullptr;
    double                  time_step    = 0;
    State                   state;
    VectorType              internal_force, applied_force;
    VectorType              previous_applied_force;
    VectorType              previous_displacement;
    /** Displacement and acceleration before a relaxation step. */
    VectorType relaxation_displacement, relaxation_acceleration;
    /** The search direction of a static solve by conjugate gradients. */
    VectorType                 search_direction;
    VectorType                 interface_force;
    std::vector<PrescribedDoF> prescribed;
    /** Per owned DoF: is it one of prescribed (the sums over the free DoFs skip it)? */
    std::vector<bool> is_prescribed_dof;
    /** Velocities and accelerations of the prescribed DoFs at the current time. */
    std::vector<double> prescribed_velocity;
    std::vector<double> prescribed_acceleration;
    std::vector<double> nodal_force_weights;
    Contact<dim>       *contact = nullptr;
    /** Whether any load or support does work (otherwise the work is not accounted). */
    bool   tracks_work = false;
    double work        = 0;
  };
} // namespace PeriArlequin

#endif
