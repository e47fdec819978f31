// The fine-scale damping may not destabilise the time step. A glass bar 40 x 10 x 5 mm
// (E = 72 GPa, nu = 0.22) pulled at its x faces by 4 MPa switched on at t = 0; PD (lattice
// 0.5 mm, m = 3) on 15 <= x <= 25 mm through the whole cross-section, a band of two FE cells
// (5 mm, weak coupling, force blending, the default damping C = 10) on each side, FE cells
// 2.5 mm beyond; no fracture; 20 us (the fronts cross the bar three times). At 0.9 of the
// estimated stable step the largest damping rate C_I = C c_L / L_B times the step is about
// 1.5: with the damping force taken at the half-step velocity (the explicit form of eq.
// 79c) the nodes of the band's FE edge grow without bound (seen on a 3D plate: bond
// stretches from 1e-4 to 1.5 within 3 us, the run stopped by a bond broken on an edge line
// of the body). The default form takes the force at the end-of-step velocity and is stable
// at any damping.
// Measured: the largest bond stretch over the run in the overlap and in the slave layer,
// against the same case at a tenth of the stable step (the reference, where both forms
// agree to 0.2 %; about 2.6 and 2.4 sigma / E, above the 2 sigma / E of two tensile steps
// meeting in a 1D bar by the overshoot of the sharp fronts and the Poisson effect at the
// bar's edges).
//  - default (implicit) damping at 0.9 of the stable step: within 10 % of the reference.
//    Steps from 0.25 to 0.9 of the stable one, either form where it is stable, gave 0.5 to
//    4 % (the time discretisation of the sharp fronts); an unstable run is off by orders.
//  - the half-step form at the same step is refused, naming Time/Time step;
//  - the half-step form at 0.95 of the lowered stable step it states: within 10 % as well
//    (the lowering, 2 / omega (sqrt(1 + xi^2) - xi), is not optimistic).
// On several ranks the default run must also equal rank 0 alone to 1e-10 (sums in another
// order).

#include <periarlequin/coupling/coupling.h>

#include "../tests.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

namespace
{
  constexpr double stress = 4e6, youngs_modulus = 72e9;

  std::string
  bar_case(const double time_step, const std::string &damping_integration)
  {
    std::ostringstream text;
    text << std::setprecision(17) << "set Dimension = 3\n"
         << "subsection Geometry\n  set Lower corner = 0, 0, 0\n"
         << "  set Upper corner = 0.04, 0.01, 0.005\n  set Subdivisions = 16, 4, 2\nend\n"
         << "subsection Material\n  set Young's modulus = " << youngs_modulus
         << "\n  set Poisson's ratio = 0.22\n  set Density = 2440\nend\n"
         << "subsection Peridynamics\n  set Region = 0.015, 0, 0 : 0.025, 0.01, 0.005\n"
         << "  set Lattice spacing = 5e-4\n  set Horizon factor = 3\nend\n"
         << "subsection Coupling\n  set Method = weak\n  set Blending = force\n"
         << "  set Overlap width = 0.005\n  set Damping integration = " << damping_integration
         << "\nend\n"
         << "subsection Boundary conditions\n"
         << "  subsection Boundary 0\n    set Type = traction\n"
         << "    subsection Function\n      set Function expression = " << -stress
         << "; 0; 0\n    end\n  end\n"
         << "  subsection Boundary 1\n    set Type = traction\n"
         << "    subsection Function\n      set Function expression = " << stress
         << "; 0; 0\n    end\n  end\nend\n"
         << "subsection Time\n  set Time step = " << time_step << "\n  set End time = 2e-5\nend\n"
         << quiet_output() << "subsection Output\n  set Energy interval = 1\nend\n"
         << "subsection Postprocess\n  set List of postprocessors = energies, bond stretches\n"
         << "end\n";
    return text.str();
  }

  /** The largest stretches over the run: in the overlap and in the slave layer. */
  std::pair<double, double>
  largest_stretches(const double time_step, const std::string &integration)
  {
    auto simulator = make_simulator<3>(bar_case(time_step, integration));
    simulator->run();
    const auto largest = [&](const std::string &column) {
      const auto values = simulator->get_energy_history().column(column);
      return *std::max_element(values.begin(), values.end());
    };
    return {largest("max_stretch_overlap"), largest("max_stretch_slave_layer")};
  }

  /** The largest stretches at @p time_step within 10 % of @p reference. */
  void
  check_against_reference(const std::string               &title,
                          const double                     time_step,
                          const std::string               &integration,
                          const std::pair<double, double> &reference)
  {
    const auto stretches = largest_stretches(time_step, integration);
    check(title + ": largest stretch in the overlap / reference",
          stretches.first / reference.first,
          1.,
          0.1);
    check(title + ": largest stretch in the slave layer / reference",
          stretches.second / reference.second,
          1.,
          0.1);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    // The stable step of the discretisation, undamped and with the half-step damping.
    auto probe = make_simulator<3>(bar_case(1e-9, "half step"));
    probe->setup();
    const double stable  = probe->get_stable_time_step();
    const double lowered = probe->get_coupling()->stable_time_step(stable);
    report("estimated stable step [s]", stable);
    report("stable step with the half-step damping / estimated stable step", lowered / stable);
    probe.reset();

    const auto reference = largest_stretches(0.1 * stable, "implicit");
    report("reference: largest stretch in the overlap / (sigma / E)",
           reference.first * youngs_modulus / stress);
    report("reference: largest stretch in the slave layer / (sigma / E)",
           reference.second * youngs_modulus / stress);

    const double time_step = 0.9 * stable;
    check_against_reference("implicit damping, 0.9 of the stable step",
                            time_step,
                            "implicit",
                            reference);

    std::string refusal;
    try
      {
        make_simulator<3>(bar_case(time_step, "half step"))->setup();
      }
    catch (const std::exception &error)
      {
        refusal = error.what();
      }
    verdicts() << "half-step damping at 0.9 of the stable step: "
               << (refusal.find("Time/Time step") != std::string::npos ? "refused, naming " :
                                                                         "NOT refused with ")
               << "Time/Time step" << std::endl;
    AssertThrow(refusal.find("Time/Time step") != std::string::npos,
                ExcMessage("the half-step damping above its stable step was not refused: " +
                           refusal));

    check_against_reference("half-step damping, 0.95 of its lowered stable step",
                            0.95 * lowered,
                            "half step",
                            reference);

    if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      check_below("implicit damping: largest relative history difference, all ranks - rank 0",
                  parallel_vs_serial_history_difference<3>(bar_case(time_step, "implicit"),
                                                           "implicit damping"),
                  1e-10);
  });
}
