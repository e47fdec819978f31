// A crack running through the coupled model on 2 and 3 ranks against 1 rank: the coupled case of
// coupling/coupled_crack (glass plate, notch, PD strip |y - 20 mm| <= 7.5 mm, force
// blending) to 20 us, run on all ranks and again on rank 0 alone. The broken-bond counts
// must be identical at every record (a bond to a ghost breaks on both ranks in the same
// step: the stretch is computed alike from both ends), and the crack area measured from the
// broken bonds agrees to 1e-12 m (sums in another order; measured 1.4e-15 m).

#include "coupled_cases.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const std::string text     = notched_glass_plate_case(true, 0.0075, 2e-5);
    auto              parallel = make_simulator<2>(text, MPI_COMM_WORLD);
    parallel->run();
    const auto broken            = parallel->get_energy_history().column("broken_bonds");
    const auto area              = parallel->get_energy_history().column("crack_area");
    double     broken_difference = 0, area_difference = 0;
    if (is_root())
      {
        auto serial = make_simulator<2>(text, MPI_COMM_SELF);
        serial->run();
        const auto serial_broken = serial->get_energy_history().column("broken_bonds");
        const auto serial_area   = serial->get_energy_history().column("crack_area");
        for (unsigned int n = 0; n < broken.size(); ++n)
          {
            broken_difference = std::max(broken_difference, std::abs(broken[n] - serial_broken[n]));
            area_difference   = std::max(area_difference, std::abs(area[n] - serial_area[n]));
          }
        report("broken bond ends at the end", broken.back());
      }
    check_above("broken bond ends at the end (a crack ran)",
                Utilities::MPI::broadcast(MPI_COMM_WORLD, broken.back() - broken.front(), 0),
                100);
    check_below("largest |broken bonds, all ranks - rank 0 alone|",
                Utilities::MPI::broadcast(MPI_COMM_WORLD, broken_difference, 0),
                0.5);
    check_below("largest |crack area, all ranks - rank 0 alone| [m]",
                Utilities::MPI::broadcast(MPI_COMM_WORLD, area_difference, 0),
                1e-12);
  });
}
