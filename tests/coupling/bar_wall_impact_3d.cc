// A short steel bar hits a rigid wall in 3D, pure FE and coupled FE-PD-FE (the CI-sized
// version of section 6.3, studies/bar_impact/README.md): a bar 40 x 4 x 4 mm (E = 200 GPa, rho =
// 7823 kg/m^3; hexahedra of h = 1 mm) at v0 = 1 m/s, its end x = 40 mm at the wall (Contact/Model
// = rigid wall) at t = 0, dt = 40 ns. Coupled: pure PD for 15 <= x <= 25 mm (dx = 0.5 mm,
// 8 sites per hexahedron, m = 1.5), overlaps of 3 FE cells on both sides, weak coupling,
// force blending, fine-scale damping C = 10. Point A = (26.5, 2, 2) mm lies in the overlap
// nearer the wall.
//
// nu = 0: the bar is one-dimensional (c0 = sqrt(E / rho)); the 1D theory says the end stays
// at the wall for 2 L / c0 = 15.8 us, the bar leaves at -v0, and at A the velocity drops to
// 0 when the compression front passes and to -v0 when the unloading front does.
//  - Contact duration (first to last step in contact, plus one) / (2 L / c0) within 1.5 %,
//    pure FE and coupled (measured 1.1 % and 0.9 %: the mesh's dispersion smears the
//    returning front, the release waits for it).
//  - Pure FE rebound velocity (momentum / mass at the end) / -v0 within 3 % (measured
//    0.974: the same dispersion; fe/bar_wall_contact's longer bar, 0.987).
//  - Both fronts at A (v_x crossing v0/2 and -v0/2): coupled and pure FE within one FE cell
//    of wave travel, h / c0 = 0.2 us (measured 0 and 0.08 us: the PD lattice is less
//    dispersive, its fronts arrive a step or two earlier).
//  - The coupled bar leaves slower than the pure-FE one (0.896 against 0.974): the
//    constraint's velocity projection removes the fine-scale kinetic energy of the fronts
//    each step, a time-discretisation error (studies/wave_coupling/README.md). It must converge:
//    with dt / 4 the deficit must fall below 0.4 of that at dt (first order: 0.25; measured 0.079
//    -> 0.022, ratio 0.27).
//  - Point A's v_x history, relative L2 of coupled - pure FE below 0.15 (measured 0.112):
//    beyond the fronts, which agree, the two discretisations ring differently behind them.
// nu = 0.3: lateral inertia rings behind the fronts (3D bar waves); point A's history
// differs from pure FE by less than 0.18 (measured 0.137). The pure-FE history is itself
// far from converged here: studies/bar_impact/README.md measures 11 % between 1 mm and 0.5 mm
// hexahedra in the full-size case.
// On 2 ranks (the .mpirun=2 output): the coupled nu = 0.3 history equals the 1-rank one to
// 1e-9 of each column's largest value (energies, contact force, x-momentum, point A;
// measured 9e-14: round-off of different sums over 600 steps).

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  const double L = 0.04, W = 0.004, E = 200e9, rho = 7823, v0 = 1, h = 1e-3, T = 24e-6;

  std::string
  bar_case(const double nu, const bool coupled, const double dt = 4e-8)
  {
    std::ostringstream prm;
    prm << std::setprecision(17) << "set Dimension = 3\n"
        << "subsection Geometry\n  set Lower corner = 0, 0, 0\n  set Upper corner = " << L << ", "
        << W << ", " << W << "\n  set Subdivisions = 40, 4, 4\nend\n"
        << "subsection Material\n  set Young's modulus = " << E
        << "\n  set Poisson's ratio = " << nu << "\n  set Density = " << rho << "\nend\n";
    if (coupled)
      prm << "subsection Peridynamics\n  set Region = 0.015, 0, 0 : 0.025, " << W << ", " << W
          << "\n  set Lattice spacing = 5e-4\n  set Horizon factor = 1.5\nend\n"
          << "subsection Coupling\n  set Method = weak\n  set Blending = force\n"
          << "  set Damping constant = 10\n"
          << "  set Overlap region = 0.012, 0, 0 : 0.015, " << W << ", " << W
          << " ; 0.025, 0, 0 : 0.028, " << W << ", " << W
          << "\n  set Finite element region = 0, 0, 0 : 0.012, " << W << ", " << W
          << " ; 0.028, 0, 0 : " << L << ", " << W << ", " << W << "\nend\n";
    prm << "subsection Initial conditions\n  subsection function\n    subsection Velocity\n"
        << "      set Function expression = " << v0 << "; 0; 0\n    end\n  end\nend\n"
        << "subsection Contact\n  set Model = rigid wall\n  subsection rigid wall\n"
        << "    set Point = " << L << ", 0, 0\n    set Normal = -1, 0, 0\n  end\nend\n"
        << "subsection Time\n  set Time step = " << dt << "\n  set End time = " << T << "\nend\n"
        << "subsection Postprocess\n  set List of postprocessors = energies, contact forces, "
           "linear momentum, probes\n  subsection probes\n    set Points = 0.0265, 0.002, 0.002\n"
           "  end\nend\n"
        << quiet_output();
    return prm.str();
  }

  /**
   * Contact duration, rebound velocity (over v0), point A's v_x history (every step) and
   * the times its v_x first falls below v0/2 and below -v0/2, of a run.
   */
  struct Impact
  {
    double              duration, rebound, first_front, second_front;
    std::vector<double> point_a;
  };

  Impact
  run_case(const double nu, const bool coupled, const double dt = 4e-8)
  {
    auto simulator = make_simulator<3>(bar_case(nu, coupled, dt));
    simulator->run();
    const auto &history  = simulator->get_energy_history();
    const auto  touching = history.column("contact_nodes");
    int         first = -1, last = -1;
    for (unsigned int n = 0; n < touching.size(); ++n)
      if (touching[n] > 0)
        {
          if (first < 0)
            first = n;
          last = n;
        }
    Impact impact;
    impact.duration     = (last - first + 1) * dt;
    impact.rebound      = history.column("linear_momentum_x").back() / (rho * L * W * W) / v0;
    impact.point_a      = history.column("probe_0_v_x");
    const auto time     = history.column("time");
    const auto crossing = [&](const double level) {
      for (unsigned int n = 0; n < time.size(); ++n)
        if (impact.point_a[n] < level)
          return time[n];
      AssertThrow(false,
                  ExcMessage("point A's velocity never fell below " + std::to_string(level)));
      return 0.;
    };
    impact.first_front  = crossing(0.5 * v0);
    impact.second_front = crossing(-0.5 * v0);
    return impact;
  }

  double
  relative_l2(const std::vector<double> &a, const std::vector<double> &reference)
  {
    AssertThrow(a.size() == reference.size(), ExcMessage("histories of different lengths"));
    double difference = 0, norm = 0;
    for (unsigned int n = 0; n < a.size(); ++n)
      {
        difference += (a[n] - reference[n]) * (a[n] - reference[n]);
        norm += reference[n] * reference[n];
      }
    return std::sqrt(difference / norm);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const double c0 = std::sqrt(E / rho), duration = 2 * L / c0;
    const bool   parallel = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1;
    if (!parallel)
      {
        const Impact fe = run_case(0, false), coupled = run_case(0, true);
        check("nu = 0, pure FE: contact duration / (2 L / c0)", fe.duration / duration, 1., 0.015);
        check("nu = 0, coupled: contact duration / (2 L / c0)",
              coupled.duration / duration,
              1.,
              0.015);
        check("nu = 0, pure FE: rebound velocity / -v0", -fe.rebound, 1., 0.03);
        check("nu = 0: compression front at A, coupled - pure FE [s]",
              coupled.first_front - fe.first_front,
              0.,
              h / c0);
        check("nu = 0: unloading front at A, coupled - pure FE [s]",
              coupled.second_front - fe.second_front,
              0.,
              h / c0);
        const double deficit = fe.rebound - coupled.rebound;
        report("nu = 0: rebound deficit of the coupled bar at dt = 40 ns", -deficit);
        const Impact fine_fe = run_case(0, false, 1e-8), fine_coupled = run_case(0, true, 1e-8);
        check_below("nu = 0: rebound deficit at dt / 4 over that at dt < 0.4",
                    (fine_fe.rebound - fine_coupled.rebound) / deficit,
                    0.4);
        check_below("nu = 0: point A, relative L2 of coupled - pure FE < 0.15",
                    relative_l2(coupled.point_a, fe.point_a),
                    0.15);
        const Impact fe3 = run_case(0.3, false), coupled3 = run_case(0.3, true);
        check_below("nu = 0.3: point A, relative L2 of coupled - pure FE < 0.18",
                    relative_l2(coupled3.point_a, fe3.point_a),
                    0.18);
      }
    else
      {
        // The columns that carry the result; the transverse ones are zero by symmetry and
        // hold round-off only.
        const std::vector<std::string> columns   = {"kinetic_energy",
                                                    "strain_energy",
                                                    "total_energy",
                                                    "contact_force_x",
                                                    "linear_momentum_x",
                                                    "probe_0_v_x"};
        auto                           two_ranks = make_simulator<3>(bar_case(0.3, true));
        two_ranks->run();
        double worst = 0;
        if (is_root())
          {
            auto one_rank = make_simulator<3>(bar_case(0.3, true), MPI_COMM_SELF);
            one_rank->run();
            for (const auto &name : columns)
              {
                const auto a = two_ranks->get_energy_history().column(name);
                const auto b = one_rank->get_energy_history().column(name);
                AssertThrow(a.size() == b.size(), ExcMessage("histories of different lengths"));
                double magnitude = 0, difference = 0;
                for (unsigned int n = 0; n < a.size(); ++n)
                  {
                    magnitude  = std::max(magnitude, std::abs(b[n]));
                    difference = std::max(difference, std::abs(a[n] - b[n]));
                  }
                worst = std::max(worst, difference / magnitude);
              }
          }
        check_below("nu = 0.3, coupled: 2 ranks - 1 rank, largest over the history columns",
                    Utilities::MPI::max(worst, MPI_COMM_WORLD),
                    1e-9);
      }
  });
}
