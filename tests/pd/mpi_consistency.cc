// MPI: several ranks reproduce 1 rank for the PD zone, with fracture on. The test runs on 2
// and 3 ranks; rank 0 also runs each case alone (MPI_COMM_SELF). Compared: every column of the
// energy history at every step (kinetic, strain, work, total, broken-bond count).
//  - the pre-cracked plate of the fracture test, coarser (50 x 50 particles, 300 steps):
//    the crack runs across the partition boundary; with the critical stretch and with the
//    critical bond energy (whose decision on a bond to a ghost uses both ends' particle
//    scalars); both must break bonds;
//  - a 3D block with a smooth initial velocity and a body force (ghosts in 3D).
//
// Tolerance 1e-10 relative to each column's largest magnitude (sums in a different order
// give round-off of order 1e-15 per step), which for the broken-bond count means identical.

#include "../tests.h"
#include "plate.h"

using namespace PeriArlequinTests;

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    require_several_ranks();
    check_below("2D pre-cracked plate, all ranks vs 1 rank, max relative difference",
                parallel_vs_serial_history_difference<2>(plate_parameters(8e-4, true, 300),
                                                         "2D plate",
                                                         "broken_bonds"),
                1e-10);
    check_below(
      "2D pre-cracked plate, bond-energy criterion, all ranks vs 1 rank, max relative "
      "difference",
      parallel_vs_serial_history_difference<2>(
        plate_parameters(8e-4, true, 300) +
          "subsection Peridynamics\n  set Fracture criterion = critical bond energy\nend\n",
        "2D plate, bond energy",
        "broken_bonds"),
      1e-10);
    const std::string block =
      "set Dimension = 3\n"
      "subsection Geometry\n"
      "  set Lower corner = 0, 0, 0\n"
      "  set Upper corner = 0.012, 0.008, 0.008\n"
      "  set Subdivisions = 3, 2, 2\n"
      "end\n"
      "subsection Peridynamics\n"
      "  set Region = 0, 0, 0 : 0.012, 0.008, 0.008\n"
      "  set Lattice spacing = 1e-3\n"
      "end\n"
      "subsection Time\n"
      "  set Time step = 5e-8\n  set End time = 5e-6\n"
      "end\n"
      "subsection Initial conditions\nsubsection function\n  subsection Velocity\n"
      "    set Function expression = sin(300*x); 0.5*cos(400*y); 0\n"
      "  end\nend\nend\n"
      "subsection Body force\n"
      "  set Function expression = 0; 0; 1e7*sin(1e6*t)\n"
      "end\n" +
      quiet_output();
    check_below("3D block, all ranks vs 1 rank, max relative difference",
                parallel_vs_serial_history_difference<3>(block, "3D block"),
                1e-10);
  });
}
