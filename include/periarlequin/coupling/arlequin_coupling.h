#ifndef periarlequin_coupling_arlequin_coupling_h
#define periarlequin_coupling_arlequin_coupling_h

#include <deal.II/lac/la_parallel_vector.h>

#include <periarlequin/base/parameters.h>
#include <periarlequin/coupling/blending_field.h>
#include <periarlequin/fe/fe_zone.h>
#include <periarlequin/pd/pd_zone.h>

#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * Glues the PD zone to the FE zone across the overlap (DESIGN.md section 2).
   *
   * N interpolates the FE field at the owned PD particles that need it (the PD nodes of the
   * overlap and the slaves), N_IJ = N_J(x_I), from the shape functions of the particle's
   * cell; the FE DoFs of an owned cell are locally relevant, so N u needs ghost values only
   * and N^T f is a local scatter plus compress(add). The constraint is g = H^T (N u - d) on
   * the overlap with H = I (strict: a multiplier per PD node and component) or H = N (weak:
   * a multiplier per FE DoF of the overlap). Each step the multipliers solve
   *   A lambda = H^T (N v* - w*),   A = dt H^T (N M_c^-1 N^T + M_p^-1) H,
   * with the row-sum diagonal of A (the paper's eq. 68) or by conjugate gradients, and correct
   * v -= dt M_c^-1 G lambda (G = N^T H), w += dt M_p^-1 H lambda: minus the derivative of
   * lambda . g on both sides, so the constraint does no work.
   *
   * Fine-scale damping adds -M_p C_I (w - N v)_I to the PD nodes of the overlap with
   * C_I = C v_w alpha_I^2 / L_B (eq. 76-78), evaluated with the half-step velocities.
   *
   * The "bad" coupling (fig. 8) has no multipliers: the PD slaves (FE-side half) take
   * d = N u, and the FE DoFs of the PD-side half take the PD field interpolated on the lattice.
   */
  template <int dim>
  class ArlequinCoupling
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    ArlequinCoupling(const Parameters::Coupling &parameters,
                     const BlendingField<dim>   &blending,
                     const Parameters::Material &material,
                     FEZone<dim>                &fe_zone,
                     PDZone<dim>                &pd_zone);

    /**
     * Interpolation rows, multiplier rows, inverse masses (0 on the FE zone's prescribed
     * DoFs: call after FEZone::initialize_state()), damping coefficients; checks that the
     * overlap holds PD nodes and FE DoFs and that the damping is stable at @p time_step.
     * Sets the FE zone's force hooks: nodal weights alpha_I (force blending) or the slaves'
     * forces N^T f (energy blending).
     */
    void
    setup(const double time_step);

    /** Slaves follow the master field: bad coupling's FE DoFs, then d = N u on PD slaves. */
    void
    set_slave_displacements();

    /** b_I -= C_I (w_I - (N v)_I) on the PD nodes of the overlap (half-step velocities). */
    void
    apply_damping();

    /**
     * Solve for the multipliers from the trial velocities and correct velocities and
     * accelerations of both zones.
     */
    void
    enforce_constraint();

    /** Slaves' velocities and accelerations from their masters. */
    void
    set_slave_velocities();

    /** |g| = |H^T (N u - d)| [m] and |g_dot| = |H^T (N v - w)| [m/s] (l2 over all rows). */
    std::pair<double, double>
    constraint_residuals();

    /** Number of multipliers (over all ranks and components). */
    types::global_dof_index
    n_multipliers() const;
    /** Overlap PD nodes and slaves over all ranks. */
    std::pair<types::global_dof_index, types::global_dof_index>
    n_coupled_particles() const;
    /** CG iterations of the last solve (0 for the diagonal solver). */
    unsigned int
    last_iterations() const;

  private:
    using Values = std::vector<Tensor<1, dim>>;

    /** @p force += N^T f on the slaves' blended PD forces (energy blending). */
    void
    add_slave_forces(VectorType &force);

    /** (N x)_I at the k-th particle with an interpolation row; x needs ghost values. */
    Tensor<1, dim>
    interpolate(const VectorType &x, const unsigned int row) const;
    /** result = N^T values (values on the overlap particles), compressed. */
    void
    scatter_overlap(const Values &values, VectorType &result) const;
    /** y = H^T s (s on the overlap particles). */
    void
    apply_transpose_h(const Values &s, std::vector<double> &y);
    /** p = H x on the overlap particles. */
    void
    apply_h(const std::vector<double> &x, Values &p);
    /** y = A x. */
    void
    apply_a(const std::vector<double> &x, std::vector<double> &y);
    double
    dot(const std::vector<double> &a, const std::vector<double> &b) const;

    const Parameters::Coupling parameters;
    const BlendingField<dim>  &blending;
    const Parameters::Material material;
    FEZone<dim>               &fe_zone;
    PDZone<dim>               &pd_zone;
    MPI_Comm                   communicator;
    double                     time_step = 0;

    /** Interpolation rows: row k belongs to owned particle row_particle[k]. */
    struct Entry
    {
      unsigned int dof;
      unsigned int component;
      double       value;
    };
    std::vector<unsigned int> row_particle, row_begin;
    std::vector<Entry>        entries;
    /** Rows of the overlap PD nodes and of the slaves. */
    std::vector<unsigned int> overlap_rows, slave_rows;
    /** Weak coupling: owned FE DoFs (local index) carrying a multiplier. */
    std::vector<unsigned int> multiplier_dofs;
    std::vector<double>       damping_coefficient;
    std::vector<double>       alpha_at_dofs;
    VectorType                inverse_mass;
    /** Bad coupling: FE DoFs that follow the PD field, with their lattice weights. */
    struct FESlave
    {
      unsigned int                                 dof;
      unsigned int                                 component;
      std::vector<std::pair<unsigned int, double>> weights;
    };
    std::vector<FESlave> fe_slaves;
    std::vector<double>  pd_motion_buffer;

    std::vector<double> diagonal, lambda, rhs, residual, direction, a_direction, preconditioned;
    mutable VectorType  fe_scratch, fe_scratch_2;
    Values              overlap_values, overlap_values_2;
    unsigned int        iterations = 0;
  };
} // namespace PeriArlequin

#endif
