// A crack that starts far from the PD zone: a compressive pulse, reflected as tension at the
// far free edge of a glass strip, spalls it there. Strip 100 x 10 mm (E = 72 GPa, nu = 0.22,
// rho = 2440 kg/m^3, G0 = 3.8 J/m^2, plane stress; lattice 0.5 mm, m = 3.015, delta = 1.51 mm;
// FE cells 2.5 mm), a pressure pulse P sin^2(pi t / 4 us), P = 25 MPa, on its left edge: its
// strain, 3.5e-4, is 1.6 times the critical stretch (2.2e-4), so the reflected tension
// breaks the strip at about half the pulse length (c 4 us / 2 = 11 mm) from the far edge,
// at about 21 us. The adaptive run starts with PD on [40, 50] mm only (band 5 mm, weak
// coupling, force blending) and Conversion criterion = damage distance, strain with every
// other adaptive setting at its default; run to 23 us. Against pure PD on the whole strip (an
// independent computation of the same strip):
//  - the adaptive run reaches the end time (no "Damage reached the overlap");
//  - spall onset, the first broken bond beyond x = 50 mm: at the same time within half the
//    settling time (the new particles follow the FE motion while their settling force is
//    above half its start; 1.35 us here, measured 0.75 us), at the same place (mean x of the
//    damaged particles then) within two horizons;
//  - the broken bonds beyond x = 50 mm at the end within 10 % (the tolerance of the
//    broken-bond energy between adaptive and pure PD runs).
// Without settling (Settling time = -1) the strain criterion converts the cells at the loaded
// edge under the pulse, the new particles overshoot the PD state of the edges (in PD the first
// layer under a traction strains twice the continuum) and break bonds next to the band: the
// run stops with "Damage reached the overlap" within 5 us, and its message points to the
// settling time (the start-up note on it). Same checks on 2 ranks, where the
// adaptive run repartitions after every conversion (Load imbalance tolerance = 0), so the
// settling forces travel with their particles: it breaks the same bonds beyond mid-length and
// starts the spall in the same step as on rank 0 alone (exact).

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  std::string
  spall_strip_text(const std::string &zone)
  {
    std::ostringstream text;
    text << "set Dimension = 2\n"
         << "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = 0.1, 0.01\n"
         << "  set Subdivisions = 40, 4\nend\n"
         << "subsection Material\n  set Young's modulus = 72e9\n  set Poisson's ratio = 0.22\n"
         << "  set Density = 2440\n  set Two-dimensional model = plane stress\nend\n"
         << "subsection Peridynamics\n  set Lattice spacing = 5e-4\n  set Horizon factor = 3.015\n"
         << "  set Fracture = true\n  set Critical energy release rate = 3.8\n";
    if (zone == "pure PD")
      text << "  set Region = 0, 0 : 0.1, 0.01\nend\n";
    else
      text << "  set Region = 0.04, 0 : 0.05, 0.01\nend\n"
           << "subsection Coupling\n  set Method = weak\n  set Blending = force\n"
           << "  set Overlap width = 0.005\nend\n"
           << "subsection Adaptive PD zone\n  set Conversion criterion = damage distance, strain\n"
           << "  set Load imbalance tolerance = 0\n"
           << (zone == "no settling" ? "  set Settling time = -1\n" : "") << "end\n";
    text << "subsection Boundary conditions\n  subsection Boundary 0\n    set Type = traction\n"
         << "    subsection Function\n      set Function constants = P=25e6, tau=4e-6\n"
         << "      set Function expression = t < tau ? P * sin(pi * t / tau)^2 : 0; 0\n"
         << "    end\n  end\nend\n"
         << "subsection Time\n  set Time step = 2.5e-8\n  set End time = 2.3e-5\nend\n"
         << quiet_output();
    return text.str();
  }

  /** The first break beyond x = 50 mm and the broken bonds there at the end. */
  struct Spall
  {
    double onset_time = -1, onset_x = 0, broken_bonds = 0;
  };

  Spall
  run_to_end(PeriArlequin::Simulator<2> &simulator)
  {
    Spall spall;
    simulator.setup();
    const MPI_Comm communicator = simulator.get_pd_zone()->get_communicator();
    // Damaged particles beyond the middle: their number and the sum of their x.
    const auto far_damage = [&]() {
      const auto &pd     = *simulator.get_pd_zone();
      const auto  damage = pd.get_bonds().damage();
      const auto  x      = pd.reference_positions();
      double      count = 0, sum_x = 0;
      for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
        if (x[i][0] > 0.05 && damage[i] > 0)
          {
            count += 1;
            sum_x += x[i][0];
          }
      return std::make_pair(Utilities::MPI::sum(count, communicator),
                            Utilities::MPI::sum(sum_x, communicator));
    };
    while (simulator.get_step_number() < simulator.get_n_steps())
      {
        simulator.advance();
        if (spall.onset_time < 0)
          {
            const auto [count, sum_x] = far_damage();
            if (count > 0)
              {
                spall.onset_time = simulator.get_time();
                spall.onset_x    = sum_x / count;
              }
          }
      }
    const auto &pd     = *simulator.get_pd_zone();
    const auto  x      = pd.reference_positions();
    const auto &bonds  = pd.get_bonds();
    double      broken = 0;
    for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
      if (x[i][0] > 0.05)
        for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
          broken += bonds.state[n] == PeriArlequin::BondFamilies<2>::broken;
    spall.broken_bonds = Utilities::MPI::sum(broken, communicator);
    return spall;
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    auto         reference = make_simulator<2>(spall_strip_text("pure PD"));
    const Spall  pure_pd   = run_to_end(*reference);
    auto         adaptive  = make_simulator<2>(spall_strip_text("adaptive"));
    const Spall  grown     = run_to_end(*adaptive);
    const double horizon   = 3.015 * 5e-4;
    // The automatic settling time: ten times a horizon over the longitudinal wave speed of
    // plane stress.
    const double wave_speed    = std::sqrt(72e9 / (2440 * (1 - 0.22 * 0.22)));
    const double settling_time = 10 * horizon / wave_speed;

    check("pure PD: the strip spalls", pure_pd.onset_time > 0, 1, 0);
    check("adaptive: reaches the end time", adaptive->get_time() > 2.3e-5 * (1 - 1e-9), 1, 0);
    check("spall onset time [s]", grown.onset_time, pure_pd.onset_time, 0.5 * settling_time);
    check("spall onset place x [m]", grown.onset_x, pure_pd.onset_x, 2 * horizon);
    check("broken bonds beyond x = 50 mm at the end, adaptive / pure PD",
          grown.broken_bonds / pure_pd.broken_bonds,
          1,
          0.1);

    if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      {
        Spall alone;
        if (is_root())
          {
            auto serial = make_simulator<2>(spall_strip_text("adaptive"), MPI_COMM_SELF);
            alone       = run_to_end(*serial);
          }
        const auto broadcast = [](const double x) {
          return Utilities::MPI::broadcast(MPI_COMM_WORLD, x, 0);
        };
        check_above("all ranks: repartitions", adaptive->n_repartitions(), 0.5);
        check("all ranks against rank 0 alone: spall onset time [s]",
              grown.onset_time,
              broadcast(alone.onset_time),
              0);
        check("all ranks against rank 0 alone: broken bonds beyond x = 50 mm",
              grown.broken_bonds,
              broadcast(alone.broken_bonds),
              0);
      }

    auto        unsettled = make_simulator<2>(spall_strip_text("no settling"));
    std::string message;
    try
      {
        run_to_end(*unsettled);
      }
    catch (const std::exception &error)
      {
        // Words only: the message is wrapped into lines.
        std::istringstream words(error.what());
        for (std::string word; words >> word;)
          message += word + ' ';
      }
    check("without settling: the run stops with 'Damage reached the overlap'",
          message.find("Damage reached the overlap at t = ") != std::string::npos,
          1,
          0);
    check("without settling: the message names the settling time",
          message.find("(Adaptive PD zone/Settling time;") != std::string::npos,
          1,
          0);
    check_below("without settling: stop time [s]", unsettled->get_time(), 5e-6);
  });
}
