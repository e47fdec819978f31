/**
 * A load removed at the switch of Time/Integration = static then explicit: the load's
 * function of time holds it in the static solve (t = 0) and drops it from the first step on
 * (if(t > 0, 0, sigma)), the classic release of a body that stores elastic energy.
 *
 * A steel strip 100 x 10 mm (plane stress, nu = 0: one-dimensional waves at c = sqrt(E/rho)),
 * clamped at x = 0 and pulled by sigma = 10 MPa at x = L, FE (Q1, 2.5 mm) with PD (dx = 0.5
 * mm) on [40, 60] mm glued by the strict coupling (5 mm band, energy blending). Released, an
 * unloading wave runs from the free end toward the clamp, through the coupling. The
 * fine-scale damping is off: it acts on the PD nodes alone, a force from outside the two
 * zones, and changes the strip's momentum while the front crosses the band (measured with
 * it: 3.2 % of sigma H t_end; also force blending, whose weighted forces do not cancel: 1.4
 * %). Checked:
 * - until it reaches the clamp (t < L/c) the only force on the strip is the clamp's reaction
 *   -sigma H, so its momentum is -sigma H (t - dt/2) (momentum balance; velocity Verlet lags
 *   half a step as the first step starts from the static accelerations, zero to the solve's
 *   tolerance 1e-8). Tolerance 1e-6 of it at every record up to t = 0.6 L/c: the residual's
 *   share and round-off;
 * - behind the front the strip moves at -sigma / (rho c) (the unloading wave's particle
 *   velocity): the mean velocity of the FE nodes on [75, 95] mm at t = 0.6 L/c, 15 mm and
 *   more behind the front, against it: tolerance 2 %, the oscillation of the discrete front's
 *   tail (measured 0.55 %);
 * - 2 ranks: the momentum history equals rank 0's alone within 1e-6 (the relaxations sum in
 *   another order).
 */
#include <periarlequin/simulator.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <sstream>

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  constexpr double E = 200e9, rho = 7850, sigma = 10e6, length = 0.1, height = 0.01,
                   time_step = 4e-8;

  double
  wave_speed()
  {
    return std::sqrt(E / rho);
  }

  std::string
  case_text()
  {
    std::ostringstream text;
    text << "set Dimension = 2\n"
         << "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = " << length
         << ", " << height << "\n  set Subdivisions = 40, 4\nend\n"
         << "subsection Material\n  set Young's modulus = " << E
         << "\n  set Poisson's ratio = 0\n  set Density = " << rho
         << "\n  set Two-dimensional model = plane stress\nend\n"
         << "subsection Boundary conditions\n"
         << "  subsection Boundary 0\n    set Type = displacement\n"
         << "    subsection Function\n      set Function expression = 0; 0\n    end\n  end\n"
         << "  subsection Boundary 1\n    set Type = traction\n    subsection Function\n"
         << "      set Function expression = if(t > 0, 0, " << sigma << "); 0\n    end\n  end\n"
         << "end\n"
         << "subsection Peridynamics\n  set Region = 0.04, 0 : 0.06, " << height
         << "\n  set Lattice spacing = 5e-4\n  set Horizon factor = 3\nend\n"
         << "subsection Coupling\n  set Method = strict\n  set Fine-scale damping = false\n"
         << "  set Overlap width = 0.005\nend\n"
         << "subsection Time\n  set Integration = static then explicit\n  set Time step = "
         << time_step << "\n  set End time = " << 0.6 * length / wave_speed() << "\nend\n"
         << "subsection Static solve\n  set Tolerance = 1e-8\nend\n"
         << "subsection Postprocess\n  set List of postprocessors = energies, linear momentum\n"
         << "end\n"
         << quiet_output();
    return text.str();
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    auto strip = make_simulator<2>(case_text());
    strip->run();
    const auto &history  = strip->get_energy_history();
    const auto  time     = history.column("time");
    const auto  momentum = history.column("linear_momentum_x");
    double      worst    = 0;
    for (unsigned int k = 0; k < time.size(); ++k)
      {
        const double exact = -sigma * height * std::max(time[k] - 0.5 * time_step, 0.);
        worst = std::max(worst, std::abs(momentum[k] - exact) / (sigma * height * time.back()));
      }
    report("records", time.size());
    check_below("largest |momentum + sigma H (t - dt/2)| over sigma H t_end", worst, 1e-6);

    double sum = 0, count = 0;
    for_each_fe_dof(*strip,
                    [&](const unsigned int dof, const Point<2> &x, const unsigned int component) {
                      if (component == 0 && x[0] >= 0.075 && x[0] <= 0.095)
                        {
                          sum += strip->get_fe_zone().get_state().velocity.local_element(dof);
                          count += 1;
                        }
                    });
    const double mean_velocity =
      Utilities::MPI::sum(sum, MPI_COMM_WORLD) / Utilities::MPI::sum(count, MPI_COMM_WORLD);
    check("mean velocity behind the front over -sigma / (rho c)",
          mean_velocity / (-sigma / (rho * wave_speed())),
          1,
          0.02);
    const auto kinetic = history.column("kinetic_energy");
    const auto total   = history.column("total_energy");
    report("kinetic energy at the end over sigma^2/(2E) H c t",
           kinetic.back() / (sigma * sigma / (2 * E) * height * wave_speed() * time.back()));
    report("change of the total energy over the stored strain energy",
           (total.back() - total.front()) / history.column("strain_energy").front());

    if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      {
        double difference = 0;
        if (is_root())
          {
            auto serial = make_simulator<2>(case_text(), MPI_COMM_SELF);
            serial->run();
            difference = largest_column_difference(history,
                                                   serial->get_energy_history(),
                                                   {"linear_momentum_x", "total_energy"},
                                                   true);
          }
        check_below("largest relative history difference, all ranks - rank 0 alone",
                    Utilities::MPI::broadcast(MPI_COMM_WORLD, difference, 0),
                    1e-6);
      }
  });
}
