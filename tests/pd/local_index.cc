// GhostExchange::local_index() against a search of the held ids, for the two ways the local
// numbers are kept: a table over the span of the held ids (ids nearly consecutive: the sites
// of a compact zone) and a hash map (ids spread over a span of more than 8 a held particle: a
// small or thin zone in a large lattice). 20 x 20 particles on a unit square of 4 x 4 cells,
// their ids the site numbers i + 20 j (dense) or 1000 times those (sparse). Checked exactly,
// on every rank:
// - every held particle (owned and ghost) is found at its position in ids();
// - no id that is not held is found: all ids of the lattice, the ids between them and ids
//   beyond the span.
// On 2 ranks the ghost particles are held too (checked that there are some), so the owned
// numbers, the ghosts' and the ids not held all meet.

#include <periarlequin/pd/ghost_exchange.h>

#include <deal.II/distributed/tria.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/particles/particle_handler.h>

#include <map>

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  constexpr unsigned int n_per_side = 20;

  /** Ids not found or found where they should not be, for ids i + 20 j times @p spacing. */
  unsigned int
  wrong_lookups(const types::particle_index spacing, const std::string &name)
  {
    parallel::distributed::Triangulation<2> triangulation(MPI_COMM_WORLD);
    GridGenerator::subdivided_hyper_cube(triangulation, 4);
    const MappingQ1<2>                 mapping;
    Particles::ParticleHandler<2>      particle_handler(triangulation, mapping, 1);
    std::vector<Point<2>>              positions;
    std::vector<types::particle_index> ids;
    for (unsigned int j = 0; j < n_per_side; ++j)
      for (unsigned int i = 0; i < n_per_side; ++i)
        {
          positions.emplace_back((i + 0.5) / n_per_side, (j + 0.5) / n_per_side);
          ids.push_back(spacing * (i + n_per_side * j));
        }
    // Every rank inserts the particles of its owned cells.
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (unsigned int p = 0; p < positions.size(); ++p)
          if (cell->point_inside(positions[p]))
            particle_handler.insert_particle(positions[p],
                                             mapping.transform_real_to_unit_cell(cell,
                                                                                 positions[p]),
                                             ids[p],
                                             cell);
    particle_handler.update_cached_numbers();
    PeriArlequin::GhostExchange<2> ghosts(particle_handler, MPI_COMM_WORLD);
    ghosts.reinit();

    std::map<types::particle_index, unsigned int> held;
    const auto                                    held_ids = ghosts.ids();
    for (unsigned int i = 0; i < held_ids.size(); ++i)
      held[held_ids[i]] = i;
    const unsigned int n_ghosts = ghosts.n_total() - ghosts.n_owned();
    if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      AssertThrow(Utilities::MPI::min(n_ghosts, MPI_COMM_WORLD) > 0,
                  ExcMessage(name + ": a rank holds no ghost particle, the case is vacuous"));

    unsigned int wrong = 0;
    for (types::particle_index id = 0; id <= spacing * n_per_side * n_per_side + 5; ++id)
      {
        const auto         found = held.find(id);
        const unsigned int expected =
          found == held.end() ? numbers::invalid_unsigned_int : found->second;
        wrong += ghosts.local_index(id) != expected;
      }
    return Utilities::MPI::sum(wrong, MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    check("dense ids (a table): wrong local numbers", wrong_lookups(1, "dense ids"), 0, 0);
    check("sparse ids, 1000 apart (a hash map): wrong local numbers",
          wrong_lookups(1000, "sparse ids"),
          0,
          0);
  });
}
