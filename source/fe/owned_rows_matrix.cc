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
    // Epetra's own row storage, in the order its product sums (deal.II's row iterators took
    // minutes here for 1e6 DoFs).
    const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
    AssertThrow(static_cast<std::size_t>(epetra.NumMyRows()) == partitioner.locally_owned_size(),
                ExcDimensionMismatch(epetra.NumMyRows(), partitioner.locally_owned_size()));
    row_begin.assign(1, 0);
    row_begin.reserve(epetra.NumMyRows() + 1);
    column.resize(epetra.NumMyNonzeros());
    value.resize(epetra.NumMyNonzeros());
    for (int row = 0; row < epetra.NumMyRows(); ++row)
      {
        AssertThrow(partitioner.global_to_local(epetra.GRID64(row)) ==
                      static_cast<unsigned int>(row),
                    ExcMessage("OwnedRowsMatrix: the matrix's rows are not in the order of the "
                               "vectors' owned entries."));
        int     n_entries;
        double *row_values;
        int    *row_columns;
        epetra.ExtractMyRowView(row, n_entries, row_values, row_columns);
        for (int k = 0; k < n_entries; ++k)
          {
            const auto col = static_cast<types::global_dof_index>(epetra.GCID64(row_columns[k]));
            AssertThrow(partitioner.in_local_range(col) || partitioner.is_ghost_entry(col),
                        ExcMessage("OwnedRowsMatrix: column " + std::to_string(col) + " of row " +
                                   std::to_string(epetra.GRID64(row)) +
                                   " is neither an owned nor a ghost entry of the vectors' "
                                   "partition."));
            column[row_begin.back() + k] = partitioner.global_to_local(col);
            value[row_begin.back() + k]  = row_values[k];
          }
        row_begin.push_back(row_begin.back() + n_entries);
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
