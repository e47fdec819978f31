// Bond stretches in the overlap and the slave layer under a suddenly applied load, against
// the FE field there and against a pure-PD plate on the same lattice. The glass plate of the
// branching benchmark without a crack (glass_plate_case: 100 x 40 mm, traction 2 MPa applied
// at t = 0 on the top and bottom edges, nominal strain sigma / E = 2.8e-5), lattice
// 0.625 mm (delta = 2 mm), run to 30 us (the waves cross the plate about four times).
// Coupled: PD strip |y - 20 mm| <= h, overlaps above and below, FE beyond, weak coupling
// with fine-scale damping; the alpha = 1 edges 5 mm from the loaded edges in every variant.
// The bonds measured are those with both ends in the band h < |y - 20 mm| < 16 mm: the
// overlap and the slave layer beyond the alpha = 1 edge, 2 horizons short of the loaded
// edges (where the pure-PD plate's surface layer carries the traction).
//  - Against the FE field: the largest stretch over all steps of those bonds, divided by the
//    largest stretch the FE displacement interpolated at their ends gives them (the slaves
//    follow it exactly): what the particles' own motion adds.
//  - Against pure PD: the same, divided by that of the same bonds in the pure-PD plate.
// Force blending (the blending for fracture): bounds 1.1 and 1.2 (measured 0.99-1.02 and
// 0.87-0.96; the coarse FE mesh, dispersive behind the sharp front, and the lattice
// overshoot differently by some percent).
// Energy blending is reported: its forces carry ghost forces proportional to grad alpha
// that nothing balances locally, and on the particles next to the slaves, whose weight
// 1 - alpha is small, they move the particles against the FE field (measured 1.66-1.90x the
// FE field's stretch at overlaps of 2-4 cells). Before the slave threshold, the particles
// next to the alpha = 1 edge carried a floored mass for a tiny stiffness: they lagged the FE
// field, stretched the bonds to the slaves 3.5x as far as pure PD did and broke them in the
// branching case. Variations: FE/PD size ratios 8 and 4 (cells 5 and 2.5 mm), overlaps of
// 10 and 12.5 mm (2 to 5 cells).

#include <periarlequin/coupling/interpolation_operator.h>
#include <periarlequin/pd/bond_families.h>

#include "coupled_cases.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

namespace
{
  /** Does @p x lie in the band between the PD strip |y - 20 mm| <= @p half_strip and 16 mm? */
  bool
  in_band(const Point<2> &x, const double half_strip)
  {
    const double distance = std::abs(x[1] - 0.02);
    return distance > half_strip && distance < 0.016;
  }

  /** The largest stretch of the intact bonds with both ends in the band, by @p u. */
  double
  band_stretch(const PDZone<2> &pd, ArrayView<const Tensor<1, 2>> u, const double half_strip)
  {
    const BondFamilies<2> &bonds   = pd.get_bonds();
    const auto             x       = pd.reference_positions();
    double                 largest = 0;
    for (unsigned int i = 0; i < bonds.n_owned; ++i)
      for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
        {
          const unsigned int j = bonds.neighbor(i, n);
          if (bonds.state[n] == BondFamilies<2>::broken || !in_band(x[i], half_strip) ||
              !in_band(x[j], half_strip))
            continue;
          const auto &entry = bonds.stencil[bonds.stencil_index[n]];
          largest =
            std::max(largest, BondFamilies<2>::extension(entry, u[j] - u[i]).first / entry.length);
        }
    return largest;
  }

  /** Largest stretch in the band over the run: PD displacements, FE field (coupled only). */
  std::pair<double, double>
  largest_band_stretch(const bool         coupled,
                       const double       cell,
                       const double       half_strip,
                       const std::string &blending)
  {
    auto simulator = make_simulator<2>(glass_plate_case(coupled,
                                                        6.25e-4,
                                                        cell,
                                                        half_strip,
                                                        0.015 - half_strip,
                                                        2e6,
                                                        5e-8,
                                                        3e-5,
                                                        blending));
    simulator->setup();
    const PDZone<2>          &pd = *simulator->get_pd_zone();
    InterpolationOperator<2>  interpolation;
    std::vector<unsigned int> band;
    for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
      if (in_band(pd.reference_positions()[i], half_strip))
        band.push_back(i);
    if (coupled)
      interpolation.reinit(simulator->get_fe_zone(), pd, band);
    std::vector<Tensor<1, 2>> fe_field(pd.reference_positions().size());
    double                    largest_pd = 0, largest_fe = 0;
    while (simulator->get_step_number() < simulator->get_n_steps())
      {
        simulator->advance();
        largest_pd =
          std::max(largest_pd, band_stretch(pd, pd.get_state().displacements(), half_strip));
        if (coupled)
          {
            const auto &u = simulator->get_displacement();
            u.update_ghost_values();
            for (unsigned int r = 0; r < band.size(); ++r)
              fe_field[band[r]] = interpolation.interpolate(u, r);
            largest_fe =
              std::max(largest_fe, band_stretch(pd, make_array_view(fe_field), half_strip));
          }
      }
    return {largest_pd, largest_fe};
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const double nominal = 2e6 / 72e9;
    for (const double half_strip : {0.005, 0.0025})
      {
        const double pure_pd = largest_band_stretch(false, 0.005, half_strip, "force").first;
        report("pure PD, band from " + std::to_string(half_strip * 1e3).substr(0, 3) +
                 " mm: largest stretch / (sigma / E)",
               pure_pd / nominal);
        for (const std::string blending : {"force", "energy"})
          for (const double cell : {0.005, 0.0025})
            {
              if (half_strip < 0.005 && cell > 0.0025)
                continue;
              const auto [coupled, fe] = largest_band_stretch(true, cell, half_strip, blending);
              std::ostringstream name;
              name << blending << " blending, FE cell " << cell * 1e3 << " mm, overlap "
                   << (0.015 - half_strip) * 1e3 << " mm: largest stretch in the band / ";
              report(name.str() + "(sigma / E), FE field", fe / nominal);
              if (blending == "force")
                {
                  check_below(name.str() + "the FE field's", coupled / fe, 1.1);
                  check_below(name.str() + "pure PD's", coupled / pure_pd, 1.2);
                }
              else
                {
                  report(name.str() + "the FE field's", coupled / fe);
                  report(name.str() + "pure PD's", coupled / pure_pd);
                }
            }
      }
  });
}
