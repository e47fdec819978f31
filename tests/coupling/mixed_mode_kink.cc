// The mixed-mode kink of the paper's section 6.4 through the coupling: the 62.5 mm square
// (plane strain, E = 29 GPa, nu = 0.29, G0 = 36 kJ/m^2) with its edge crack loaded by the
// crack-tip field at K_II / K_I = 1 (G = G0 at 300 us, quasi-static), lattice of 128 sites per
// side (dx = 0.49 mm, m = 3, delta = 1.46 mm), run to 360 us, when the kinked crack has grown
// past the fit range (1 to 5 horizons from the tip). Pure PD, and coupled: PD box around the
// crack and the kink, overlaps of 2 cells, FE cells of 1.95 mm (FE/PD ratio 4), weak
// coupling, force blending.
//  - Kink angle against the maximum-circumferential-stress criterion,
//    theta_c = 2 atan((1 - sqrt(1 + 8 r^2)) / (4 r)) = -53.13 degrees at r = 1, within 11
//    degrees for both runs: at m = 3 the crack runs along the directions the small stencil
//    favours, and the lattice's (1, 1) and (1, 2) directions, -45 and -63.4 degrees, bracket
//    the MTS angle within 10.3 degrees (studies/mixed_mode/README.md). Measured -58.1 pure PD,
//    -63.3 coupled (the (1, 2) direction); the coupled run picks -56.4 with the FE-node
//    lambda-mesh, -63.4 with it and overlaps of 4 cells, -62.4 with the default lambda-mesh and 4
//    cells: which lattice direction wins is not a property of the coupling.
//  - The coupling must not move the answer beyond that scatter: the coupled kink within 7.5
//    degrees of the pure-PD one (the scatter of the PD answer itself at m = 3 is 0 to 7
//    degrees across phase angles and resolutions, studies/mixed_mode/README.md; measured 5.1) and
//    its initiation load G_init / G0 within 0.03 of the pure-PD one (the record interval, 1 us, is
//    0.9 % of G; measured 0.568 against 0.578).

#include "coupled_cases.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const double r = 1.;
    const double mts =
      2. * std::atan((1. - std::sqrt(1. + 8. * r * r)) / (4. * r)) * 180. / numbers::PI;
    std::array<double, 2> angle, g_init;
    for (const bool coupled : {false, true})
      {
        auto simulator = make_simulator<2>(mixed_mode_case(coupled, 128, 3, 32, 45, 3e-4, 3.6e-4));
        simulator->run();
        const auto &history = simulator->get_energy_history();
        angle[coupled]      = history.column("kink_angle").back();
        g_init[coupled]     = history.column("initiation_G").back();
        check(std::string(coupled ? "coupled" : "pure PD") + ": kink angle [deg] against MTS",
              angle[coupled],
              mts,
              11.);
      }
    check("coupled kink angle [deg] against pure PD", angle[1], angle[0], 7.5);
    check("coupled G_init / G0 against pure PD", g_init[1] / 36e3, g_init[0] / 36e3, 0.03);
  });
}
