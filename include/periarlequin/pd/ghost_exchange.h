#ifndef periarlequin_pd_ghost_exchange_h
#define periarlequin_pd_ghost_exchange_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/base/tensor.h>
#include <deal.II/particles/particle_handler.h>

#include <map>
#include <memory>
#include <unordered_map>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The local numbering of the particles of one rank and the exchange of per-particle
   * values with the ghost particles. Local number i runs over the owned particles in the
   * handler's order, then over the ghosts in the order of their owners' numbering; it is the
   * index of every flat PD array.
   *
   * reinit() after the particle set changed (insertion, sort, repartition) builds the ghost
   * particles (exchange_ghost_particles(true)), numbers the owned particles of all ranks
   * consecutively and builds from that numbering a fixed communication pattern, a
   * Utilities::MPI::Partitioner. Every update_ghosts() in between sends through it only the
   * values asked for, straight from and into the flat arrays: no particle is touched, and
   * no id, location or other property travels.
   */
  template <int dim>
  class GhostExchange
  {
  public:
    /** The particles of @p particle_handler, distributed over @p communicator. */
    GhostExchange(Particles::ParticleHandler<dim> &particle_handler, const MPI_Comm communicator);

    /** Ghost particles, local numbers and the communication pattern for the particle set. */
    void
    reinit();

    unsigned int
    n_owned() const;
    /** Owned plus ghost particles. */
    unsigned int
    n_total() const;
    /** Ids in local order. */
    ArrayView<const types::particle_index>
    ids() const;
    /** Reference positions in local order. */
    ArrayView<const Point<dim>>
    reference_positions() const;
    /** Local number of the particle @p id, or numbers::invalid_unsigned_int if not held. */
    unsigned int
    local_index(const types::particle_index id) const
    {
      if (!index_by_id.empty())
        return id >= first_id && id - first_id < index_by_id.size() ? index_by_id[id - first_id] :
                                                                      numbers::invalid_unsigned_int;
      const auto found = index_of_id.find(id);
      return found == index_of_id.end() ? numbers::invalid_unsigned_int : found->second;
    }

    /**
     * Copy @p n_per_particle values per owned particle (entries [0, n_per_particle n_owned)
     * of @p values, sized for n_total particles) to the ghost entries.
     */
    void
    update_ghosts(ArrayView<double> values, const unsigned int n_per_particle);
    /** Copy the owned vectors of @p values to the ghost entries. */
    void
    update_ghosts(ArrayView<Tensor<1, dim>> values);

  private:
    /** The pattern for @p n_per_particle values a particle (built, collectively, on first use). */
    const Utilities::MPI::Partitioner &
    partitioner(const unsigned int n_per_particle);

    Particles::ParticleHandler<dim>   &particle_handler;
    const MPI_Comm                     communicator;
    unsigned int                       n_owned_particles = 0;
    std::vector<types::particle_index> particle_ids;
    std::vector<Point<dim>>            positions;
    /**
     * The local numbers by id. Lattice ids of a compact zone are nearly consecutive: where the
     * held ids span at most max_table_span slots a held particle, a table over that span
     * (index_by_id[id - first_id], invalid where not held; at most 32 bytes a particle, and
     * built and read faster than a hash map, which every growth of an adaptive zone does for
     * all particles); otherwise (a small zone in a large lattice) the hash map index_of_id.
     */
    types::particle_index                                   first_id = 0;
    std::vector<unsigned int>                               index_by_id;
    std::unordered_map<types::particle_index, unsigned int> index_of_id;
    static constexpr unsigned int                           max_table_span = 8;
    /** The consecutive number of the first owned particle, and those of the ghosts. */
    types::global_dof_index                                              first_index = 0;
    std::vector<types::global_dof_index>                                 ghost_indices;
    types::global_dof_index                                              n_global = 0;
    std::map<unsigned int, std::unique_ptr<Utilities::MPI::Partitioner>> partitioners;
    std::vector<double>                                                  send_buffer;
    std::vector<MPI_Request>                                             requests;
  };
} // namespace PeriArlequin

#endif
