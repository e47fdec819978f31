#ifndef periarlequin_base_parallel_loops_h
#define periarlequin_base_parallel_loops_h

#include <deal.II/base/parallel.h>

#include <algorithm>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * Call @p work(first, end) on subranges of [0, @p n) on the threads of this rank (TBB),
   * at least @p grain entries each. For loops whose iterations are independent (one particle,
   * one entry each), so that the results do not depend on the number of threads.
   */
  template <typename Work>
  void
  for_each_subrange(const unsigned int n, const Work &work, const unsigned int grain = 4096)
  {
    parallel::apply_to_subranges(0u, n, work, grain);
  }

  /** @p values resized to @p n entries, all 0, filled on the threads of this rank. */
  inline void
  fill_zeros(std::vector<double> &values, const std::size_t n)
  {
    if (values.size() != n)
      values.assign(n, 0.);
    else
      for_each_subrange(n, [&](const unsigned int first, const unsigned int end) {
        std::fill(values.begin() + first, values.begin() + end, 0.);
      });
  }
} // namespace PeriArlequin

#endif
