#include <periarlequin/base/parallel_loops.h>
#include <periarlequin/base/vector_reductions.h>
#include <periarlequin/coupling/multiplier_solver.h>


namespace PeriArlequin
{
  template <int dim>
  MultiplierSolver<dim>::MultiplierSolver(MultiplierSpace<dim>              &space,
                                          const InterpolationOperator<dim>  &overlap,
                                          const VectorType                  &fe_inverse_mass,
                                          const std::vector<double>         &pd_inverse_mass,
                                          const double                       time_step,
                                          const Parameters::MultiplierSolver method)
    : space(space)
    , overlap(overlap)
    , fe_inverse_mass(fe_inverse_mass)
    , pd_inverse_mass(pd_inverse_mass)
    , time_step(time_step)
    , method(method)
  {
    fe_scratch.reinit(fe_inverse_mass);
    space.initialize_vector(row_sums);
    if (method == Parameters::MultiplierSolver::cg)
      {
        prepare_exact_solve();
        return;
      }
    // Positive for FE_Q1, whose shape functions are non-negative: A has no negative entry.
    // Shape functions that change sign can make a row sum vanish, while CG only needs A to be
    // positive definite.
    row_sum_diagonal(row_sums);
    for (unsigned int m = 0; m < row_sums.locally_owned_size(); ++m)
      AssertThrow(row_sums.local_element(m) >= 0,
                  ExcMessage("Invalid input: parameter 'Coupling/Multiplier solver' = "
                             "'diagonal'; a row sum of the multiplier matrix A is "
                             "negative; allowed: 'cg' (conjugate gradients preconditioned "
                             "by the diagonal of A, positive since A is positive "
                             "definite)."));
    set_free_rows(row_sums);
  }

  template <int dim>
  void
  MultiplierSolver<dim>::set_free_rows(const VectorType &diagonal)
  {
    // A multiplier whose FE DoFs and PD nodes all move as prescribed (zero inverse masses) has
    // a zero row and column in A: it transmits no force, and its constraint holds as well as
    // the prescribed fields agree. Its equation is dropped (lambda = 0 there).
    space.initialize_vector(free_rows);
    for (unsigned int m = 0; m < diagonal.locally_owned_size(); ++m)
      free_rows.local_element(m) = diagonal.local_element(m) > 0 ? 1. : 0.;
  }

  template <int dim>
  void
  MultiplierSolver<dim>::prepare_exact_solve()
  {
    space.initialize_vector(inverse_diagonal);
    jacobi_diagonal(inverse_diagonal);
    set_free_rows(inverse_diagonal);
    for (unsigned int m = 0; m < inverse_diagonal.locally_owned_size(); ++m)
      inverse_diagonal.local_element(m) =
        free_rows.local_element(m) > 0 ? 1. / inverse_diagonal.local_element(m) : 0.;
    preconditioner.reinit(inverse_diagonal);
    for (VectorType *v : {&residual, &preconditioned_residual, &direction, &product})
      space.initialize_vector(*v);
    exact_solve_prepared = true;
  }

  template <int dim>
  void
  MultiplierSolver<dim>::solve_exactly(const bool exact)
  {
    if (exact && !exact_solve_prepared)
      prepare_exact_solve();
    if (exact && !exact_on_request)
      {
        exact_solves = 0;
        space.initialize_vector(request_multipliers);
      }
    if (!exact && exact_on_request && exact_solves > 0)
      {
        previous_request_multipliers.swap(request_multipliers);
        previous_request_available = true;
      }
    exact_on_request = exact;
  }

  template <int dim>
  void
  MultiplierSolver<dim>::initialize_vector(VectorType &lambda) const
  {
    space.initialize_vector(lambda);
  }

  template <int dim>
  void
  MultiplierSolver<dim>::vmult(VectorType &y, const VectorType &x)
  {
    // A x = dt H^T (N M_c^-1 N^T + M_p^-1) H x
    space.apply_h(x, overlap_values);
    overlap.Tvmult(fe_scratch, overlap_values);
    fe_scratch.scale(fe_inverse_mass);
    fe_scratch.update_ghost_values();
    overlap.vmult(overlap_values_2, fe_scratch);
    overlap.for_each_row_range([&](const unsigned int first, const unsigned int end) {
      for (unsigned int r = first; r < end; ++r)
        overlap_values_2[r] += pd_inverse_mass[r] * overlap_values[r];
    });
    space.apply_transpose_h(overlap_values_2, y);
    y *= time_step;
  }

  template <int dim>
  void
  MultiplierSolver<dim>::row_sum_diagonal(VectorType &row_sums)
  {
    VectorType ones;
    space.initialize_vector(ones);
    ones = 1.;
    vmult(row_sums, ones);
  }

  template <int dim>
  void
  MultiplierSolver<dim>::jacobi_diagonal(VectorType &entries) const
  {
    space.diagonal_of_projection(fe_inverse_mass, pd_inverse_mass, entries);
    entries *= time_step;
  }

  template <int dim>
  void
  MultiplierSolver<dim>::solve(VectorType &lambda, const VectorType &rhs)
  {
    iterations = 0;
    if (method == Parameters::MultiplierSolver::diagonal && !exact_on_request)
      {
        for_each_subrange(lambda.locally_owned_size(),
                          [&](const unsigned int first, const unsigned int end) {
                            for (unsigned int m = first; m < end; ++m)
                              lambda.local_element(m) =
                                free_rows.local_element(m) > 0 ?
                                  rhs.local_element(m) / row_sums.local_element(m) :
                                  0.;
                          });
        return;
      }
    free_rhs = rhs;
    free_rhs.scale(free_rows);
    const double rhs_norm = l2_norm_in_fixed_chunks(free_rhs);
    if (rhs_norm == 0)
      lambda = 0.;
    else
      solve_by_cg(lambda, rhs_norm);
    if (exact_on_request)
      {
        request_multipliers += lambda;
        ++exact_solves;
      }
  }

  template <int dim>
  void
  MultiplierSolver<dim>::solve_by_cg(VectorType &lambda, const double rhs_norm)
  {
    // Start from the previous request's multipliers in the first solve of a request, from
    // the Jacobi solution otherwise. Stop at a relative residual of 1e-12; a later solve of
    // a request only corrects what its first solve left (a constraint residual of 1e-12 of
    // that solve's right-hand side): 1e-6 of it leaves 1e-18.
    const bool correction = exact_on_request && exact_solves > 0;
    if (exact_on_request && exact_solves == 0 && previous_request_available)
      lambda = previous_request_multipliers;
    else
      preconditioner.vmult(lambda, free_rhs);
    const double relative_tolerance = correction ? 1e-6 : 1e-12;
    const double tolerance          = relative_tolerance * rhs_norm;
    // Jacobi-preconditioned conjugate gradients, stopped on the residual norm; its dot
    // products in fixed chunks (dot_in_fixed_chunks()), so the multipliers do not depend on
    // the number of threads, to the bit.
    vmult(product, lambda);
    residual.equ(1., free_rhs);
    residual.add(-1., product);
    double residual_norm = l2_norm_in_fixed_chunks(residual);
    double rz            = 0;
    for (unsigned int k = 0; residual_norm > tolerance; ++k)
      {
        AssertThrow(k < 1000,
                    ExcMessage("The multiplier CG solve did not reach a relative residual of " +
                               Utilities::to_string(relative_tolerance) + " in 1000 iterations " +
                               "(reached " + Utilities::to_string(residual_norm / rhs_norm) +
                               ")."));
        preconditioner.vmult(preconditioned_residual, residual);
        const double rz_next = dot_in_fixed_chunks(residual, preconditioned_residual);
        if (k == 0)
          direction.equ(1., preconditioned_residual);
        else
          direction.sadd(rz_next / rz, 1., preconditioned_residual);
        rz = rz_next;
        vmult(product, direction);
        const double step = rz / dot_in_fixed_chunks(direction, product);
        lambda.add(step, direction);
        residual.add(-step, product);
        residual_norm = l2_norm_in_fixed_chunks(residual);
        iterations    = k + 1;
      }
  }

  template <int dim>
  unsigned int
  MultiplierSolver<dim>::last_iterations() const
  {
    return iterations;
  }

  template class MultiplierSolver<2>;
  template class MultiplierSolver<3>;
} // namespace PeriArlequin
