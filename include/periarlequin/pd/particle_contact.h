#ifndef periarlequin_pd_particle_contact_h
#define periarlequin_pd_particle_contact_h

#include <periarlequin/pd/bond_families.h>
#include <periarlequin/pd/pd_parameters.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <cstddef>
#include <limits>
#include <unordered_set>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * Short-range repulsion between PD particles that no intact bond joins: the faces of a
   * crack that closes, fragments, separate bodies. A pair at distance r < d_c pushes apart
   * with the force k (d_c - r) along the line joining them, the potential k (d_c - r)^2 / 2,
   * split evenly between its two particles' energy densities.
   *
   * The candidate pairs are kept in a Verlet list: every pair of held particles (owned and
   * ghost) closer than d_c plus a skin when the list was built, found by binning the current
   * positions in cells of that size. The list holds until two particles may have moved by
   * the skin relative to each other (the box of all drifts since has a diagonal of a skin);
   * then it is built again, on all ranks together. A pair closer than d_c is in
   * the list whenever the list is current, so the forces do not depend on when lists were
   * built, nor on the partition: each owned particle sums the forces of its pairs in the
   * order of its partners' ids, and a pair's force is formed identically (to the sign) from
   * both of its particles, whichever ranks hold them. A rank holds the particles of its own
   * and the neighbouring background cells; where particles of cells farther apart come
   * together on several ranks (fragments, faces sliding past each other across a rank
   * boundary), the run stops with a message rather than miss a pair.
   *
   * Contact acts between particles outside the Arlequin overlap (alpha = 0), whose PD model
   * carries the full mass and stiffness.
   */
  template <int dim>
  class ParticleContact
  {
  public:
    /**
     * Contact for a lattice of spacing @p lattice_spacing in a material of Young's modulus
     * @p youngs_modulus [Pa], over @p communicator.
     */
    ParticleContact(const Parameters::ParticleContact &parameters,
                    const double                       lattice_spacing,
                    const double                       youngs_modulus,
                    const MPI_Comm                     communicator);

    /**
     * The particle set or its local numbering changed: build the list before the next use.
     * @p particle_cells: the global active index of the background cell of every owned
     * particle; @p held_cells: the cells whose particles this rank holds (owned and ghost
     * cells).
     */
    void
    reinit(std::vector<types::global_cell_index>        particle_cells,
           std::unordered_set<types::global_cell_index> held_cells);

    /**
     * Add the contact force densities [N/m^dim] and energy densities [J/m^dim] of the owned
     * particles to @p force_density and @p energy_density, for displacements @p displacement
     * of the owned and ghost particles (ghosts current). Collective.
     */
    void
    add_forces(const BondFamilies<dim>               &bonds,
               ArrayView<const Point<dim>>            reference_position,
               ArrayView<const types::particle_index> ids,
               ArrayView<const double>                alpha,
               ArrayView<const Tensor<1, dim>>        displacement,
               const double                           particle_volume,
               std::vector<Tensor<1, dim>>           &force_density,
               std::vector<double>                   &energy_density);

    /**
     * A bound on the largest eigenvalue that contact adds to M^-1 K for particles of mass
     * @p particle_mass [1/s^2]: 2 n k / m, the row sum of the pair stiffnesses, with at most
     * n = 2 (dim - 1) partners a particle (the faces of two lattices pressed together,
     * aligned or offset by half a spacing).
     */
    double
    eigenvalue_bound(const double particle_mass) const;

    /** Owned particles that touched another in the last force evaluation. */
    unsigned int
    n_touching() const
    {
      return touching;
    }

    /**
     * The contact potential of the owned particles in the last force evaluation [J; J/m in
     * 2D]: half of each pair's k (d_c - r)^2 / 2 at each of its particles.
     */
    double
    local_energy() const
    {
      return energy;
    }

    /** Contact distance d_c [m]. */
    double
    distance() const
    {
      return contact_distance;
    }

    /** Pair stiffness k [N/m; N/m^2 per unit thickness in 2D]. */
    double
    stiffness() const
    {
      return pair_stiffness;
    }

  private:
    static constexpr std::size_t no_bond = std::numeric_limits<std::size_t>::max();

    /**
     * Whether two particles may have moved by the skin relative to each other since the list
     * was built (collective).
     */
    bool
    list_outdated(ArrayView<const Tensor<1, dim>> displacement, const unsigned int n_owned) const;

    /** The Verlet list of the current positions. */
    void
    build_list(const BondFamilies<dim>               &bonds,
               ArrayView<const Point<dim>>            reference_position,
               ArrayView<const types::particle_index> ids,
               ArrayView<const double>                alpha,
               ArrayView<const Tensor<1, dim>>        displacement);

    /**
     * Refuse a partition that may hide a contact partner: a rank holds the particles of its
     * own and the neighbouring background cells. Every rank's cells' boxes of current particle
     * positions are gathered; a box within the list's cutoff of one of this rank's boxes whose
     * cell this rank does not hold stops the run (collective; nothing on one rank).
     */
    void
    check_partners_held(const std::vector<Point<dim>> &position,
                        ArrayView<const double>        alpha) const;

    double                                       contact_distance;
    double                                       skin;
    double                                       pair_stiffness;
    const MPI_Comm                               communicator;
    std::vector<types::global_cell_index>        particle_cells;
    std::unordered_set<types::global_cell_index> held_cells;

    bool list_current = false;
    /** Displacements of the owned particles when the list was built. */
    std::vector<Tensor<1, dim>> displacement_at_build;
    /** Owned particles with partners, and their partners in [partner_begin[p], ...[p + 1]). */
    std::vector<unsigned int> particles_with_partners;
    std::vector<unsigned int> partner_begin;
    std::vector<unsigned int> partner;
    /** The stored bond joining each pair, or no_bond. */
    std::vector<std::size_t> partner_bond;
    unsigned int             touching = 0;
    double                   energy   = 0;
  };
} // namespace PeriArlequin

#endif
