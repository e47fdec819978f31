#ifndef periarlequin_pd_ghost_exchange_h
#define periarlequin_pd_ghost_exchange_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/tensor.h>
#include <deal.II/particles/particle_handler.h>

#include <unordered_map>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The local numbering of the particles of one rank and the exchange of per-particle
   * values with the ghost particles. Local number i runs over the owned particles in the
   * handler's order, then over the ghosts; it is the index of every flat PD array.
   *
   * reinit() after the particle set changed (insertion, sort, repartition) builds the ghost
   * particles with a cached communication pattern (exchange_ghost_particles(true)) and
   * renumbers; every update_ghosts() in between reuses that fixed pattern
   * (update_ghost_particles()), sending the owned values through the particle properties and
   * reading the ghosts' back in the same order.
   */
  template <int dim>
  class GhostExchange
  {
  public:
    explicit GhostExchange(Particles::ParticleHandler<dim> &particle_handler);

    /** Ghost particles and local numbers for the current particle set. */
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
    local_index(const types::particle_index id) const;

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
    Particles::ParticleHandler<dim>                        &particle_handler;
    unsigned int                                            n_owned_particles = 0;
    std::vector<types::particle_index>                      particle_ids;
    std::vector<Point<dim>>                                 positions;
    std::unordered_map<types::particle_index, unsigned int> index_of_id;
    std::vector<double>                                     buffer;
  };
} // namespace PeriArlequin

#endif
