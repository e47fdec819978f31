#ifndef periarlequin_base_parallel_loops_h
#define periarlequin_base_parallel_loops_h

#include <deal.II/base/parallel.h>

#include <algorithm>
#include <cstdint>
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

  /** The most fixed chunks a range is split into (for_each_fixed_chunk()). */
  constexpr unsigned int max_fixed_chunks = 64;

  /**
   * Call @p work(chunk, first, end) on fixed chunks of [0, @p n), on the threads of this rank.
   * The chunks depend on @p n only: results combined in chunk order do not depend on the
   * number of threads (a reduction over TBB's own split would).
   */
  template <typename Work>
  unsigned int
  for_each_fixed_chunk(const unsigned int n, const Work &work)
  {
    const unsigned int n_chunks = std::min(max_fixed_chunks, 1 + n / 4096);
    parallel::apply_to_subranges(
      0u,
      n_chunks,
      [&](const unsigned int first_chunk, const unsigned int end_chunk) {
        for (unsigned int c = first_chunk; c < end_chunk; ++c)
          work(c,
               static_cast<unsigned int>(std::uint64_t(n) * c / n_chunks),
               static_cast<unsigned int>(std::uint64_t(n) * (c + 1) / n_chunks));
      },
      1);
    return n_chunks;
  }

  /** The sum of @p chunk_sum(first, end) over the fixed chunks of [0, @p n), in chunk order. */
  template <typename T, typename ChunkSum>
  T
  sum_over_chunks(const unsigned int n, const ChunkSum &chunk_sum)
  {
    std::vector<T>     partial(max_fixed_chunks, T());
    const unsigned int n_chunks =
      for_each_fixed_chunk(n,
                           [&](const unsigned int c,
                               const unsigned int first,
                               const unsigned int end) { partial[c] = chunk_sum(first, end); });
    T sum = T();
    for (unsigned int c = 0; c < n_chunks; ++c)
      sum += partial[c];
    return sum;
  }

  /**
   * The entries that @p chunk_list(first, end, list) appends for the fixed chunks of
   * [0, @p n), joined in chunk order: the list a loop over [0, n) would build.
   */
  template <typename T, typename ChunkList>
  std::vector<T>
  join_over_chunks(const unsigned int n, const ChunkList &chunk_list)
  {
    std::vector<std::vector<T>> lists(max_fixed_chunks);
    const unsigned int          n_chunks =
      for_each_fixed_chunk(n,
                           [&](const unsigned int c,
                               const unsigned int first,
                               const unsigned int end) { chunk_list(first, end, lists[c]); });
    std::vector<T> joined;
    for (unsigned int c = 0; c < n_chunks; ++c)
      joined.insert(joined.end(), lists[c].begin(), lists[c].end());
    return joined;
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
