#ifndef periarlequin_pd_bond_families_h
#define periarlequin_pd_bond_families_h

#include <deal.II/base/tensor.h>

#include <array>
#include <cstdint>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The bonds of a regular lattice, stored once as flat CSR arrays indexed by a local
   * particle number (owned particles first, then ghosts; only owned particles have families).
   *
   * On a lattice every bond is a lattice offset, so a bond stores only its neighbour and the
   * index of its offset in a shared stencil that holds the reference bond vector xi, its
   * length and the partial volume V_J v_IJ of eq. 22. Seven bytes a bond.
   */
  template <int dim>
  class BondFamilies
  {
  public:
    /** One lattice offset within the horizon. */
    struct StencilEntry
    {
      std::array<int, dim> offset;
      Tensor<1, dim>       xi;
      double               length;
      /** Neighbour volume times the partial-volume factor, V_J v_IJ [m^dim]. */
      double volume;
    };

    enum BondState : std::uint8_t
    {
      broken      = 0,
      intact      = 1,
      unbreakable = 2
    };

    /**
     * The lattice stencil for spacing @p dx and horizon @p horizon: every offset with a
     * non-zero partial volume v = 1 if x <= delta - dx/2, (delta - x)/dx + 1/2 if
     * |x - delta| < dx/2, else 0 (eq. 22).
     */
    void
    build_stencil(const double dx, const double horizon);

    /** Start a family for the next owned particle (call in order of local index). */
    void
    begin_family();
    void
    add_bond(const unsigned int neighbor, const unsigned int stencil_index, const BondState state);
    /** Close the CSR arrays after the last family. */
    void
    end_families(const unsigned int n_owned, const unsigned int n_total);

    unsigned int n_owned = 0;
    /** Owned plus ghost particles. */
    unsigned int n_total = 0;

    std::vector<StencilEntry>  stencil;
    std::vector<unsigned int>  family_begin;
    std::vector<unsigned int>  neighbor;
    std::vector<std::uint16_t> stencil_index;
    std::vector<std::uint8_t>  state;
    /** Reference weighted volume q = sum x^2 V_J v_IJ over the full family, owned and ghosts. */
    std::vector<double> weighted_volume;

    std::size_t
    n_bonds() const;
    /** Damage 1 - (intact bond volume)/(initial bond volume) of owned particle @p i. */
    double
    damage(const unsigned int i) const;
    /** Memory of the bond arrays [bytes]. */
    std::size_t
    memory_consumption() const;
  };
} // namespace PeriArlequin

#endif
