#ifndef periarlequin_coupling_multiplier_solver_h
#define periarlequin_coupling_multiplier_solver_h

#include <periarlequin/coupling/blending_field.h>
#include <periarlequin/coupling/multiplier_space.h>

#include <deal.II/lac/diagonal_matrix.h>

#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The multipliers of a step (eq. 64-69): from d/dt g = 0 at t_n+1,
   *   A lambda = H^T (N v* - w*),   A = dt H^T (N M_c^-1 N^T + M_p^-1) H   (eq. 66-67),
   * symmetric positive definite. Solved with the paper's row-sum diagonal of A (eq. 68-69),
   * which needs positive row sums (FE degree 1), or exactly by conjugate gradients
   * preconditioned with the diagonal of A (Jacobi; positive for any FE degree).
   */
  template <int dim>
  class MultiplierSolver
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    /**
     * @p fe_inverse_mass: 1/m_J on the FE DoFs (0 where prescribed) with ghost values;
     * @p pd_inverse_mass: 1/m_I at the overlap PD nodes (the rows of @p overlap).
     */
    MultiplierSolver(MultiplierSpace<dim>              &space,
                     const InterpolationOperator<dim>  &overlap,
                     const VectorType                  &fe_inverse_mass,
                     const std::vector<double>         &pd_inverse_mass,
                     const double                       time_step,
                     const Parameters::MultiplierSolver method);

    /** Shape a multiplier vector. */
    void
    initialize_vector(VectorType &lambda) const;

    /** y = A x (eq. 67). */
    void
    vmult(VectorType &y, const VectorType &x);

    /** The paper's diagonal of A (eq. 68): its row sums A 1. */
    void
    row_sum_diagonal(VectorType &diagonal);

    /** The diagonal entries of A, the Jacobi preconditioner of the exact solve. */
    void
    jacobi_diagonal(VectorType &diagonal) const;

    /** Solve A lambda = @p rhs (eq. 66; eq. 69 with the row-sum diagonal). */
    void
    solve(VectorType &lambda, const VectorType &rhs);

    /**
     * Solve exactly (by CG) whatever the method while @p exact: a static solve by conjugate
     * gradients needs the projection onto the constraint that the diagonal only
     * approximates. The solves of one such request (a projection, in one or more passes)
     * add up to its multipliers; the first solve of the next request starts from them: the
     * residuals a static solve projects converge, and so do their multipliers.
     */
    void
    solve_exactly(const bool exact);

    /** CG iterations of the last solve (0 for the diagonal solver). */
    unsigned int
    last_iterations() const;

  private:
    MultiplierSpace<dim>              &space;
    const InterpolationOperator<dim>  &overlap;
    const VectorType                  &fe_inverse_mass;
    const std::vector<double>          pd_inverse_mass;
    const double                       time_step;
    const Parameters::MultiplierSolver method;

    /** Marks the rows with an equation, from the diagonal or the row sums of A. */
    void
    set_free_rows(const VectorType &diagonal);
    /** The Jacobi preconditioner and the operator of the exact solve. */
    void
    prepare_exact_solve();
    /** CG on A lambda = free_rhs, whose norm is @p rhs_norm > 0. */
    void
    solve_by_cg(VectorType &lambda, const double rhs_norm);

    /** Row sums of A (diagonal solver). */
    VectorType row_sums;
    /** The inverse diagonal of A (the exact solve's preconditioner). */
    VectorType inverse_diagonal;
    bool       exact_solve_prepared = false;
    bool       exact_on_request     = false;
    /** 1 for the multipliers with an equation, 0 where A has a zero row (all prescribed). */
    VectorType                 free_rows;
    VectorType                 free_rhs;
    DiagonalMatrix<VectorType> preconditioner;
    /** The conjugate gradients' vectors: residual, preconditioned, direction, A direction. */
    VectorType                            residual, preconditioned_residual, direction, product;
    VectorType                            fe_scratch;
    typename MultiplierSpace<dim>::Values overlap_values, overlap_values_2;
    unsigned int                          iterations = 0;

    /** The solves since the current exact request, and the sum of their solutions. */
    unsigned int exact_solves = 0;
    VectorType   request_multipliers;
    /** The multipliers of the previous exact request, where its successor starts. */
    VectorType previous_request_multipliers;
    bool       previous_request_available = false;
  };
} // namespace PeriArlequin

#endif
