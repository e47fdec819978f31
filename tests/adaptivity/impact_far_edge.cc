// An impact-driven plate whose far free edge cracks under reflected tension, away from any
// damage the adaptive zone follows. Steel plate 100 x 200 mm (E = 190 GPa, nu = 0.3, 8000
// kg/m^3, G0 = 22.17 kJ/m^2, plane strain; lattice 1 mm, m = 3.015; FE cells 5 mm), two edge
// notches 50 mm long and 50 mm apart, the edge between them struck at 32 m/s (three particle
// layers moved at that velocity), run to 90 us. Pure PD (the independent reference) starts a
// crack at the far edge x = 100 mm between the notches (y about 100 mm) besides the two
// cracks from the notch tips. The adaptive runs start with PD on the notches and the struck
// edge, [0, 55] x [70, 130] mm, a band of 10 mm (weak coupling, force blending), other
// adaptive settings at their defaults:
//  - Conversion criterion = damage distance: the far edge stays FE, its strain passes the
//    critical stretch (the FE strain check warns), and a bond next to the overlap where the
//    PD zone meets that edge breaks: the run stops before the end with "Damage reached the
//    overlap", and the message says why the growth could not act (the FE strain past the
//    critical stretch) and what to add (the strain criterion);
//  - Conversion criterion = damage distance, strain: reaches the end; its broken-bond energy
//    at the end within 10 % of pure PD's (the tolerance of the adaptive studies; measured
//    1.5 %), and it has the far-edge crack: the mean y of the particles with damage above
//    0.35 beyond x = 93 mm (two horizons from the edge) and |y - 100 mm| < 50 mm within two
//    horizons (6 mm) of pure PD's (measured 0.14 mm).
// On 2 ranks the same checks, and the strain run's broken-bond energy equals rank 0 alone's
// within 1e-9 relative (the sums of several ranks add in another order; measured equal to
// ten digits).

#include "../tests.h"
#include "plates.h"

using namespace PeriArlequinTests;

namespace
{
  std::string
  impact_plate_text(const std::string &criterion)
  {
    std::ostringstream text;
    if (criterion.empty())
      text << struck_steel_plate("0, 0 : 0.1, 0.2");
    else
      text << struck_steel_plate("0, 0.07 : 0.055, 0.13")
           << "subsection Coupling\n  set Method = weak\n  set Blending = force\n"
           << "  set Overlap width = 0.01\nend\n"
           << "subsection Adaptive PD zone\n  set Conversion criterion = " << criterion
           << "\nend\n";
    text << "subsection Time\n  set Time step = 1e-7\n  set End time = 9e-5\nend\n"
         << quiet_output() << "subsection Output\n  set Energy interval = 300\nend\n"
         << "subsection Postprocess\n  set List of postprocessors = energies, cracks\nend\n";
    return text.str();
  }

  /** The mean y of the cracked particles (damage > 0.35) at the far edge between the notches. */
  double
  far_edge_crack_y(const PeriArlequin::Simulator<2> &simulator)
  {
    const auto  &pd      = *simulator.get_pd_zone();
    const auto   damage  = pd.get_bonds().damage();
    const auto   x       = pd.reference_positions();
    const double reach   = 2 * 3.015e-3;
    double       sums[2] = {0, 0};
    for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
      if (damage[i] > 0.35 && x[i][0] > 0.1 - reach && std::abs(x[i][1] - 0.1) < 0.05)
        {
          sums[0] += 1;
          sums[1] += x[i][1];
        }
    const MPI_Comm communicator = pd.get_communicator();
    const double   count        = Utilities::MPI::sum(sums[0], communicator);
    return count > 0 ? Utilities::MPI::sum(sums[1], communicator) / count : -1;
  }

  double
  final_broken_bond_energy(const PeriArlequin::Simulator<2> &simulator)
  {
    return simulator.get_energy_history().column("broken_bond_energy").back();
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const double horizon = 3.015e-3;
    auto         pure_pd = make_simulator<2>(impact_plate_text(""));
    pure_pd->run();
    const double reference_y = far_edge_crack_y(*pure_pd);
    check("pure PD: the far edge cracks", reference_y > 0, 1, 0);

    auto        outrun = make_simulator<2>(impact_plate_text("damage distance"));
    std::string message;
    try
      {
        outrun->run();
      }
    catch (const std::exception &error)
      {
        // Words only: the message is wrapped into lines.
        std::istringstream words(error.what());
        for (std::string word; words >> word;)
          message += word + ' ';
      }
    const auto says = [&](const std::string &text) {
      return message.find(text) != std::string::npos;
    };
    check("damage distance: the run stops with 'Damage reached the overlap'",
          says("Damage reached the overlap at t = "),
          1,
          0);
    check_below("damage distance: stop time / end time", outrun->get_time() / 9e-5, 1);
    check("damage distance: the message names the FE strain past the critical stretch",
          says("times the critical stretch at t = "),
          1,
          0);
    check("damage distance: the message advises the strain criterion",
          says("Conversion criterion = damage distance, strain"),
          1,
          0);

    auto adaptive = make_simulator<2>(impact_plate_text("damage distance, strain"));
    adaptive->run();
    check("damage distance, strain: reaches the end time",
          adaptive->get_time() > 9e-5 * (1 - 1e-9),
          1,
          0);
    check("damage distance, strain: broken-bond energy at the end / pure PD",
          final_broken_bond_energy(*adaptive) / final_broken_bond_energy(*pure_pd),
          1,
          0.1);
    check("damage distance, strain: far-edge crack mean y [m]",
          far_edge_crack_y(*adaptive),
          reference_y,
          2 * horizon);

    if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      {
        double alone = 0;
        if (is_root())
          {
            auto serial =
              make_simulator<2>(impact_plate_text("damage distance, strain"), MPI_COMM_SELF);
            serial->run();
            alone = final_broken_bond_energy(*serial);
          }
        check("all ranks against rank 0 alone: broken-bond energy at the end, relative",
              final_broken_bond_energy(*adaptive) /
                Utilities::MPI::broadcast(MPI_COMM_WORLD, alone, 0),
              1,
              1e-9);
      }
  });
}
