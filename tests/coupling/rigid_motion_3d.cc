// Rigid motion through the coupled model in 3D: the bar case of coupled_cases.h (PD middle,
// two-cell overlaps, FE ends), all boundaries free. A rigid translation with a rigid velocity and
// a small linearised rotation about an oblique axis (theta = 1e-12: the second-order stretch
// theta^2 / 2 is far below round-off), strict and weak lambda-mesh, energy and force
// blending. After 5 steps:
//  - every acceleration, FE and PD, below 1e-10 of a_scale = c^2 u_max / h^2 (c the 3D
//    longitudinal wave speed, h the FE cell);
//  - |g| and |g_dot| below 1e-12 of u_max (v_max) times the square root of the number of
//    multipliers.
// Q1 elements and N reproduce linear fields exactly and rigid fields carry no strain in
// either model (the PD surfaces do not matter), so anything above round-off is a defect of
// the 3D coupling operators.

#include "coupled_cases.h"

using namespace PeriArlequinTests;

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    // rotation theta (1, 2, 3) / sqrt(14): u = theta x r
    const std::vector<RigidMotion> motions = {
      {"translation", "1e-3; -5e-4; 2e-4", "0.1; 0.05; -0.02", 1e-3, 0.1},
      {"rotation",
       "1e-12*(2*z-3*y)/sqrt(14); 1e-12*(3*x-z)/sqrt(14); 1e-12*(y-2*x)/sqrt(14)",
       "0; 0; 0",
       1e-13,
       0}};
    const double nu = 0.3, c = std::sqrt(69e9 * (1 - nu) / (2700 * (1 + nu) * (1 - 2 * nu)));
    for (const auto &motion : motions)
      for (const std::string method : {"strict", "weak"})
        for (const std::string blending : {"energy", "force"})
          check_rigid_motion<3>(bar_case_3d(method,
                                            blending,
                                            "cg",
                                            false,
                                            motion.displacement,
                                            motion.velocity,
                                            1e-7,
                                            5e-7),
                                motion.name + ", " + method + ", " + blending,
                                motion,
                                c,
                                0.01);
  });
}
