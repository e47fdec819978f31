#ifndef periarlequin_fe_owned_rows_matrix_h
#define periarlequin_fe_owned_rows_matrix_h

#include <deal.II/base/partitioner.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <cstddef>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The rows a rank owns of an assembled distributed sparse matrix, with the columns
   * numbered as the local entries (owned, then ghosts) of the ghosted vectors of one
   * partition. Trilinos' matrix-vector product runs on one thread; this one reads the
   * vector's local storage directly and splits the rows among TBB threads (deal.II's task
   * facilities). Each row is summed by one thread in the column order of the matrix it was
   * copied from, so the product does not depend on the number of threads, and it equals
   * that matrix's product to the bit.
   */
  class OwnedRowsMatrix
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    /**
     * Copy the owned rows of the compressed @p matrix. @p partitioner is that of the vectors
     * of the products; every column of an owned row must be one of its owned or ghost
     * entries (true of a matrix assembled on the locally owned cells and the vectors of the
     * locally relevant DoFs).
     */
    void
    reinit(const TrilinosWrappers::SparseMatrix &matrix,
           const Utilities::MPI::Partitioner    &partitioner);

    /** dst = A src on the owned entries of @p dst; the ghost values of @p src are updated first. */
    void
    vmult(VectorType &dst, const VectorType &src) const;

  private:
    std::vector<std::size_t>  row_begin;
    std::vector<unsigned int> column;
    std::vector<double>       value;
  };
} // namespace PeriArlequin

#endif
