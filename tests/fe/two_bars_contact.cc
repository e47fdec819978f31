// Two equal bars collide (Contact/Model = elastic target): strips 50 mm x 4 mm (plane
// stress, E = 200 GPa, nu = 0, rho = 7800 kg/m^3; Q1 cells of 1 mm x 2 mm, two bodies of one
// mesh, two_bars.geo), the striker at v0 = 1 m/s, the target at rest 1 um ahead. With nu = 0
// each strip is a one-dimensional bar (c = sqrt(E / rho)), and the 1D theory of equal bars
// says: from the touch on, both ends move at v0 / 2 under the force rho c (v0 / 2) A
// while a compression wave runs to both free ends and back; after 2 L / c = 19.75 us the
// striker is at rest and the target moves at v0 (the striker's momentum handed over whole).
//  - Momentum: the two bodies' total is conserved exactly (the contact forces on them
//    cancel): 1e-10 relative to M_striker v0 over the run (measured 2.5e-12: round-off of
//    internal forces of 8e4 N over 1400 steps).
//  - Contact force: its mean over the middle half of the contact (the 1D force is constant
//    there; the first and last steps carry the arrival and the release) within 1 % of
//    rho c (v0 / 2) A (measured 2e-5; it rings around the mean with the mesh's dispersion).
//  - Contact duration (first to last step with a pair in contact, plus one step) within 2 %
//    of 2 L / c (measured 1.3 %: the release waits for the unloading fronts, which the
//    mesh's dispersion smears, from two bars here against one at the rigid wall), and no
//    contact in the last 15 us of the run.
//  - After separation: the striker's mean velocity / v0 within 0.02 of 0 and the target's
//    within 0.02 of 1 (measured 0.011 and 0.989; as for the rigid wall, fe/bar_wall_contact,
//    the mesh's dispersion smears the returning fronts, an error that falls like the cell
//    size).
//  - Energy: kinetic + strain - contact work over the initial energy in [0.999, 1.001]: the
//    contact work accounts for what the arriving nodes lose (measured 0.5 % of the energy)
//    and velocity Verlet's energy error is far below 1e-3 at this step; the loss itself
//    below 1 % (one node column of 51 per bar meets the other with relative speed v0).
// Twice: on two_bars.msh, whose contact faces match node to node (one Gauss-Seidel sweep
// is exact), and on two_bars_nonmatching.msh, whose target has 3 cells across against the
// striker's 2 (the middle striker vertex pushes two target nodes with weights 1/2; the
// sweeps couple the pairs); measured the same to the digits quoted above.
// The same on 2 ranks (the .mpirun=2 output): the contact pairs are solved on every rank in
// the same order, so the verdicts are the same.

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  void
  collide(const std::string &mesh)
  {
    const double       L = 0.05, A = 0.004, E = 200e9, rho = 7800, v0 = 1, dt = 5e-8, T = 70e-6;
    const double       c = std::sqrt(E / rho), duration = 2 * L / c, gap = 1e-6;
    std::ostringstream prm;
    prm << std::setprecision(17) << "set Dimension = 2\n"
        << "subsection Geometry\n  set Mesh file = " PERIARLEQUIN_SOURCE_DIR "/examples/two_bars/"
        << mesh << "\nend\n"
        << "subsection Material\n  set Young's modulus = " << E
        << "\n  set Poisson's ratio = 0\n  set Density = " << rho
        << "\n  set Two-dimensional model = plane stress\nend\n"
        << "subsection Initial conditions\n  subsection function\n    subsection Velocity\n"
        << "      set Function expression = x < " << L + gap / 2 << " ? " << v0
        << " : 0; 0\n    end\n  end\nend\n"
        << "subsection Contact\n  set Model = elastic target\n  subsection elastic target\n"
        << "    set Striker boundary ids = 10\n    set Target boundary ids = 11\n  end\nend\n"
        << "subsection Time\n  set Time step = " << dt << "\n  set End time = " << T << "\nend\n"
        << quiet_output();
    auto simulator = make_simulator<2>(prm.str());
    simulator->setup();
    auto       &fe      = simulator->get_fe_zone();
    const auto &contact = *simulator->get_contact();

    // Mass and x-momentum of each body (striker: x <= L) over the owned DoFs of component 0.
    std::vector<unsigned int> dofs, components;
    std::vector<Point<2>>     points;
    fe.support_points(dofs, points, components);
    const auto momenta = [&]() {
      std::array<double, 4> sums{}; // striker momentum, mass, target momentum, mass
      for (unsigned int k = 0; k < dofs.size(); ++k)
        if (components[k] == 0)
          {
            const unsigned int body = points[k][0] < L + gap / 2 ? 0 : 2;
            const double       m    = fe.lumped_mass().local_element(dofs[k]);
            sums[body] += m * fe.get_state().velocity.local_element(dofs[k]);
            sums[body + 1] += m;
          }
      for (double &sum : sums)
        sum = Utilities::MPI::sum(sum, MPI_COMM_WORLD);
      return sums;
    };
    const auto   start   = momenta();
    const double energy0 = fe.kinetic_energy();
    check(mesh + ": striker mass / (rho L A)", start[1] / (rho * L * A), 1., 1e-12);

    int                 first = -1, last = -1;
    std::vector<double> forces;
    for (int step = 1; simulator->get_time() < T * (1 - 1e-12); ++step)
      {
        simulator->advance();
        if (contact.n_touching_nodes() > 0)
          {
            if (first < 0)
              first = step;
            last = step;
            forces.resize(step - first + 1, 0.);
            forces.back() = contact.total_force()[0];
          }
      }
    const auto end = momenta();
    report(mesh + ": contact steps", last - first + 1);
    check(mesh + ": total momentum change / (M v0)",
          (end[0] + end[2] - start[0] - start[2]) / (start[1] * v0),
          0.,
          1e-10);
    const unsigned int quarter = forces.size() / 4;
    const double middle = std::accumulate(forces.begin() + quarter, forces.end() - quarter, 0.) /
                          (forces.size() - 2 * quarter);
    check(mesh + ": mean contact force over the middle half / (rho c v0 A / 2)",
          -middle / (rho * c * v0 * A / 2),
          1.,
          0.01);
    check(mesh + ": contact duration / (2 L / c)", (last - first + 1) * dt / duration, 1., 0.02);
    check_above(mesh + ": time without contact at the end of the run [s] >= 1.5e-5",
                T - last * dt,
                1.5e-5);
    check(mesh + ": striker velocity after / v0", end[0] / end[1] / v0, 0., 0.02);
    check(mesh + ": target velocity after / v0", end[2] / end[3] / v0, 1., 0.02);
    const double energy = fe.kinetic_energy() + fe.strain_energy() - fe.external_work();
    check_below(mesh + ": (kinetic + strain - contact work) / initial energy <= 1.001",
                energy / energy0,
                1.001);
    check_above(mesh + ": (kinetic + strain - contact work) / initial energy >= 0.999",
                energy / energy0,
                0.999);
    check_below(mesh + ": energy lost at the contact / initial energy <= 0.01",
                fe.external_work() / -energy0,
                0.01);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    collide("two_bars.msh");
    collide("two_bars_nonmatching.msh");
  });
}
