#ifndef periarlequin_tests_reflection_study_h
#define periarlequin_tests_reflection_study_h

#include "coupled_cases.h"

/**
 * The reflection study of the paper's section 6.1 at half resolution (coarse_wave_case:
 * parameter_files/arlequin_wave_2d_coarse.prm), run at one time step: energy left in the pure
 * PD zone at t = 5e-4 s over the initial energy, for the bad coupling (fig. 8, no damping),
 * the weak coupling with fine-scale damping and, if asked, the strict coupling with damping
 * (diagonal multiplier solve, energy blending). The 6 cm component of the pulse (1.5 FE
 * cells) cannot enter the FE zone: the coupling must absorb it or it comes back.
 *
 * Part of that energy is not reflected at all: in the 8 cm plate the 6 cm component splits
 * into slow plate modes, and the pure-PD reference (PD on the whole plate) itself keeps
 * about 4 % in the pure PD zone at 5e-4 s, which bounds the raw ratio bad / weak from above
 * (by about 0.52 / 0.041 = 12.7). So the study asserts on the energy the coupling adds to the
 * reference's, the "excess", as well as on the raw ratio. The
 * reference runs at dt = 1e-7 s for both time steps: velocity Verlet's phase error,
 * (omega dt)^2 / 24, is 1.3e-4 there for the 6 cm component (omega = 5.5e5 rad/s), far
 * below the bounds below.
 *
 * Bounds (measured at dt = 1e-7 s / 1e-8 s):
 *  - energy left, bad / weak + damping, at least 10 (the factor; measured 11.2 /
 *    10.5, below the 12.7 that a weak coupling reflecting nothing would reach);
 *  - weak + damping: excess below 1 % of the initial energy (measured 0.53 % / 0.85 %): the
 *    order of the paper's "less than 1 % left" criterion;
 *  - bad: excess above 10 % (measured 48 % / 48 %: it sends back most of the 6 cm
 *    component), so the study can tell the two apart;
 *  - excess of bad over excess of weak + damping at least 10 (the factor; measured
 *    90 / 56);
 *  - strict: reported, and asserted to sit between weak + damping and bad (measured excess
 *    18 % at 1e-7 s).
 */
namespace PeriArlequinTests
{
  inline double
  energy_left_in_pure_pd(const PeriArlequin::Simulator<2> &simulator)
  {
    const auto &history = simulator.get_energy_history();
    return history.column("pure_pd_energy").back() / history.column("total_energy").front();
  }

  inline void
  reflection_study(const double time_step, const bool with_strict)
  {
    const auto run = [](const std::string &method, const bool damping, const double dt) {
      auto simulator = make_simulator<2>(coarse_wave_case(method, damping, dt));
      simulator->run();
      return energy_left_in_pure_pd(*simulator);
    };
    const double reference = run("none", false, 1e-7);
    report("pure-PD reference (dt = 1e-7 s): energy left in pure PD / initial", reference);

    const double bad  = run("bad", false, time_step);
    const double weak = run("weak", true, time_step);
    report("bad: energy left in pure PD / initial", bad);
    report("weak + damping: energy left in pure PD / initial", weak);
    check_above("energy left, bad / weak + damping", bad / weak, 10.);
    check_below("weak + damping: excess over the reference", weak - reference, 1e-2);
    check_above("bad: excess over the reference", bad - reference, 0.1);
    check_above("excess over the reference, bad / weak + damping",
                (bad - reference) / (weak - reference),
                10.);
    if (with_strict)
      {
        const double strict = run("strict", true, time_step);
        report("strict + damping: energy left in pure PD / initial", strict);
        check_above("strict + damping: excess over the reference, above weak + damping's",
                    strict - weak,
                    0.);
        check_above("strict + damping: excess over the reference, below bad's", bad - strict, 0.);
      }
  }
} // namespace PeriArlequinTests

#endif
