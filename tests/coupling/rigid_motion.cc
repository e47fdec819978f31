// Rigid motion passes through the coupled model untouched: on the ring case (PD centre,
// overlap ring, FE outside, all boundaries free), a rigid translation with a rigid velocity,
// and a small linearised rotation (theta = 1e-12, so the second-order stretch theta^2 / 2 is
// 5e-25, far below round-off), for the strict and weak lambda-mesh and every blending. After 5
// steps (checks and bounds: check_rigid_motion in coupled_cases.h):
//  - every acceleration, FE and PD, below 1e-10 of a_scale = c^2 u_max / h^2 (the acceleration
//    of a node displaced by u_max against fixed neighbours one cell away);
//  - the constraint residuals |g| and |g_dot| at round-off: below 1e-12 of u_max (v_max)
//    times the square root of the number of multipliers.
// Q1 elements and the interpolation N reproduce linear fields exactly and a rigid field has
// no strain in either model, so anything above round-off is a coupling defect.

#include "coupled_cases.h"

using namespace PeriArlequinTests;

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const std::vector<RigidMotion> motions = {
      {"translation", "1e-3; -5e-4", "0.1; 0.05", 1e-3, 0.1},
      {"rotation", "-1e-12*y; 1e-12*x", "0; 0", 2.9e-13, 0}};
    const double c = std::sqrt(69e9 / (2700 * (1 - 0.09)));
    for (const auto &motion : motions)
      for (const std::string method : {"strict", "weak"})
        for (const std::string blending : {"paper", "energy", "force"})
          check_rigid_motion<2>(
            ring_case(0.04, method, blending, motion.displacement, motion.velocity, false, 1e-6),
            motion.name + ", " + method + ", " + blending,
            motion,
            c,
            0.02);
  });
}
