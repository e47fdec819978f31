#ifndef periarlequin_base_vector_reductions_h
#define periarlequin_base_vector_reductions_h

#include <periarlequin/base/parallel_loops.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <cmath>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The dot product of @p a and @p b (same layout) over all ranks, summed over the fixed
   * chunks of the owned entries (for_each_fixed_chunk()): the same bits on any number of
   * threads. deal.II's own reductions split a vector of more than 16,384 owned entries in
   * chunks when it runs on several threads and sum it in one pass on one thread, so they
   * differ in the last bits between DEAL_II_NUM_THREADS=1 and more.
   */
  inline double
  dot_in_fixed_chunks(const LinearAlgebra::distributed::Vector<double> &a,
                      const LinearAlgebra::distributed::Vector<double> &b)
  {
    const double local =
      sum_over_chunks<double>(a.locally_owned_size(),
                              [&](const unsigned int first, const unsigned int end) {
                                double sum = 0;
                                for (unsigned int i = first; i < end; ++i)
                                  sum += a.local_element(i) * b.local_element(i);
                                return sum;
                              });
    return Utilities::MPI::sum(local, a.get_mpi_communicator());
  }

  /** The l2 norm of @p v over all ranks, as dot_in_fixed_chunks(): independent of the threads. */
  inline double
  l2_norm_in_fixed_chunks(const LinearAlgebra::distributed::Vector<double> &v)
  {
    return std::sqrt(dot_in_fixed_chunks(v, v));
  }
} // namespace PeriArlequin

#endif
