// A running crack grows the PD zone, on 2 and 3 ranks as on 1. The notched glass plate of
// coupling/crack_mpi (0.1 x 0.04 m, E = 72 GPa, traction 2 MPa on the long edges, lattice
// 0.625 mm, delta = 2 mm, FE cells 2.5 mm, a 50 mm notch along y = 20 mm, G0 = 3.8 J/m^2,
// weak coupling with force blending, damping constant 10 for this narrow band) starts with PD only
// around the notch, [0, 0.06] x [0.0125, 0.0275], an overlap band of 5 mm, and the damage-distance
// criterion (7.5 mm, every 10 steps): the zone grows along the notch first, then ahead of the
// running tip. Run to 20 us on all ranks, repartitioning after every conversion (Load imbalance
// tolerance = 0: particles, their state and broken bonds, and the FE field move to new owners), and
// again on rank 0 alone:
//  - the crack ran (more than 100 broken bond ends) and the zone grew while it ran (more cells
//    converted at the end than after the first check);
//  - broken bonds and converted cells identical at every record (a conversion depends on the
//    damage only, which both runs break alike; particles keep their lattice ids);
//  - crack area, particle count, total energy and the energy change of the conversions agree
//    to 1e-10 of their magnitude (sums in another order);
//  - the ranks repartitioned, and the load imbalance at the end is below 2 %: p4est cuts the
//    curve of cells at a cell, so the imbalance left is about one cell's weight (at most
//    1000 + 16 sites x 37 bonds) over a rank's load (about 5e5 here), 0.3 %.

#include "../tests.h"
#include "plates.h"

using namespace PeriArlequinTests;

std::string
growing_crack_text(const double imbalance_tolerance)
{
  std::ostringstream text;
  text << notched_glass_plate("0, 0.0125 : 0.06, 0.0275") << opposite_y_tractions(2e6, 2)
       << "subsection Coupling\n  set Method = weak\n  set Blending = force\n"
       << "  set Overlap width = 0.005\n  set Damping constant = 10\nend\n"
       << "subsection Adaptive PD zone\n  set Conversion criterion = damage distance\n"
       << "  set Check interval = 10\n  set Load imbalance tolerance = " << imbalance_tolerance
       << "\n  subsection damage distance\n"
       << "    set Distance = 0.0075\n  end\nend\n"
       << "subsection Time\n  set Time step = 4e-8\n  set End time = 2e-5\nend\n"
       << quiet_output() << "subsection Output\n  set Energy interval = 25\nend\n"
       << "subsection Postprocess\n  set List of postprocessors = energies, cracks, zone sizes\n"
       << "end\n";
  return text.str();
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    require_several_ranks();
    auto parallel = make_simulator<2>(growing_crack_text(0.), MPI_COMM_WORLD);
    parallel->run();
    const auto                   &history = parallel->get_energy_history();
    const auto                    broken  = history.column("broken_bonds");
    const auto                    cells   = history.column("converted_cells");
    std::map<std::string, double> worst;
    if (is_root())
      {
        auto serial = make_simulator<2>(growing_crack_text(0.1), MPI_COMM_SELF);
        serial->run();
        for (const std::string column : {"broken_bonds",
                                         "converted_cells",
                                         "crack_area",
                                         "pd_particles",
                                         "total_energy",
                                         "conversion_energy"})
          {
            const auto a = history.column(column), b = serial->get_energy_history().column(column);
            double     magnitude = 0, difference = 0;
            for (unsigned int n = 0; n < a.size(); ++n)
              {
                magnitude  = std::max(magnitude, std::abs(b[n]));
                difference = std::max(difference, std::abs(a[n] - b[n]));
              }
            worst[column] = magnitude > 0 ? difference / magnitude : difference;
            report(column + " at the end", b.back());
          }
        report("cells converted after the first check", cells[1]);
      }
    const auto broadcast = [](const double x) {
      return Utilities::MPI::broadcast(MPI_COMM_WORLD, x, 0);
    };
    check_above("broken bond ends at the end (a crack ran)",
                broadcast(broken.back() - broken.front()),
                100);
    check_above("cells converted at the end - after the first check (the zone grew with the crack)",
                broadcast(cells.back() - cells[1]),
                0.5);
    for (const std::string column : {"broken_bonds", "converted_cells"})
      check_below("largest |" + column + ", all ranks - rank 0 alone|",
                  broadcast(worst[column]),
                  1e-15);
    check_above("repartitions (all ranks)", history.column("repartitions").back(), 0.5);
    check_below("load imbalance at the end (all ranks)",
                history.column("load_imbalance").back(),
                0.02);
    for (const std::string column :
         {"crack_area", "pd_particles", "total_energy", "conversion_energy"})
      check_below("largest relative |" + column + ", all ranks - rank 0 alone|",
                  broadcast(worst[column]),
                  1e-10);
  });
}
