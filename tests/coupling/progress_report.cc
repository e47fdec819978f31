// Progress lines on 2 ranks: whether a line is due depends on the wall clock, which differs
// between ranks, and printing one runs a collective check of the state. If each rank asked
// its own clock, the ranks would sooner or later disagree and wait for each other forever
// (seen with the default example on 2 ranks). Here a progress line is due about every other
// step (interval 1 ms, steps of about a millisecond), so a disagreement would come within the
// first few hundred steps: the run must finish (ctest stops it after 300 s) and reproduce the
// 1-rank energy history to 1e-10 relative (printing must not change the state).

#include "coupled_cases.h"

using namespace PeriArlequinTests;

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    require_several_ranks();
    check_below(
      "weak coupling with progress lines every 1 ms: 2 ranks vs 1 rank, max relative difference",
      parallel_vs_serial_history_difference<2>(
        strip_case("weak",
                   "energy",
                   "diagonal",
                   true,
                   false,
                   smooth_pulse,
                   "0; 0",
                   2e-7,
                   2e-4,
                   10) +
          "subsection Output\n  set Progress interval = 0.001\nend\n",
        "weak"),
      1e-10);
  });
}
