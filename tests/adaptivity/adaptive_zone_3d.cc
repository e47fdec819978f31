// The adaptive PD zone in 3D.
// 1. Momentum through a conversion: a block [-0.2, 0.2]^2 x [-0.08, 0.08] m, FE cells 40 mm,
//    lattice 10 mm (m = 3.015, aluminium), pure PD [-0.08, 0.08]^2 x [-0.04, 0.04], overlap
//    band 0.04 m (one cell), energy blending, weak coupling. A criterion registered here, as a
//    user would, flags the cells whose centre lies in [0.08, 0.12] x [-0.08, 0.08] x
//    [-0.04, 0.04] (one layer, 1 x 4 x 2 = 8 cells); one conversion at t = 0, at rest under the
//    uniform velocity (3, -2, 1) m/s and under a smooth non-uniform one. The conversion conserves
//    the momentum of both zones to round-off (1e-12 relative): the particles that gained mass take
//    up what the two quadratures of the blended mass disagree on.
// 2. A running crack grows the zone, on 2 ranks as on 1: a glass plate 60 x 40 x 8 mm
//    (E = 72 GPa, nu = 0.22, G0 = 3.8 J/m^2), lattice 1 mm, m = 3.015, FE cells 4 mm, a
//    through-thickness notch 30 mm long along y = 20 mm, traction 4 MPa on the y faces; PD on
//    [0, 36] x [12, 28] mm through the thickness, band 8 mm; default adaptive settings
//    (damage distance with its automatic Distance, Check interval 10); to 10 us: the crack
//    runs, the zone grows with it (and repartitions on 2 ranks). Broken bonds, converted cells
//    and particles identical at every record on all ranks and on rank 0 alone, crack area and
//    total energy to 1e-10 (sums in another order).

#include <periarlequin/adaptivity/conversion_criterion.h>

#include "../tests.h"
#include "plates.h"

using namespace PeriArlequinTests;

namespace
{
  /** Flags the cells whose centre lies in [0.08, 0.12] x [-0.08, 0.08] x [-0.04, 0.04]. */
  template <int dim>
  class LayerConversion : public PeriArlequin::CellCentreCriterion<dim>
  {
  protected:
    bool
    converts(const Point<dim> &c) const override
    {
      return c[0] > 0.08 && c[0] < 0.12 && std::abs(c[1]) < 0.08 && std::abs(c[dim - 1]) < 0.04;
    }
  };
} // namespace

PERIARLEQUIN_REGISTER_CONVERSION_CRITERION(LayerConversion,
                                           "test layer",
                                           "cells in a fixed box (test)")

std::string
block_text(const std::string &velocity)
{
  return "set Dimension = 3\n"
         "subsection Geometry\n  set Lower corner = -0.2, -0.2, -0.08\n"
         "  set Upper corner = 0.2, 0.2, 0.08\n  set Subdivisions = 10, 10, 4\nend\n"
         "subsection Material\n  set Young's modulus = 69e9\n  set Poisson's ratio = 0.3\n"
         "  set Density = 2700\nend\n"
         "subsection Peridynamics\n  set Region = -0.08, -0.08, -0.04 : 0.08, 0.08, 0.04\n"
         "  set Lattice spacing = 0.01\nend\n"
         "subsection Coupling\n  set Method = weak\n  set Blending = energy\n"
         "  set Overlap width = 0.04\nend\n"
         "subsection Adaptive PD zone\n  set Conversion criterion = test layer\n"
         "  set Check interval = 1000\nend\n"
         "subsection Time\n  set Time step = 2e-7\n  set End time = 1e-6\nend\n"
         "subsection Initial conditions\nsubsection function\n"
         "  subsection Velocity\n    set Function expression = " +
         velocity + "\n  end\nend\nend\n" + quiet_output();
}

std::string
notched_plate_text()
{
  std::ostringstream text;
  text << notched_glass_plate_3d("0, 0.012, 0 : 0.036, 0.028, 0.008")
       << opposite_y_tractions(4e6, 3)
       << "subsection Coupling\n  set Method = weak\n  set Blending = force\n"
       << "  set Overlap width = 0.008\n  set Damping constant = 10\nend\n"
       << "subsection Adaptive PD zone\n  set Conversion criterion = damage distance\nend\n"
       << "subsection Time\n  set Time step = 5e-8\n  set End time = 1e-5\nend\n"
       << quiet_output() << "subsection Output\n  set Energy interval = 20\nend\n"
       << "subsection Postprocess\n  set List of postprocessors = energies, cracks, zone sizes\n"
       << "end\n";
  return text.str();
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    for (const std::string velocity : {"3; -2; 1", "3 + sin(20*x); -2 + cos(15*y); 1 + sin(10*z)"})
      {
        auto simulator = make_simulator<3>(block_text(velocity));
        simulator->setup();
        const auto momentum = [&] {
          return simulator->get_fe_zone().linear_momentum() +
                 simulator->get_pd_zone()->linear_momentum();
        };
        const Tensor<1, 3> before = momentum();
        check("velocity (" + velocity + "): cells converted", simulator->grow_pd_zone(), 8, 0);
        check_below("velocity (" + velocity + "): |momentum change| / |momentum|",
                    (momentum() - before).norm() / before.norm(),
                    1e-12);
      }

    auto plate = make_simulator<3>(notched_plate_text(), MPI_COMM_WORLD);
    plate->run();
    const auto &history = plate->get_energy_history();
    check_above("broken bond ends during the run (a crack ran)",
                history.column("broken_bonds").back() - history.column("broken_bonds").front(),
                100);
    check_above("cells converted (the zone grew)", history.column("converted_cells").back(), 0.5);
    check_growth_matches_rank_0(*plate, notched_plate_text());
  });
}
