#include <periarlequin/base/parallel_loops.h>
#include <periarlequin/coupling/transposed_rows.h>

namespace PeriArlequin
{
  template <int dim>
  void
  TransposedRows<dim>::reinit(const std::vector<Term> &terms, const unsigned int n_targets)
  {
    // A counting sort by target, stable: the terms of a target stay in row order.
    std::vector<unsigned int> start(n_targets + 1, 0);
    for (const Term &term : terms)
      {
        AssertIndexRange(term.target, n_targets);
        ++start[term.target + 1];
      }
    targets.clear();
    column_begin.assign(1, 0);
    for (unsigned int t = 0; t < n_targets; ++t)
      if (start[t + 1] > 0)
        {
          targets.push_back(t);
          column_begin.push_back(column_begin.back() + start[t + 1]);
        }
    for (unsigned int t = 0; t < n_targets; ++t)
      start[t + 1] += start[t];
    column_terms.resize(terms.size());
    for (const Term &term : terms)
      column_terms[start[term.target]++] = {term.coefficient, term.row, term.component};
  }

  template <int dim>
  void
  TransposedRows<dim>::add_to(VectorType &x, const Values &s) const
  {
    // A few flops a term: chunks of a thousand targets keep the tasks worth their start.
    for_each_subrange(
      targets.size(),
      [&](const unsigned int first, const unsigned int end) {
        for (unsigned int c = first; c < end; ++c)
          {
            double &entry = x.local_element(targets[c]);
            for (unsigned int k = column_begin[c]; k < column_begin[c + 1]; ++k)
              entry +=
                column_terms[k].coefficient * s[column_terms[k].row][column_terms[k].component];
          }
      },
      1024);
  }

  template class TransposedRows<2>;
  template class TransposedRows<3>;
} // namespace PeriArlequin
