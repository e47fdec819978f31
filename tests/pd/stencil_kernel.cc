// The stencil kernel of the LPS model (Peridynamics/Force kernel = stencil: lattice offsets,
// contiguous runs of particles, bond states as a byte mask) against the bond-list kernel
// (CSR neighbour lists), on cases rich in what the stencil handles by its mask: free
// surfaces of a notched plate with a hole, a pre-crack, sites outside the region in the
// stencil box, ghosts (the 2-rank run), blending weights in the overlap of a coupled case
// (energy and force blending), and bonds that break during a run (the mask refreshed).
//  - Static: force and energy densities of every owned particle under a random displacement
//    of strain 1e-2, in 2D plane stress, plane strain and 3D, at the default horizon
//    (m = 3.015) and at m = 1.5, 4.5 (2D) and 2, 4 (3D). Tolerance 1e-12 relative to
//    the largest density: both kernels sum the same bond terms (computed by the same
//    formula) in a different order, round-off of a few 1e-16 of the largest term per sum
//    (measured 3e-16 to 1.1e-15).
//  - Dynamic: the pre-cracked plate of the fracture test pulled apart (300 steps, the crack
//    runs): every column of the energy history, broken-bond count included, within 1e-10
//    of the largest magnitude (round-off grows over the steps; a bond broken in one run and
//    not in the other would change the count by 1, relative 1/count >> 1e-10; measured
//    1.1e-14 with 1872 broken bond ends).
//  - Neighbours: every stored bond reaches the same particle under both (the stencil finds
//    it from the slot and the offset, the bond lists store it): tolerance 0.
//  - Threads: the stencil kernel on 2 threads gives the same bits as on 1 (a slab of the
//    layout goes to one thread, and the slabs' order does not depend on the threads), in
//    every static case: tolerance 0.
// On 2 ranks the same numbers come out (the test's .mpirun=2 output is the 1-rank one).

#include "../coupling/coupled_cases.h"
#include "../tests.h"
#include "plate.h"

using namespace PeriArlequinTests;

namespace
{
  std::string
  kernel(const std::string &name)
  {
    return "subsection Peridynamics\n  set Force kernel = " + name + "\nend\n";
  }

  /** The largest |a - b| over owned entries relative to the largest |b| (over all ranks). */
  template <typename T>
  double
  relative_difference(const ArrayView<const T> a, const ArrayView<const T> b)
  {
    double difference = 0, magnitude = 0;
    for (unsigned int i = 0; i < b.size(); ++i)
      {
        const T delta = a[i] - b[i];
        difference    = std::max(difference, std::sqrt(double(delta * delta)));
        magnitude     = std::max(magnitude, std::sqrt(double(b[i] * b[i])));
      }
    difference = Utilities::MPI::max(difference, MPI_COMM_WORLD);
    magnitude  = Utilities::MPI::max(magnitude, MPI_COMM_WORLD);
    AssertThrow(magnitude > 0, ExcMessage("vacuous comparison: all densities are 0"));
    return difference / magnitude;
  }

  /** Force and energy densities of the case @p parameters with either kernel, compared. */
  template <int dim>
  void
  compare_densities(const std::string &title,
                    const std::string &parameters,
                    const bool         skips_unused_forces = false)
  {
    auto stencil = make_simulator<dim>(parameters + kernel("stencil"));
    auto list    = make_simulator<dim>(parameters + kernel("bond list"));
    stencil->setup();
    list->setup();
    auto &a = *stencil->get_pd_zone();
    auto &b = *list->get_pd_zone();
    AssertThrow(Utilities::MPI::min(int(a.get_bonds().uses_stencil()), MPI_COMM_WORLD) == 1 &&
                  Utilities::MPI::max(int(b.get_bonds().uses_stencil()), MPI_COMM_WORLD) == 0,
                ExcMessage("the kernels were not the ones asked for"));
    AssertThrow(a.n_owned_particles() == b.n_owned_particles(),
                ExcMessage("the two runs hold different particles"));
    // Under the stencil a stored bond finds its neighbour from the slot and the offset; the
    // bond lists store it: every stored bond must reach the same particle (ids: exact).
    {
      const auto  &bonds_a = a.get_bonds(), &bonds_b = b.get_bonds();
      const auto   ids_a = a.particle_ids(), ids_b = b.particle_ids();
      unsigned int differing = bonds_a.n_bonds() == bonds_b.n_bonds() ? 0 : 1;
      for (unsigned int i = 0; i < bonds_a.n_owned && differing == 0; ++i)
        for (unsigned int n = bonds_a.family_begin[i]; n < bonds_a.family_begin[i + 1]; ++n)
          differing += ids_a[bonds_a.neighbor(i, n)] != ids_b[bonds_b.neighbor(i, n)] ||
                       bonds_a.stencil_index[n] != bonds_b.stencil_index[n];
      check_below(title + ", stored bonds whose neighbour differs, stencil vs bond list",
                  Utilities::MPI::sum(differing, MPI_COMM_WORLD),
                  0.5);
    }
    // A coupled case has slaves whose pair forces are not used (force weight 0, or both
    // ends of state weight 0): the stencil's force pass skips them, the bond lists do not,
    // and the densities compared below must agree all the same.
    if (skips_unused_forces)
      {
        const auto [all, forced] = a.get_bonds().stencil_layout().visited_slots();
        check_above(title + ", bond slots the force pass skips",
                    Utilities::MPI::sum(double(all - forced), MPI_COMM_WORLD),
                    0.5);
      }
    // The stencil kernel on one thread, then on all (2) of them.
    on_one_thread([&] { a.compute_internal_forces(); });
    const std::vector<Tensor<1, dim>> one_thread_force(a.force_densities().begin(),
                                                       a.force_densities().end());
    const std::vector<double>         one_thread_energy(a.energy_densities().begin(),
                                                a.energy_densities().end());
    a.compute_internal_forces();
    b.compute_internal_forces();
    unsigned int differing = 0;
    for (unsigned int i = 0; i < a.n_owned_particles(); ++i)
      differing += !(a.force_densities()[i] == one_thread_force[i] &&
                     a.energy_densities()[i] == one_thread_energy[i]);
    check_below(title + ", stencil kernel, particles whose densities differ between 1 and " +
                  std::to_string(MultithreadInfo::n_threads()) + " threads",
                Utilities::MPI::sum(differing, MPI_COMM_WORLD),
                0.5);
    report(title + " broken bonds", a.n_global_broken_bonds());
    check_below(title + ", force densities, stencil vs bond list, relative",
                relative_difference(a.force_densities(), b.force_densities()),
                1e-12);
    check_below(title + ", energy densities, stencil vs bond list, relative",
                relative_difference(a.energy_densities(), b.energy_densities()),
                1e-12);
  }

  /** Horizon factor @p m with @p subdivisions background cells (wide enough for it). */
  std::string
  horizon(const double m, const std::string &subdivisions)
  {
    return "subsection Geometry\n  set Subdivisions = " + subdivisions +
           "\nend\nsubsection Peridynamics\n  set Horizon factor = " + Utilities::to_string(m) +
           "\nend\n";
  }

  /** The 2D cracked block with a notch and a hole: more surface than bulk near them. */
  std::string
  notched_block(const std::string &model)
  {
    return cracked_random_block<2>(model) +
           "subsection Peridynamics\n  set Region = 0, 0 : 0.02, 0.008 ; 0, 0.008 : 0.006, "
           "0.012 ; 0.01, 0.008 : 0.02, 0.012 ; 0.004, 0.012 : 0.02, 0.02\nend\n";
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
      compare_densities<2>("2D plane stress, notched block with a hole", notched_block(""));
      compare_densities<2>("2D plane strain, notched block with a hole",
                           notched_block("plane strain"));
      compare_densities<3>("3D cracked block with a hole",
                           cracked_random_block<3>() +
                             "subsection Peridynamics\n  set Region = 0, 0, 0 : 0.01, 0.01, "
                             "0.004 ; 0, 0, 0.004 : 0.01, 0.004, 0.007 ; 0, 0.007, 0.004 : "
                             "0.01, 0.01, 0.007 ; 0, 0.004, 0.004 : 0.004, 0.007, 0.007 ; 0, 0, "
                             "0.007 : 0.01, 0.01, 0.01\nend\n");
      // Other horizons: the blocks of the kernel change with the stencil's reach (offsets
      // fewer than 8 slots apart are summed in chunks, the others directly).
      for (const double m : {1.5, 4.5})
        compare_densities<2>("2D plane stress, notched block with a hole, m = " +
                               Utilities::to_string(m),
                             notched_block("") + horizon(m, "4, 4"));
      for (const double m : {2., 4.})
        compare_densities<3>("3D cracked block, m = " + Utilities::to_string(m),
                             cracked_random_block<3>() + horizon(m, "2, 2, 2"));
      for (const std::string blending : {"energy", "force"})
        compare_densities<2>("coupled ring, " + blending + " blending",
                             ring_case(0.04,
                                       "weak",
                                       blending,
                                       "1e-4*sin(30*x*y+7*y+1); 1e-4*cos(20*x+400*x*y)",
                                       "0; 0",
                                       false,
                                       2e-7),
                             true);

      const std::string plate   = plate_parameters(8e-4, true, 300);
      auto              stencil = make_simulator<2>(plate + kernel("stencil"));
      auto              list    = make_simulator<2>(plate + kernel("bond list"));
      stencil->run();
      list->run();
      require_active_column(*stencil, "pre-cracked plate, stencil", "broken_bonds");
      check_below("pre-cracked plate, 300 steps, stencil vs bond list histories, relative",
                  history_difference(stencil->get_energy_history(),
                                     list->get_energy_history(),
                                     "pre-cracked plate"),
                  1e-10);
    },
    2);
}
