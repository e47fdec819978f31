#ifndef periarlequin_coupling_interpolation_operator_h
#define periarlequin_coupling_interpolation_operator_h

#include <periarlequin/base/parallel_loops.h>
#include <periarlequin/coupling/transposed_rows.h>
#include <periarlequin/fe/fe_zone.h>
#include <periarlequin/pd/pd_zone.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <array>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The interpolation N of the FE field at a set of PD particles, N_IJ = N_J(x_I) (eq. 38):
   * one row per particle, from the shape functions of the FE cell that holds it, evaluated at
   * its unit-cell location. The owner of a particle owns its cell, so the DoFs of a row are
   * locally relevant: N x needs the ghost values of x, and N^T s is a local scatter followed
   * by compress(add).
   */
  template <int dim>
  class InterpolationOperator
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;
    /** One vector per row (particle). */
    using Values = std::vector<Tensor<1, dim>>;

    /**
     * A non-zero N_IJ: the value of the shape function of node J at particle I, and the
     * local DoF index (owned or ghost) of each vector component of J. One entry for all
     * components: the loops keep the row's vector in registers instead of indexing it.
     */
    struct Entry
    {
      double                        value;
      std::array<unsigned int, dim> dofs;
    };

    /**
     * One row for each of the owned PD particles @p particles (local indices), in that
     * order. Their cells must carry FE unknowns: the overlap and the slave layer must lie in
     * FE cells, which is checked with a clear error.
     */
    void
    reinit(const FEZone<dim>               &fe_zone,
           const PDZone<dim>               &pd_zone,
           const std::vector<unsigned int> &particles);

    /** Inline: the loops over the rows of the coupling's operators test it at every row. */
    unsigned int
    n_rows() const
    {
      return row_begin.size() - 1;
    }

    /**
     * Call @p work(first, end) on subranges of the rows on the threads of this rank: for
     * loops whose rows are independent (each writes its own particle).
     */
    template <typename Work>
    void
    for_each_row_range(const Work &work) const
    {
      // A row costs a few dozen flops: a few hundred rows keep a task worth its start.
      for_each_subrange(n_rows(), work, 512);
    }

    /** The non-zero entries of row @p row. */
    ArrayView<const Entry>
    row(const unsigned int row) const;

    /** (N x)_row; @p x must have its ghost values. */
    Tensor<1, dim>
    interpolate(const VectorType &x, const unsigned int row) const;

    /** values = N x, on the threads; @p x must have its ghost values. */
    void
    vmult(Values &values, const VectorType &x) const;

    /** x = N^T values (owned entries, compressed), on the threads. */
    void
    Tvmult(VectorType &x, const Values &values) const;

    /** x += N^T values (owned entries, compressed; x's ghost entries must be zero). */
    void
    Tvmult_add(VectorType &x, const Values &values) const;

  private:
    std::vector<unsigned int> row_begin = {0};
    std::vector<Entry>        entries;
    /** N^T by columns, for the product on the threads. */
    TransposedRows<dim> transpose;
  };
} // namespace PeriArlequin

#endif
