// A crack driven at its limiting speed towards the edge of an adaptive PD zone grows the zone
// and never stops the run, with the default adaptive settings. The notched glass plate
// 0.1 x 0.04 m (E = 72 GPa, nu = 0.22, rho = 2440 kg/m^3, G0 = 3.8 J/m^2, plane stress,
// lattice 0.625 mm, delta = 2 mm, FE cells 2.5 mm, 50 mm notch along y = 20 mm) under a
// traction of 4 MPa applied suddenly on its long edges (twice that of the branching
// benchmark): the crack starts at about 7 us, runs at 0.5-0.6 c_R (c_R = 3170 m/s), the
// speed at which PD cracks branch, and branches towards the overlap. PD starts on
// [0, 0.06] x [0.0125, 0.0275] only, an overlap band of 5 mm; run to 20 us.
//  - default: damage distance with its automatic Distance and Check interval 10;
//  - trigger only: the strain criterion with a threshold no FE strain reaches, so that every
//    growth comes from the per-step trigger (damage within the trigger distance of an FE
//    cell converts the cells around it in the step it appears);
// both run to the end time ("Damage reached the overlap" would end them with an exception),
// and both grow the zone. Against pure PD on the whole plate (an independent computation
// of the same crack): the leading tip x of both branches at the end within two horizons
// (4 mm: the coupled runs miss pure PD's edge damage under the sudden traction and start the
// crack a few steps later), two branches in each run, and the crack extension within 10 %.
// The default run on 2 ranks converts the same cells and breaks the same bonds at every
// record as on 1 rank (exact), the energies agree to 1e-10 (sums in another order).

#include "../tests.h"
#include "plates.h"

using namespace PeriArlequinTests;

std::string
fast_crack_text(const std::string &zone)
{
  std::ostringstream text;
  if (zone == "pure PD")
    text << notched_glass_plate("0, 0 : 0.1, 0.04");
  else
    text << notched_glass_plate("0, 0.0125 : 0.06, 0.0275")
         << "subsection Coupling\n  set Method = weak\n  set Blending = force\n"
         << "  set Overlap width = 0.005\n  set Damping constant = 10\nend\n"
         << "subsection Adaptive PD zone\n"
         << (zone == "default" ? "  set Conversion criterion = damage distance\n" :
                                 "  set Conversion criterion = strain\n"
                                 "  subsection strain\n    set Strain = 1\n  end\n")
         << "end\n";
  text << opposite_y_tractions(4e6, 2)
       << "subsection Time\n  set Time step = 4e-8\n  set End time = 2e-5\nend\n"
       << quiet_output() << "subsection Output\n  set Energy interval = 25\nend\n"
       << "subsection Postprocess\n  set List of postprocessors = energies, cracks, zone sizes\n"
       << "end\n";
  return text.str();
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    // The default adaptive run on all ranks, the others on rank 0 alone.
    auto parallel = make_simulator<2>(fast_crack_text("default"), MPI_COMM_WORLD);
    parallel->run();
    check_above("default settings: cells converted (all ranks)",
                parallel->get_energy_history().column("converted_cells").back(),
                0.5);
    double                        mpi_difference = 0, energy_difference = 0;
    std::map<std::string, double> figures;
    if (is_root())
      {
        auto serial = make_simulator<2>(fast_crack_text("default"), MPI_COMM_SELF);
        serial->run();
        auto trigger_only = make_simulator<2>(fast_crack_text("trigger only"), MPI_COMM_SELF);
        trigger_only->run();
        auto pure = make_simulator<2>(fast_crack_text("pure PD"), MPI_COMM_SELF);
        pure->run();

        const auto &a = parallel->get_energy_history(), &b = serial->get_energy_history();
        mpi_difference =
          largest_column_difference(a,
                                    b,
                                    {"broken_bonds", "converted_cells", "pd_particles"},
                                    false);
        energy_difference = largest_column_difference(a, b, {"total_energy", "crack_area"}, true);

        const auto &reference = pure->get_energy_history();
        const auto  tip_x     = [](const PeriArlequin::EnergyHistory &h) {
          return std::max(h.column("branch_0_x").back(), h.column("branch_1_x").back());
        };
        // The crack's speed in pure PD from 10 to 20 us (leading tip, records every 1 us).
        const auto   x0 = reference.column("branch_0_x");
        const double speed =
          (x0.back() - x0[x0.size() - 11]) / (reference.column("time").back() - 1e-5);
        const double mu = 72e9 / (2 * 1.22), c_s = std::sqrt(mu / 2440);
        // Rayleigh speed of plane stress (nu' = nu / (1 + nu)), Viktorov's approximation.
        const double nu = 0.22 / 1.22, c_r = c_s * (0.862 + 1.14 * nu) / (1 + nu);
        report("pure PD crack speed 10-20 us / c_R", speed / c_r);
        figures["pure PD crack speed over c_R"] = speed / c_r;
        for (const auto &[name, run] :
             {std::pair<std::string, PeriArlequin::Simulator<2> *>{"default", serial.get()},
              {"trigger only", trigger_only.get()}})
          {
            const auto &h                             = run->get_energy_history();
            figures[name + ": cells converted"]       = h.column("converted_cells").back();
            figures[name + ": |tip x - pure PD| [m]"] = std::abs(tip_x(h) - tip_x(reference));
            figures[name + ": branches"]              = h.column("branches").back();
            figures[name + ": crack extension / pure PD - 1"] = std::abs(
              h.column("crack_extension").back() / reference.column("crack_extension").back() - 1);
          }
        figures["pure PD: branches"] = reference.column("branches").back();
      }
    const auto broadcast = [](const double x) {
      return Utilities::MPI::broadcast(MPI_COMM_WORLD, x, 0);
    };
    check_above("pure PD crack speed over c_R (the crack runs near its limit)",
                broadcast(figures["pure PD crack speed over c_R"]),
                0.45);
    check("pure PD: branches at the end", broadcast(figures["pure PD: branches"]), 2, 0);
    for (const std::string name : {"default", "trigger only"})
      {
        check_above(name + ": cells converted",
                    broadcast(figures[name + ": cells converted"]),
                    0.5);
        check_below(name + ": |leading tip x - pure PD| [m] (two horizons)",
                    broadcast(figures[name + ": |tip x - pure PD| [m]"]),
                    4e-3);
        check(name + ": branches at the end", broadcast(figures[name + ": branches"]), 2, 0);
        check_below(name + ": |crack extension / pure PD - 1|",
                    broadcast(figures[name + ": crack extension / pure PD - 1"]),
                    0.1);
      }
    check_below("largest |broken bonds, converted cells, particles: all ranks - rank 0 alone|",
                broadcast(mpi_difference),
                1e-15);
    check_below("largest relative |total energy, crack area: all ranks - rank 0 alone|",
                broadcast(energy_difference),
                1e-10);
  });
}
