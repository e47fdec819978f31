// Reflection and transmission of wave packets at the overlap (PeriArlequin::WaveReflection):
// a strip one FE cell high (h = 20 mm, plane stress aluminium), pure PD (dx = h / 8, m =
// 3.015) up to an overlap of 5 FE cells, FE beyond; a Gaussian-windowed sinusoid of
// wavelength lambda runs from the pure PD zone into the overlap; R = reflected / incident
// energy from the difference with a pure-PD reference run, T = energy in the FE zone / the
// energy the reference carried past the pure PD zone. Weak coupling, the defaults (energy
// blending, diagonal multiplier solve, fine-scale damping C = 30).
//  - The measurement closes the balance where nothing is meant to be absorbed: lambda = 12 h
//    (resolved by the mesh), damping off, R + T within 0.01 of 1 (measured 0.994: the
//    velocity projection's first-order-in-dt loss, doc/wave_study.md). R and T come from
//    different runs and zones, so this checks both.
//  - Resolved by the FE mesh, lambda = 6 h: R <= 1 % (the issue's target; measured 0.015 %)
//    and T >= 0.9 (measured 0.947; the damping takes some of a resolved wave too, as the FE
//    field interpolates the PD motion only to O(h^2)).
//  - Beyond the FE cut-off, lambda = 1.5 h < 2 h: the mesh cannot carry it, T <= 0.01
//    (measured 8e-4), and R <= 5 % (the target; measured 2.3 %): the damping absorbs it.
//  - Near the cut-off, lambda = 2.5 h: R below 0.2 (measured 0.131). The 5 % target is not
//    met there: the constraint ties the PD motion to an FE field that cannot propagate at
//    this wavelength (with exact multipliers R = 0.37), doc/wave_study.md.
//  - From the FE side, lambda = 6 h: R <= 1 % (measured 0.025 %) and the pure PD zone
//    receives the packet, T within 0.05 of 1 (measured 0.998; T counts the PD energy, which
//    for the same field differs from FE's by the strip's surface effect).
// On 2 ranks (the .mpirun=2 output): lambda = 6 h, R and T equal to 1 rank within 1e-9
// relative (round-off of different sums).

#include "../tests.h"

#include <periarlequin/postprocess/wave_reflection.h>

using namespace PeriArlequinTests;

namespace
{
  PeriArlequin::WaveReflection::Result
  measure(const double       wavelength,
          const std::string &coupling,
          const MPI_Comm     communicator,
          const bool         from_fe = false)
  {
    PeriArlequin::WaveReflection study;
    study.wavelength = wavelength;
    study.coupling   = coupling;
    study.from_fe    = from_fe;
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
        check_below("lambda = 6 h: R, 2 ranks / 1 rank - 1", Utilities::MPI::max(r, MPI_COMM_WORLD), 1e-9);
        check_below("lambda = 6 h: T, 2 ranks / 1 rank - 1", Utilities::MPI::max(t, MPI_COMM_WORLD), 1e-9);
        return;
      }
    const auto balance = measure(12, "set Method = weak\nset Fine-scale damping = false\n", MPI_COMM_WORLD);
    report("lambda = 12 h, damping off: R", balance.reflected);
    check("lambda = 12 h, damping off: R + T", balance.reflected + balance.transmitted, 1., 0.01);

    const auto resolved = measure(6, defaults, MPI_COMM_WORLD);
    check_below("lambda = 6 h: R <= 0.01", resolved.reflected, 0.01);
    check_above("lambda = 6 h: T >= 0.9", resolved.transmitted, 0.9);

    const auto beyond = measure(1.5, defaults, MPI_COMM_WORLD);
    check_below("lambda = 1.5 h: T <= 0.01", beyond.transmitted, 0.01);
    check_below("lambda = 1.5 h: R <= 0.05", beyond.reflected, 0.05);

    const auto cut_off = measure(2.5, defaults, MPI_COMM_WORLD);
    check_below("lambda = 2.5 h: R < 0.2", cut_off.reflected, 0.2);

    const auto from_fe = measure(6, defaults, MPI_COMM_WORLD, true);
    check_below("from the FE side, lambda = 6 h: R <= 0.01", from_fe.reflected, 0.01);
    check("from the FE side, lambda = 6 h: T", from_fe.transmitted, 1., 0.05);
  });
}
