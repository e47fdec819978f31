#include <periarlequin/fe/owned_rows_matrix.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parallel.h>

#include <string>

namespace PeriArlequin
{
  void
  OwnedRowsMatrix::reinit(const TrilinosWrappers::SparseMatrix &matrix,
                          const Utilities::MPI::Partitioner    &partitioner)
  {
    const IndexSet &owned = partitioner.locally_owned_range();
    row_begin.assign(1, 0);
    row_begin.reserve(owned.n_elements() + 1);
    column.clear();
    value.clear();
    column.reserve(matrix.trilinos_matrix().NumMyNonzeros());
    value.reserve(matrix.trilinos_matrix().NumMyNonzeros());
    for (const types::global_dof_index row : owned)
      {
        for (auto entry = matrix.begin(row); entry != matrix.end(row); ++entry)
          {
            const types::global_dof_index col = entry->column();
            AssertThrow(partitioner.in_local_range(col) || partitioner.is_ghost_entry(col),
                        ExcMessage("OwnedRowsMatrix: column " + std::to_string(col) +
                                   " of row " + std::to_string(row) +
                                   " is neither an owned nor a ghost entry of the vectors' "
                                   "partition."));
            column.push_back(partitioner.global_to_local(col));
            value.push_back(entry->value());
          }
        row_begin.push_back(column.size());
      }
  }

  void
  OwnedRowsMatrix::vmult(VectorType &dst, const VectorType &src) const
  {
    Assert(dst.locally_owned_size() + 1 == row_begin.size(),
           ExcDimensionMismatch(dst.locally_owned_size() + 1, row_begin.size()));
    src.update_ghost_values();
    const double *const x = src.begin();
    double *const       y = dst.begin();
    parallel::apply_to_subranges(
      std::size_t(0),
      row_begin.size() - 1,
      [&](const std::size_t first, const std::size_t last) {
        for (std::size_t row = first; row < last; ++row)
          {
            double sum = 0;
            for (std::size_t k = row_begin[row]; k < row_begin[row + 1]; ++k)
              sum += value[k] * x[column[k]];
            y[row] = sum;
          }
      },
      512);
  }
} // namespace PeriArlequin
