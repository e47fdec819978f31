/**
 * Time/Integration = static then explicit: the static equilibrium by dynamic relaxation, then
 * the explicit loop from it.
 *
 * 1. Pure FE, a plane-stress plate 100 x 50 mm (Q1, 2.5 mm cells) pulled by a traction
 *    sigma = 4 MPa on its x faces: linear elements hold the exact uniform state, u_x =
 *    sigma/E (x - 50 mm), u_y = -nu sigma/E (y - 25 mm) (no rigid motion: the loads are
 *    symmetric and the relaxation starts at rest), with the strain energy sigma^2/(2E) V.
 *    The relaxation stops at |M a| <= 1e-9 |F|; its displacement error is the residual over
 *    the lowest stiffness of the plate, measured 2.7 times the tolerance at 1e-6: 1e-6 of the
 *    displacement scale leaves a factor of several hundred. The explicit run from the
 *    equilibrium stays at rest: kinetic energy below 1e-6 of the strain energy for 100 steps
 *    (the bound the residual allows: a force 1e-9 |F| for 100 steps).
 * 3. A crack released in a preloaded pure PD plate (40 x 20 mm, dx = 0.5 mm, the same pull):
 *    the crack x = 20 mm cuts the plate in two. From the release on, the only force on the
 *    right half is the traction on its far face, so its momentum is sigma H (t - dt/2)
 *    exactly (momentum balance; velocity Verlet lags half a step, since the first step uses
 *    the accelerations of the intact equilibrium, which are 0 to the solve's tolerance
 *    1e-8). Tolerance 1e-6 of it: the residual's share and round-off. The left half mirrors
 *    it. The static plate is at rest before the release (kinetic energy 0).
 * 2. Coupled (weak Arlequin, force blending, a PD zone in the middle of a smaller plate, with
 *    fracture on but bonds that cannot break at this load): the relaxation converges to
 *    1e-6, the explicit run from it stays at rest as in 1 and breaks no bond; on 2 ranks the
 *    strain and total energies equal rank 0's alone within the relaxation's tolerance.
 */
#include <periarlequin/simulator.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  constexpr double E = 72e9, nu = 0.22, sigma = 4e6;

  std::string
  plate_text(const double length, const double height, const unsigned int cells_x)
  {
    std::ostringstream text;
    text << "set Dimension = 2\n"
         << "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = " << length
         << ", " << height << "\n  set Subdivisions = " << cells_x << ", " << cells_x / 2
         << "\nend\n"
         << "subsection Material\n  set Young's modulus = " << E
         << "\n  set Poisson's ratio = " << nu
         << "\n  set Density = 2440\n  set Two-dimensional model = plane stress\nend\n"
         << opposite_tractions(sigma, 2, 0)
         << "subsection Time\n  set Integration = static then explicit\n  set Time step = 4e-8\n"
         << "  set End time = 4e-6\nend\n"
         << quiet_output();
    return text.str();
  }

  /** The largest kinetic energy of the explicit run over the strain energy it started with. */
  double
  largest_kinetic_over_strain_energy(const PeriArlequin::EnergyHistory &history)
  {
    const auto   kinetic = history.column("kinetic_energy");
    const double strain  = history.column("strain_energy").front();
    return *std::max_element(kinetic.begin(), kinetic.end()) / strain;
  }

  void
  pure_fe()
  {
    const double length = 0.1, height = 0.05;
    auto         plate = make_simulator<2>(plate_text(length, height, 40) +
                                   "subsection Static solve\n  set Tolerance = 1e-9\nend\n");
    plate->setup();
    const auto result = plate->solve_static();
    check_below("FE: |M a| / |F| after the static solve", result.relative_residual, 1e-9);

    const auto               &fe = plate->get_fe_zone();
    std::vector<unsigned int> dofs, components;
    std::vector<Point<2>>     points;
    fe.support_points(dofs, points, components);
    const auto &u     = fe.get_state().displacement;
    double      error = 0;
    for (unsigned int k = 0; k < dofs.size(); ++k)
      {
        const double exact = components[k] == 0 ? sigma / E * (points[k][0] - 0.5 * length) :
                                                  -nu * sigma / E * (points[k][1] - 0.5 * height);
        error              = std::max(error, std::abs(u.local_element(dofs[k]) - exact));
      }
    check_below("FE: largest |u - u_exact| over sigma/E times the half length",
                Utilities::MPI::max(error, MPI_COMM_WORLD) / (sigma / E * 0.5 * length),
                1e-6);
    const double exact_energy = sigma * sigma / (2 * E) * length * height;
    check("FE: strain energy over sigma^2/(2E) V",
          plate->get_fe_zone().strain_energy() / exact_energy,
          1,
          1e-6);

    plate->run();
    check_below("FE: largest kinetic energy of the explicit run over the strain energy",
                largest_kinetic_over_strain_energy(plate->get_energy_history()),
                1e-6);
  }

  void
  released_crack()
  {
    const double      length = 0.04, height = 0.02, time_step = 4e-8, end_time = 4e-6;
    const std::string case_text =
      plate_text(length, height, 16) +
      "subsection Peridynamics\n  set Region = 0, 0 : 0.04, 0.02\n  set Lattice spacing = 5e-4\n"
      "  set Horizon factor = 3\nend\n"
      "subsection Coupling\n  set Method = none\nend\n"
      "subsection Static solve\n  set Tolerance = 1e-8\n"
      "  set Released cracks = 0.02, -0.01 : 0.02, 0.03\nend\n";
    auto plate = make_simulator<2>(case_text);
    plate->run();
    check("released crack: kinetic energy at the release [J]",
          plate->get_energy_history().column("kinetic_energy").front(),
          0,
          0);
    check_above("released crack: broken bond ends",
                plate->get_energy_history().column("broken_bonds").back(),
                0.5);
    const auto &pd          = *plate->get_pd_zone();
    const auto  x           = pd.reference_positions();
    const auto  v           = pd.get_state().velocities();
    double      momentum[2] = {0, 0};
    for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
      momentum[x[i][0] > 0.5 * length] += pd.particle_mass(i) * v[i][0];
    const double exact = sigma * height * (end_time - 0.5 * time_step);
    check("released crack: momentum of the right half over sigma H (t - dt/2)",
          Utilities::MPI::sum(momentum[1], MPI_COMM_WORLD) / exact,
          1,
          1e-6);
    check("released crack: momentum of the left half over -sigma H (t - dt/2)",
          -Utilities::MPI::sum(momentum[0], MPI_COMM_WORLD) / exact,
          1,
          1e-6);
  }

  void
  coupled()
  {
    const std::string case_text =
      plate_text(0.04, 0.02, 16) +
      "subsection Peridynamics\n  set Region = 0.015, 0.005 : 0.025, 0.015\n"
      "  set Lattice spacing = 5e-4\n  set Horizon factor = 3\n  set Fracture = true\n"
      "  set Critical energy release rate = 3.8\nend\n"
      "subsection Coupling\n  set Method = weak\n  set Blending = force\n"
      "  set Overlap width = 0.0025\nend\n"
      "subsection Postprocess\n  set List of postprocessors = energies, cracks\nend\n";
    auto plate = make_simulator<2>(case_text);
    plate->run();
    const auto &history = plate->get_energy_history();
    check_below("coupled: largest kinetic energy of the explicit run over the strain energy",
                largest_kinetic_over_strain_energy(history),
                1e-6);
    check("coupled: broken bond ends", history.column("broken_bonds").back(), 0, 0);
    // The ranks sum in another order, so their relaxations may stop an iteration apart:
    // the energies agree to the relaxation's tolerance, not to round-off.
    double difference = 0;
    if (is_root())
      {
        auto serial = make_simulator<2>(case_text, MPI_COMM_SELF);
        serial->run();
        difference = largest_column_difference(history,
                                               serial->get_energy_history(),
                                               {"strain_energy", "total_energy"},
                                               true);
      }
    check_below("coupled: largest relative energy difference, all ranks - rank 0 alone",
                Utilities::MPI::max(difference, MPI_COMM_WORLD),
                1e-6);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    pure_fe();
    released_crack();
    coupled();
  });
}
