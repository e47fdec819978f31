// Reflection and transmission of wave packets at the overlap (PeriArlequin::WaveReflection):
// a strip one FE cell high (h = 20 mm, plane stress aluminium), pure PD (dx = h / 8, m =
// 3.015) up to an overlap of 5 FE cells, FE beyond; a Gaussian-windowed sinusoid of
// wavelength lambda runs from the pure PD zone into the overlap; R = reflected / incident
// energy from the difference with a pure-PD reference run, T = energy in the FE zone / the
// energy the reference carried past the pure PD zone. Weak coupling, the defaults (energy
// blending, diagonal multiplier solve, lambda-mesh of 2 FE cells, fine-scale damping C = 10).
// The issue's targets: R <= 1 % for lambda >= 6 h, R <= 5 % across the band.
//  - The measurement closes the balance where nothing is meant to be absorbed: lambda = 12 h
//    (resolved by the mesh), damping off, R + T within 0.01 of 1 (measured 0.991; 0.994
//    with the FE-node lambda-mesh), and what is missing is the velocity projection's loss,
//    first order in dt (studies/wave_coupling/README.md): at half the step it is at most 0.6 of
//    that at the step (first order: 0.5; measured 0.53). R and T come from different runs and
//    zones, so this checks both, and energy blending without damping conserves energy as dt -> 0
//    (issue item 5).
//  - Resolved by the FE mesh, lambda = 6 h: R <= 1 % (measured 0.047 %) and T >= 0.9
//    (measured 0.924; the damping takes some of a resolved wave too, as the constraint on the
//    coarser lambda-mesh holds the PD motion to the FE field only in the mean over a hat).
//  - Near the FE cut-off, lambda = 2.5 h and 3 h (the worst of the band): R <= 5 % (measured
//    0.77 % and 3.2 %). The paper's lambda-mesh, the FE nodes, with C = 30 reflects at 2.5 h
//    R > 5 % (measured 13 %): it ties the PD motion to an FE field that cannot propagate
//    there, which is why the default lambda-mesh is coarser.
//  - Beyond the FE cut-off, lambda = 1.5 h < 2 h: the mesh cannot carry it, T <= 0.01, and
//    R <= 5 %: the damping absorbs it.
//  - From the FE side, lambda = 6 h: R <= 1 % and the pure PD zone receives the packet, T
//    within 0.05 of 1 (T counts the PD energy, which for the same field differs from FE's by
//    the strip's surface effect).
// On 2 ranks (the .mpirun=2 output): lambda = 6 h, R and T equal to 1 rank within 1e-9
// relative (round-off of different sums).

#include <periarlequin/postprocess/wave_reflection.h>

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  PeriArlequin::WaveReflection::Result
  measure(const double       wavelength,
          const std::string &coupling,
          const MPI_Comm     communicator,
          const bool         from_fe            = false,
          const double       time_step_fraction = 1)
  {
    PeriArlequin::WaveReflection study;
    study.wavelength         = wavelength;
    study.coupling           = coupling;
    study.from_fe            = from_fe;
    study.time_step_fraction = time_step_fraction;
    return study.measure(communicator);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const std::string defaults = "set Method = weak\n";
    if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      {
        const auto parallel = measure(6, defaults, MPI_COMM_WORLD);
        double     r = 0, t = 0;
        if (is_root())
          {
            const auto serial = measure(6, defaults, MPI_COMM_SELF);
            r                 = std::abs(parallel.reflected / serial.reflected - 1);
            t                 = std::abs(parallel.transmitted / serial.transmitted - 1);
          }
        check_below("lambda = 6 h: R, 2 ranks / 1 rank - 1",
                    Utilities::MPI::max(r, MPI_COMM_WORLD),
                    1e-9);
        check_below("lambda = 6 h: T, 2 ranks / 1 rank - 1",
                    Utilities::MPI::max(t, MPI_COMM_WORLD),
                    1e-9);
        return;
      }
    const std::string undamped = "set Method = weak\nset Fine-scale damping = false\n";
    const auto        balance  = measure(12, undamped, MPI_COMM_WORLD);
    const auto        half_dt  = measure(12, undamped, MPI_COMM_WORLD, false, 0.5);
    report("lambda = 12 h, damping off: R", balance.reflected);
    check("lambda = 12 h, damping off: R + T", balance.reflected + balance.transmitted, 1., 0.01);
    check_below("lambda = 12 h, damping off: (1 - R - T) at dt / 2 over (1 - R - T) at dt",
                (1 - half_dt.reflected - half_dt.transmitted) /
                  (1 - balance.reflected - balance.transmitted),
                0.6);

    const auto resolved = measure(6, defaults, MPI_COMM_WORLD);
    check_below("lambda = 6 h: R <= 0.01", resolved.reflected, 0.01);
    check_above("lambda = 6 h: T >= 0.9", resolved.transmitted, 0.9);

    const auto beyond = measure(1.5, defaults, MPI_COMM_WORLD);
    check_below("lambda = 1.5 h: T <= 0.01", beyond.transmitted, 0.01);
    check_below("lambda = 1.5 h: R <= 0.05", beyond.reflected, 0.05);

    for (const double wavelength : {2.5, 3.})
      {
        const auto cut_off = measure(wavelength, defaults, MPI_COMM_WORLD);
        check_below("lambda = " + std::to_string(wavelength).substr(0, 3) + " h: R <= 0.05",
                    cut_off.reflected,
                    0.05);
      }
    const auto fe_nodes = measure(
      2.5,
      "set Method = weak\nset Damping constant = 30\nsubsection weak\nset Multiplier spacing = 1\nend\n",
      MPI_COMM_WORLD);
    check_above("FE-node lambda-mesh, C = 30, lambda = 2.5 h: R > 0.05", fe_nodes.reflected, 0.05);

    const auto from_fe = measure(6, defaults, MPI_COMM_WORLD, true);
    check_below("from the FE side, lambda = 6 h: R <= 0.01", from_fe.reflected, 0.01);
    check("from the FE side, lambda = 6 h: T", from_fe.transmitted, 1., 0.05);
  });
}
