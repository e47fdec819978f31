// Boundary tractions on PD particles, by the momentum they put in. A 2D plate
// [0, 0.1] x [0, 0.04] m (aluminium, lattice 1 mm, free otherwise) under a traction
// t_y = 2 MPa on its top face (boundary 3) and t_y = 1 MPa on its right face (boundary 1):
// internal forces cancel in sum, so the y momentum after n steps of velocity Verlet is
// exactly n dt F with F = 2e6 x 0.1 + 1e6 x 0.04 N per unit thickness. Pure PD first (the
// particles within dx of a loaded face carry t / dx), then coupled (weak coupling, energy
// blending, damping off: forces that derive from a translation-invariant energy, and the
// coupling forces cancel on a rigid translation), with a PD strip 0.04 <= x <= 0.06,
// overlaps 0.02 wide on both sides and FE beyond, so the top face crosses every zone and
// its traction is shared as alpha (FE) and 1 - alpha (PD): FE momentum (lumped masses,
// the slaves' included) plus that of the free particles. And pure PD on a plate that dx does
// not divide, [0, 0.1005] x [0, 0.0408]: the lattice fills [0, 0.1] x [0, 0.04] (100 x 40
// cells; the PD body is the lattice's cells), its top and right layers lie 1.3 and 1.0 dx
// from the domain's faces, and they carry the tractions all the same: F as above (the
// traction over the faces of the lattice's cells). Tolerance 1e-10 relative: the sums of
// some ten thousand terms in double precision over 50 steps.

#include "../tests.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

namespace
{
  std::string
  plate(const bool coupled, const bool dx_divides = true)
  {
    std::string text =
      "set Dimension = 2\n"
      "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = " +
      std::string(dx_divides ? "0.1, 0.04" : "0.1005, 0.0408") +
      "\n  set Subdivisions = 20, 8\nend\n"
      "subsection Material\n  set Young's modulus = 69e9\n  set Poisson's ratio = 0.3\n"
      "  set Density = 2700\nend\n"
      "subsection Peridynamics\n  set Lattice spacing = 1e-3\n  set Horizon factor = 3.015\n"
      "  set Region = " +
      std::string(coupled ? "0.04, 0 : 0.06, 0.04" :
                            (dx_divides ? "0, 0 : 0.1, 0.04" : "0, 0 : 0.1005, 0.0408")) +
      "\nend\n"
      "subsection Boundary conditions\n"
      "  subsection Boundary 1\n    set Type = traction\n"
      "    subsection Function\n      set Function expression = 0; 1e6\n    end\n  end\n"
      "  subsection Boundary 3\n    set Type = traction\n"
      "    subsection Function\n      set Function expression = 0; 2e6\n    end\n  end\n"
      "end\n"
      "subsection Time\n  set Time step = 5e-8\n  set End time = 2.5e-6\nend\n" +
      quiet_output();
    if (coupled)
      text += "subsection Coupling\n  set Method = weak\n  set Blending = energy\n"
              "  set Fine-scale damping = false\n"
              "  set Overlap region = 0.02, 0 : 0.04, 0.04 ; 0.06, 0 : 0.08, 0.04\n"
              "  set Finite element region = 0, 0 : 0.02, 0.04 ; 0.08, 0 : 0.1, 0.04\nend\n";
    return text;
  }

  double
  momentum_y(const Simulator<2> &simulator)
  {
    double sum = 0;
    if (const PDZone<2> *pd = simulator.get_pd_zone())
      for (unsigned int i = 0; i < pd->n_owned_particles(); ++i)
        if (!pd->is_slave(i))
          sum += pd->particle_mass(i) * pd->get_state().velocities()[i][1];
    for_each_fe_dof(simulator,
                    [&](const unsigned int dof, const Point<2> &, const unsigned int component) {
                      if (component == 1)
                        sum += simulator.get_fe_zone().lumped_mass().local_element(dof) *
                               simulator.get_velocity().local_element(dof);
                    });
    return Utilities::MPI::sum(sum, MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const double force = 2e6 * 0.1 + 1e6 * 0.04;
    for (const bool coupled : {false, true})
      {
        auto simulator = make_simulator<2>(plate(coupled));
        simulator->run();
        const double expected = force * simulator->get_time();
        check_below(std::string(coupled ? "coupled" : "pure PD") + ": |y momentum / (F t) - 1|",
                    std::abs(momentum_y(*simulator) / expected - 1.),
                    1e-10);
      }
    auto simulator = make_simulator<2>(plate(false, false));
    simulator->run();
    check_below("pure PD, dx not dividing the plate: |y momentum / (F t) - 1|",
                std::abs(momentum_y(*simulator) / (force * simulator->get_time()) - 1.),
                1e-10);
  });
}
