#ifndef periarlequin_coupling_transposed_rows_h
#define periarlequin_coupling_transposed_rows_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The transpose of a sparse operator with one vector row per particle, applied by its
   * columns: x_t += sum_k c_k s_{r_k, d_k} over the terms k of target t (a local entry of x).
   * A loop over the rows scatters to the targets and cannot be split among threads; by
   * columns each target is written by one thread. The terms of a column are kept in row
   * order, so each target receives the same additions in the same order as from the loop
   * over the rows: the result is that of the serial scatter, whatever the number of threads.
   */
  template <int dim>
  class TransposedRows
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;
    using Values     = std::vector<Tensor<1, dim>>;

    /** One term of a row: it adds coefficient * s[row][component] to x.local_element(target). */
    struct Term
    {
      unsigned int row;
      unsigned int component;
      unsigned int target;
      double       coefficient;
    };

    /**
     * The columns of @p terms, which must come in the order of their rows; targets are local
     * entries below @p n_targets.
     */
    void
    reinit(const std::vector<Term> &terms, unsigned int n_targets);

    /** x_t += (C^T s)_t on the threads of this rank (local entries, no communication). */
    void
    add_to(VectorType &x, const Values &s) const;

  private:
    /** A term of a column. */
    struct ColumnTerm
    {
      double       coefficient;
      unsigned int row;
      unsigned int component;
    };

    /** The targets that some term reaches, ascending, and where each one's terms begin. */
    std::vector<unsigned int> targets;
    std::vector<unsigned int> column_begin = {0};
    std::vector<ColumnTerm>   column_terms;
  };
} // namespace PeriArlequin

#endif
