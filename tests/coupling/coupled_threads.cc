// The coupled step on the threads of a rank: the coupling's operators (N and N^T by rows and
// by columns, the multiplier grid's H and H^T, the multiplier solves, the fine-scale damping,
// the slave layer), the FE accelerations and the crack diagnostics split their loops among
// the threads; each entry is written by one thread with the additions of the serial loop in
// its order, and the sums over particles run in fixed chunks. So 2 threads must give what 1
// thread gives to the bit: tolerance 0 on every column of the energy history at every record.
// The one-thread run limits deal.II itself to one thread (MultithreadInfo::set_thread_limit,
// as DEAL_II_NUM_THREADS=1 does), not only the tasks: deal.II takes other code paths then
// (FEValues copy the geometry of a translated cell from the cell before, which changed the
// weights JxW in the last bit until the FE zone's mapping computed every cell afresh).
// The cases: the notched glass plate of coupling/coupled_crack, a crack running in the PD
// strip (force blending, weak coupling on the default multiplier grid, diagonal multipliers,
// damping, broken-bond and crack-tip diagnostics), to 15 us; again with the multipliers on
// the FE nodes and conjugate-gradient solves, and with the strict coupling. The overlaps hold
// 3520 PD nodes, the slave layer 2560 (checked above 2000): on each of 2 ranks, more than two
// tasks of 512 rows. About 6900 bond ends break in each run. And the adaptive zone: the
// plate under 4 MPa, PD first on [0, 60] x [12.5, 27.5] mm only, the zone grown by the
// damage-distance and strain criteria as the crack runs and branches (20 us; cells converted
// at several growths, each rebuilding the particle structures, the FE zone and the coupling
// on the threads). Last, a strict coupling whose multipliers (48,000 unknowns on the PD
// nodes of two wide overlaps, more than 16,384 a rank on 2 ranks) are solved by conjugate
// gradients: deal.II's vector reductions split such vectors among the threads and sum them in
// one pass on one thread; the project's CG forms its dot products in fixed chunks instead.

#include "coupled_cases.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

namespace
{
  /**
   * Run @p parameters on 2 threads and on 1 (deal.II limited to one thread); the largest
   * relative difference of the histories. With @p many_rows, the overlap and the slave layer
   * must hold more than 2000 PD nodes, several tasks of rows a rank; with
   * @p multipliers_per_rank, the ranks more multiplier unknowns than that on average.
   */
  double
  threads_difference(const std::string &parameters,
                     const std::string &title,
                     const std::string &active_column        = "broken_bonds",
                     const bool         many_rows            = true,
                     const unsigned int multipliers_per_rank = 0)
  {
    auto two_threads = make_simulator<2>(parameters, MPI_COMM_WORLD);
    two_threads->run();
    std::unique_ptr<Simulator<2>> one_thread;
    on_one_thread([&] {
      one_thread = make_simulator<2>(parameters, MPI_COMM_WORLD);
      one_thread->run();
    });
    require_active_column(*two_threads, title, active_column);
    if (many_rows)
      {
        const auto [overlap_nodes, slaves] = two_threads->get_coupling()->n_coupled_particles();
        check_above(title + ": overlap PD nodes", overlap_nodes, 2000);
        check_above(title + ": slave particles", slaves, 2000);
      }
    if (multipliers_per_rank > 0)
      check_above(title + ": multiplier unknowns a rank",
                  two_threads->get_coupling()->n_multipliers() /
                    Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD),
                  multipliers_per_rank);
    return history_difference(two_threads->get_energy_history(),
                              one_thread->get_energy_history(),
                              title);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(
    argc,
    argv,
    [] {
      require_two_threads();
      const std::string plate = notched_glass_plate_case(true, 0.0075, 1.5e-5);
      check("weak on the grid, diagonal, damping: 2 threads vs 1, largest relative difference",
            threads_difference(plate, "weak grid"),
            0.,
            0.);
      check("weak on the FE nodes, CG: 2 threads vs 1, largest relative difference",
            threads_difference(plate + "subsection Coupling\n  set Multiplier solver = cg\n"
                                       "  subsection weak\n    set Multiplier spacing = 1\n"
                                       "  end\nend\n",
                               "weak FE nodes CG"),
            0.,
            0.);
      check("strict, diagonal, damping: 2 threads vs 1, largest relative difference",
            threads_difference(plate + "subsection Coupling\n  set Method = strict\nend\n",
                               "strict"),
            0.,
            0.);
      const std::string adaptive =
        glass_plate_case(true,
                         6.25e-4,
                         0.0025,
                         0.0075,
                         0.0075,
                         4e6,
                         4e-8,
                         2e-5,
                         "force",
                         "subsection Peridynamics\n  set Fracture = true\n"
                         "  set Critical energy release rate = 3.8\n"
                         "  set Pre-cracks = 0, 0.02 : 0.05, 0.02\n"
                         "  set Region = 0, 0.0125 : 0.06, 0.0275\nend\n"
                         "subsection Coupling\n  set Overlap region =\n"
                         "  set Finite element region =\n  set Overlap width = 0.005\nend\n"
                         "subsection Adaptive PD zone\n"
                         "  set Conversion criterion = damage distance, strain\nend\n"
                         "subsection Output\n  set Energy interval = 25\nend\n"
                         "subsection Postprocess\n  set List of postprocessors = energies, "
                         "cracks, zone sizes\nend\n");
      check("adaptive zone, damage distance and strain: 2 threads vs 1, largest relative "
            "difference",
            threads_difference(adaptive, "adaptive", "converted_cells", false),
            0.,
            0.);
      const std::string wide_overlaps =
        "set Dimension = 2\n"
        "subsection Geometry\n  set Lower corner = -0.15, -0.05\n"
        "  set Upper corner = 0.15, 0.05\n  set Subdivisions = 75, 25\nend\n"
        "subsection Material\n  set Young's modulus = 69e9\n  set Poisson's ratio = 0.3\n"
        "  set Density = 2700\nend\n"
        "subsection Peridynamics\n  set Region = -0.01, -0.05 : 0.01, 0.05\n"
        "  set Lattice spacing = 5e-4\n  set Horizon factor = 3.015\nend\n"
        "subsection Coupling\n  set Method = strict\n  set Multiplier solver = cg\n"
        "  set Overlap region = -0.04, -0.05 : -0.01, 0.05 ; 0.01, -0.05 : 0.04, 0.05\n"
        "  set Finite element region = -0.15, -0.05 : -0.04, 0.05 ; 0.04, -0.05 : 0.15, 0.05\n"
        "end\n"
        "subsection Time\n  set Time step = 5e-8\n  set End time = 5e-7\nend\n"
        "subsection Initial conditions\n  set Model = function\n  subsection function\n"
        "    subsection Velocity\n"
        "      set Function expression = 1e-2*sin(40*x)*cos(30*y); 1e-2*cos(50*x+y)\n"
        "    end\n  end\nend\n"
        "subsection Output\n  set Output interval = 0\n  set Energy interval = 1\n"
        "  set Progress interval = 0\n  set Directory = test_output_wide_overlaps\nend\n";
      check(
        "strict, CG on 48,000 multipliers: 2 threads vs 1, largest relative difference",
        threads_difference(wide_overlaps, "wide overlaps", "multiplier_iterations", false, 16384),
        0.,
        0.);
    },
    2);
}
