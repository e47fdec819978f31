#ifndef periarlequin_coupling_arlequin_coupling_h
#define periarlequin_coupling_arlequin_coupling_h

#include <periarlequin/coupling/coupling.h>
#include <periarlequin/coupling/fine_scale_damping.h>
#include <periarlequin/coupling/interpolation_operator.h>
#include <periarlequin/coupling/multiplier_solver.h>
#include <periarlequin/coupling/multiplier_space.h>
#include <periarlequin/coupling/slave_layer.h>

#include <memory>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The Arlequin coupling with Lagrange multipliers (doc/method.md, section 4), registered as
   * "strict" (a multiplier per PD node of the overlap, H = I) and "weak" (a multiplier per FE
   * node of the overlap, H = N, or per node of a coarser Cartesian grid). Made of named operators:
   * N at the overlap's PD nodes (InterpolationOperator), the lambda-mesh H (MultiplierSpace), the
   * multiplier system (MultiplierSolver), the fine-scale damping (FineScaleDamping) and the slaves
   * that complete the families past the overlap (SlaveLayer).
   *
   * The constraint is g = H^T (N u - d) (eq. 38, 40). Each step the multipliers solve
   * A lambda = H^T (N v* - w*), and correct v -= dt M_c^-1 G lambda (G = N^T H, eq. 46) and
   * w += dt M_p^-1 H lambda (eq. 62): minus the derivative of lambda . g on both sides, so the
   * constraint does no work.
   */
  template <int dim>
  class ArlequinCoupling : public Coupling<dim>
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    /** Which lambda-mesh. */
    enum class MultiplierMesh
    {
      /** The PD nodes of the overlap. */
      strict,
      /** The FE nodes of the overlap. */
      weak
    };

    /** The weak coupling's lambda-mesh (subsection Coupling/weak). */
    struct MultiplierGrid
    {
      /** Spacing in FE cells; 1: the FE nodes [-]. */
      double spacing = 2;
      /** Where the grid starts, a fraction of its spacing before the overlap's corner [-]. */
      double offset = 0;

      void
      entries(ParameterEntries &entries);
    };

    ArlequinCoupling(const Parameters::Coupling &parameters, const MultiplierMesh mesh);

    /** The weak coupling's own entries (subsection Coupling/weak). */
    static void
    declare_weak_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm) override;

    BlendingProfile
    blending_profile() const override;
    void
    initialize(const BlendingField<dim> &blending,
               FEZone<dim>              &fe_zone,
               PDZone<dim>              &pd_zone,
               const double              time_step) override;
    void
    set_slave_displacements() override;
    void
    add_interface_forces(const double time) override;
    void
    apply_damping() override;
    double
    stable_time_step(const double undamped_step) const override;
    void
    enforce_constraint() override;
    void
    set_slave_velocities() override;
    std::pair<double, double>
    constraint_residuals() const override;
    types::global_dof_index
    n_multipliers() const override;
    std::pair<types::global_dof_index, types::global_dof_index>
    n_coupled_particles() const override;
    unsigned int
    last_solver_iterations() const override;
    /** Empty with energy blending: the other blendings' forces derive from no energy. */
    std::string
    conjugate_gradient_obstacle() const override;
    void
    solve_multipliers_exactly(const bool exact) override;

    /** The solver of the multiplier system. */
    MultiplierSolver<dim> &
    multiplier_solver();

    /** The multipliers of the last step [N], one per multiplier and component. */
    const VectorType &
    multipliers() const;

  private:
    /** g = H^T (N x - y) for an FE field @p x and PD field @p y at the overlap nodes. */
    void
    constraint(const VectorType &x, ArrayView<const Tensor<1, dim>> y, VectorType &g) const;

    const Parameters::Coupling parameters;
    const MultiplierMesh       mesh;
    MultiplierGrid             multiplier_grid;
    FEZone<dim>               *fe_zone   = nullptr;
    PDZone<dim>               *pd_zone   = nullptr;
    double                     time_step = 0;

    /** Owned PD nodes of the overlap (0 < alpha < 1), the rows of N. */
    std::vector<unsigned int>              overlap_particles;
    InterpolationOperator<dim>             overlap;
    SlaveLayer<dim>                        slaves;
    std::unique_ptr<MultiplierSpace<dim>>  space;
    std::unique_ptr<MultiplierSolver<dim>> solver;
    std::unique_ptr<FineScaleDamping<dim>> damping;
    VectorType                             fe_inverse_mass;
    std::vector<double>                    pd_inverse_mass;

    VectorType lambda, rhs, fe_scratch;
    /** Scratch values at the overlap's PD nodes. */
    mutable typename InterpolationOperator<dim>::Values overlap_values;
  };
} // namespace PeriArlequin

#endif
