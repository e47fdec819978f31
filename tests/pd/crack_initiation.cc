// Initiation, growth and kink angle of CrackInitiation from cracked particles of known
// geometry (a horizon of 3 mm, tip at the origin, pre-crack pointing along +x):
//  - record 0: the pre-crack's particles along the negative x axis (with damage, so cracked)
//    and 10 broken bonds near the tip: the reference state, no kink, no initiation;
//  - record 1 (t = 1): the same broken-bond count, one new cracked particle 2 mm from the
//    tip at -40 degrees: nothing has initiated (no new broken bond), growth has not happened
//    (2 mm < one horizon), no kink (fewer than three particles to fit);
//  - record 2 (t = 2): one more broken bond near the tip: initiation at t = 2;
//  - record 3 (t = 3): a crack two particles wide along the ray at -40 degrees (pairs
//    0.5 mm on either side of the ray, every 1 mm from 1 to 20 mm), plus new cracked
//    particles that must be ignored (behind the tip, along the pre-crack's faces at
//    170 degrees). Growth at t = 3 (particles beyond 3 mm); the kink angle is the ray's,
//    -40 degrees, to round-off (1e-10 degrees): the band is symmetric about the ray, so
//    the principal axis of its second moment about the tip is the ray itself; the fit
//    range (1 to 5 horizons, 3 to 15 mm) holds the pairs from 3 to 14 mm, 24 particles.
// The same on every rank (the tracker works on gathered particles): run on one.

#include <periarlequin/postprocess/crack_diagnostics.h>

#include <cmath>

#include "../tests.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    using Particle             = CrackInitiation<2>::CrackedParticle;
    const double       horizon = 3e-3;
    CrackInitiation<2> initiation(Point<2>(), 0., horizon, {{horizon, 5. * horizon}});

    std::vector<Particle> cracked;
    types::particle_index id = 0;
    for (unsigned int k = 0; k < 30; ++k)
      cracked.push_back({id++, Point<2>(-0.5e-3 - k * 1e-3, 0.5e-3)});
    initiation.update(0., cracked, 10);

    const double       kink = -40. * numbers::PI / 180.;
    const Tensor<1, 2> along({std::cos(kink), std::sin(kink)});
    const Tensor<1, 2> across({-std::sin(kink), std::cos(kink)});
    cracked.push_back({id++, Point<2>(2e-3 * along)});
    initiation.update(1., cracked, 10);
    check_above("record 1: initiation not yet (NaN)",
                std::isnan(initiation.initiation_time()),
                0.5);
    check_above("record 1: growth not yet (NaN)", std::isnan(initiation.growth_time()), 0.5);
    check_above("record 1: no kink angle (NaN)", std::isnan(initiation.kink_angle()), 0.5);

    initiation.update(2., cracked, 11);
    check("record 2: initiation time", initiation.initiation_time(), 2., 0.);
    check_above("record 2: growth not yet (NaN)", std::isnan(initiation.growth_time()), 0.5);

    for (unsigned int k = 1; k <= 20; ++k)
      for (const double side : {-0.5e-3, 0.5e-3})
        cracked.push_back({id++, Point<2>(k * 1e-3 * along + side * across)});
    const double behind = 170. * numbers::PI / 180.;
    for (unsigned int k = 2; k <= 8; ++k)
      cracked.push_back(
        {id++, Point<2>(k * 1e-3 * Tensor<1, 2>({std::cos(behind), std::sin(behind)}))});
    initiation.update(3., cracked, 40);
    check("record 3: initiation time unchanged", initiation.initiation_time(), 2., 0.);
    check("record 3: growth time", initiation.growth_time(), 3., 0.);
    check("record 3: kink angle [deg]", initiation.kink_angle() * 180. / numbers::PI, -40., 1e-10);
    check("record 3: fitted particles", initiation.n_fitted_particles(), 24, 0);
  });
}
