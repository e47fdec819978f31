// A crack running through a coupled model against the same crack in pure PD: the branching
// plate of glass_plate_case (100 x 40 mm glass, traction 2 MPa applied at t = 0 on the top
// and bottom edges, G0 = 3.8 J/m^2) with a 50 mm notch along y = 20 mm from the left edge,
// at a coarse resolution (lattice 0.625 mm, delta = 2 mm; the crack starts near 10 us and
// branches near 22 us, the branches reaching y = 20 +- 5 mm by 30 us).
//  - Crack through the coupling: PD strip |y - 20 mm| <= 7.5 mm, overlaps 7.5 mm (3 FE
//    cells of 2.5 mm, FE/PD size ratio 4), FE beyond, force blending, to 20 us: the tip
//    position x of the coupled run (CrackDiagnostics, recorded every 1 us) stays within 2
//    horizons of the pure-PD one at every record (the target), the crack area within
//    20 % of it at the end, and no bond with an end in the overlap or the slave layer breaks.
//  - Crack reaching the overlap: the same with a PD strip |y - 20 mm| <= 5 mm run to 40 us:
//    the run stops with the message that damage reached the overlap before the end (not
//    blaming the loaded edges, which lie beyond two bond reaches of the stop), and still no
//    bond of the overlap or the slave layer is broken.

#include <periarlequin/pd/bond_families.h>

#include "coupled_cases.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

namespace
{
  /** Broken bonds with an end in the overlap or the slave layer (alpha > 0), all ranks. */
  unsigned int
  broken_coupled_bonds(const PDZone<2> &pd)
  {
    const BondFamilies<2> &bonds    = pd.get_bonds();
    const auto             alpha    = pd.blending_weights();
    unsigned int           n_broken = 0;
    for (unsigned int i = 0; i < bonds.n_owned; ++i)
      for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
        n_broken += bonds.state[n] == BondFamilies<2>::broken &&
                    (alpha[i] > 0 || alpha[bonds.neighbor(i, n)] > 0);
    return Utilities::MPI::sum(n_broken, MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const double delta   = 3.2 * 6.25e-4;
    auto         pure_pd = make_simulator<2>(notched_glass_plate_case(false, 0.0075, 2e-5));
    pure_pd->run();
    auto coupled = make_simulator<2>(notched_glass_plate_case(true, 0.0075, 2e-5));
    coupled->run();

    const auto &reference = pure_pd->get_energy_history(), &history = coupled->get_energy_history();
    const auto  x_ref = reference.column("branch_0_x"), x = history.column("branch_0_x");
    double      largest   = 0;
    unsigned int compared = 0;
    for (unsigned int n = 0; n < x.size(); ++n)
      if (std::isfinite(x_ref[n]) || std::isfinite(x[n]))
        {
          // A tip seen in one run only counts as the distance from the notch tip.
          const double a = std::isfinite(x_ref[n]) ? x_ref[n] : 0.05;
          const double b = std::isfinite(x[n]) ? x[n] : 0.05;
          largest        = std::max(largest, std::abs(a - b));
          ++compared;
        }
    check_above("records with a running crack", compared, 5);
    report("crack extension at 20 us, pure PD [m]", reference.column("crack_extension").back());
    check_below("largest |tip x coupled - pure PD| / delta, up to 20 us", largest / delta, 2.);
    check_below("|crack area coupled / pure PD - 1| at 20 us",
                std::abs(
                  history.column("crack_area").back() / reference.column("crack_area").back() - 1.),
                0.2);
    check_below("broken bonds of the overlap and slave layer",
                broken_coupled_bonds(*coupled->get_pd_zone()),
                0.5);

    auto        narrow = make_simulator<2>(notched_glass_plate_case(true, 0.005, 4e-5));
    std::string message;
    try
      {
        narrow->run();
      }
    catch (const std::exception &error)
      {
        message = error.what();
      }
    check("narrow strip: the run stops with 'Damage reached the overlap'",
          message.find("Damage reached the overlap at t = ") != std::string::npos,
          1,
          0);
    // The band meets the crack 7.5 mm from the loaded edges, beyond two bond reaches (4.6 mm):
    // the stop must not blame them.
    check("narrow strip: the stop names no loaded boundary",
          message.find("from boundary") == std::string::npos,
          1,
          0);
    check_below("narrow strip: stop time / end time", narrow->get_time() / 4e-5, 1.);
    check_below("narrow strip: broken bonds of the overlap and slave layer",
                broken_coupled_bonds(*narrow->get_pd_zone()),
                0.5);
  });
}
