// Crack initiation in mode I against G0: the paper's section 6.4 specimen (62.5 mm square,
// E = 29 GPa, nu = 0.29, G0 = 36 kJ/m^2, plane strain) in pure PD with m = 3, its edge crack
// loaded by the crack-tip field K_I = Kdot t (G = G0 at 300 us, about ten shear-wave transits
// of the square: quasi-static), on two lattices: 64 and 128 sites per side (delta = 2.93 and
// 1.46 mm). Initiation is the first new broken bond of a particle within a horizon of the tip
// (CrackInitiation); G = K_I^2 (1 - nu^2) / E there is compared with G0.
//  - Scale invariance: under the sqrt(r) field, bond stretches at r ~ delta scale as
//    K / sqrt(delta), and so does the critical stretch sqrt(5 pi G0 / (12 E delta)); the
//    load at which the first bond breaks is therefore the same G for any delta at a fixed m
//    (up to the domain's size, 21 and 43 horizons here, and the record interval: 10 steps,
//    1 and 2 us, 0.7 % of G). Asserted: the two G_init / G0 agree within 3 %.
//  - Against G0: a critical stretch derived from G0 breaks the first bond at the tip later
//    than LEFM's G = G0 (studies/mixed_mode/README.md: 1.12-1.20 G0 at m = 3, lower at larger m).
//    Asserted: G_init / G0 in [0.9, 1.25], the band the PD model holds at m = 3; the
//    issue's 10 % is not met at this horizon factor (see the doc).
//  - The "critical bond energy" criterion on the coarse lattice, run on until the crack has
//    grown 5 mm: it breaks the first bond at G_init within 10 % of G0 (0.96 G0 measured at
//    m = 3; it falls to 0.6 G0 at m = 6-8, studies/mixed_mode/README.md), and the crack dissipates
//    G0 per unit area of new crack: the energy the balance leaves unaccounted for (external work -
//    kinetic - strain energy drop) between 1 and 5 mm of new crack (broken-bond measure), divided
//    by that area, within [0.95, 1.15] G0. Measured 1.03-1.07 at m = 3-8: bonds off the crack plane
//    break too, and the area measure weighs bonds by their length while the criterion dissipates
//    the same w_c in each.

#include "coupled_cases.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    std::vector<double> ratios;
    for (const unsigned int n : {64u, 128u})
      {
        auto simulator = make_simulator<2>(mixed_mode_case(false, n, 3, 16, 0, 3e-4, 3.5e-4));
        simulator->run();
        const auto g = simulator->get_energy_history().column("initiation_G");
        ratios.push_back(g.back() / 36e3);
        check_above("lattice " + std::to_string(n) + ": G_init / G0 >= 0.9", ratios.back(), 0.9);
        check_below("lattice " + std::to_string(n) + ": G_init / G0 <= 1.25", ratios.back(), 1.25);
      }
    check("G_init / G0 at delta = 1.46 mm against delta = 2.93 mm", ratios[1], ratios[0], 0.03);

    auto simulator =
      make_simulator<2>(mixed_mode_case(false, 64, 3, 16, 0, 3e-4, 4.2e-4, "critical bond energy"));
    simulator->run();
    const auto &history = simulator->get_energy_history();
    check("bond energy criterion: G_init / G0",
          history.column("initiation_G").back() / 36e3,
          1.,
          0.1);
    const auto area = history.column("crack_area"), total = history.column("total_energy");
    const auto at = [&](const double a) {
      const auto k = std::find_if(area.begin(), area.end(), [a](const double x) { return x >= a; });
      AssertThrow(k != area.end(),
                  ExcMessage("the crack did not grow by " + std::to_string(a) + " m"));
      return k - area.begin();
    };
    const auto   begin = at(1e-3), end = at(5e-3);
    const double dissipated = (total[begin] - total[end]) / (area[end] - area[begin]);
    check_above("bond energy criterion: dissipated energy per new crack area / G0 >= 0.95",
                dissipated / 36e3,
                0.95);
    check_below("bond energy criterion: dissipated energy per new crack area / G0 <= 1.15",
                dissipated / 36e3,
                1.15);
  });
}
