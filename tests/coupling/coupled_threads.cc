// The coupled step on the threads of a rank: the coupling's operators (N and N^T by rows and
// by columns, the multiplier grid's H and H^T, the multiplier solves, the fine-scale damping,
// the slave layer), the FE accelerations and the crack diagnostics split their loops among
// the threads; each entry is written by one thread with the additions of the serial loop in
// its order, and the sums over particles run in fixed chunks. So 2 threads must give what 1
// thread gives to the bit: tolerance 0 on every column of the energy history at every record.
// The case: the notched glass plate of coupling/coupled_crack, a crack running in the PD strip
// (force blending, weak coupling on the default multiplier grid, diagonal multipliers,
// damping, broken-bond and crack-tip diagnostics), to 15 us; again with the multipliers on
// the FE nodes and conjugate-gradient solves, and with the strict coupling. The overlaps hold
// 3520 PD nodes, the slave layer 2560 (checked above 2000): on each of 2 ranks, more than two
// tasks of 512 rows. About 6900 bond ends break in each run.

#include <tbb/task_arena.h>

#include "coupled_cases.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

namespace
{
  /** Run @p parameters on 2 threads and on 1; the largest relative difference of the histories. */
  double
  threads_difference(const std::string &parameters, const std::string &title)
  {
    auto two_threads = make_simulator<2>(parameters, MPI_COMM_WORLD);
    auto one_thread  = make_simulator<2>(parameters, MPI_COMM_WORLD);
    two_threads->run();
    tbb::task_arena(1).execute([&] { one_thread->run(); });
    require_active_column(*two_threads, title, "broken_bonds");
    const auto [overlap_nodes, slaves] = two_threads->get_coupling()->n_coupled_particles();
    check_above(title + ": overlap PD nodes", overlap_nodes, 2000);
    check_above(title + ": slave particles", slaves, 2000);
    return history_difference(two_threads->get_energy_history(),
                              one_thread->get_energy_history(),
                              title);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(
    argc,
    argv,
    [] {
      require_two_threads();
      const std::string plate = notched_glass_plate_case(true, 0.0075, 1.5e-5);
      check("weak on the grid, diagonal, damping: 2 threads vs 1, largest relative difference",
            threads_difference(plate, "weak grid"),
            0.,
            0.);
      check("weak on the FE nodes, CG: 2 threads vs 1, largest relative difference",
            threads_difference(plate + "subsection Coupling\n  set Multiplier solver = cg\n"
                                       "  subsection weak\n    set Multiplier spacing = 1\n"
                                       "  end\nend\n",
                               "weak FE nodes CG"),
            0.,
            0.);
      check("strict, diagonal, damping: 2 threads vs 1, largest relative difference",
            threads_difference(plate + "subsection Coupling\n  set Method = strict\nend\n",
                               "strict"),
            0.,
            0.);
    },
    2);
}
