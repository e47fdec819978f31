#ifndef periarlequin_pd_bond_families_h
#define periarlequin_pd_bond_families_h

#include <periarlequin/base/parallel_loops.h>
#include <periarlequin/base/regions.h>
#include <periarlequin/pd/ghost_exchange.h>
#include <periarlequin/pd/lattice.h>
#include <periarlequin/pd/stencil_layout.h>

#include <deal.II/base/tensor.h>

#include <array>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The bonds of a regular lattice as flat CSR arrays indexed by a local particle number
   * (owned particles first, then ghosts). Each bond is stored once per rank that owns an end
   * of it: a bond between two owned particles I < J only in the list of I, a bond between
   * an owned particle and a ghost in the list of the owned one. A model visits every bond
   * once and adds its contribution to both ends that are owned (pair-wise evaluation, as
   * with Newton's third law in molecular dynamics): half the work of visiting each family in
   * full. The two ranks holding a bond to a ghost compute it identically, so a bond breaks in
   * the same step on both.
   *
   * On a lattice every bond is a lattice offset, so a bond stores only the index of its
   * offset in a shared stencil that holds the reference bond vector xi (from the list owner
   * to the neighbour), its length and the partial volume V v of eq. 22 (the same from both
   * ends on a uniform lattice), its state, and, unless the stencil layout is in use (it
   * finds the neighbour from the offset), its neighbour's local index: three bytes a bond
   * under the stencil, seven with the bond lists. neighbor(i, n) gives the neighbour either way.
   */
  template <int dim>
  class BondFamilies
  {
  public:
    /** The particle ids of a bond's ends, the lower first. */
    using IdPair = std::pair<types::particle_index, types::particle_index>;
    /** Bonds by the ids of their ends, in no particular order; a pair may repeat. */
    using IdPairs = std::vector<IdPair>;

    /** One lattice offset within the horizon. */
    struct StencilEntry
    {
      std::array<int, dim> offset;
      Tensor<1, dim>       xi;
      double               length;
      /** Neighbour volume times the partial-volume factor, V_J v_IJ [m^dim]. */
      double volume;
    };

    /** How the material models loop over the bonds (Peridynamics/Force kernel). */
    enum class Kernel
    {
      /** The stencil unless the padded box holds more than max_stencil_fill_ratio slots a particle.
       */
      automatic,
      stencil,
      /** The CSR arrays. */
      bond_list
    };
    /** Above this many box slots per held particle, automatic takes the CSR arrays. */
    static constexpr double max_stencil_fill_ratio = 4;

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

    /**
     * What a rebuild after particles were inserted (a grown zone) can keep of the families it
     * replaces. An owned particle that was held before and none of whose stencil neighbours is
     * touched keeps its family as stored, breaks included: nothing that decides it changed.
     */
    struct PreviousNumbering
    {
      /** Per owned particle of the new numbering: its owned index before, or invalid (new). */
      std::vector<unsigned int> owned_index;
      /** Per owned and ghost particle: new, or its no-fail flag changed. */
      std::vector<bool> touched;
    };

    /**
     * The families of the owned particles of @p ghosts on @p lattice (the stencil built):
     * every stencil neighbour that is held, owned or ghost. A bond cut by one of
     * @p pre_cracks starts broken, an intact one with an end whose @p no_fail is true (one
     * entry per owned and ghost particle) cannot break. A neighbour that @p extent accepts but that
     * is not held means the ghost layer does not cover the horizon: an error. The bonds whose ends'
     * ids are a pair in @p broken_pairs start broken (a zone rebuilt with the bonds broken so far).
     * Fills weighted_volume for owned particles and ghosts. With @p previous (these families
     * were built before particles were inserted), the families it shows unchanged are copied
     * (stencil layouts only); the result is the same as without it.
     */
    void
    build(const Lattice<dim>                            &lattice,
          GhostExchange<dim>                            &ghosts,
          const std::function<bool(const Point<dim> &)> &extent,
          const std::vector<PreCrack<dim>>              &pre_cracks,
          const std::vector<bool>                       &no_fail,
          const IdPairs                                 &broken_pairs,
          const Kernel                                   kernel   = Kernel::automatic,
          const PreviousNumbering                       *previous = nullptr);

    /** Whether the models loop over the stencil layout (else over the CSR arrays). */
    bool
    uses_stencil() const
    {
      return stencil_active;
    }
    /** The stencil view of the bonds (only if uses_stencil()). */
    const StencilLayout<dim> &
    stencil_layout() const
    {
      return layout;
    }
    /**
     * Under the stencil, let the force pass skip the bonds whose pair force is not used
     * (StencilLayout::restrict_force_pass(); flags per owned and ghost particle).
     */
    void
    restrict_force_pass(const std::vector<bool> &force_used, const std::vector<bool> &state_used)
    {
      if (stencil_active)
        layout.restrict_force_pass(force_used, state_used);
    }

    /**
     * Under the stencil, let the next passes visit only the bonds near two windows of owned
     * and ghost particles (StencilLayout::restrict_to_window()) until clear_window().
     */
    void
    restrict_to_window(std::vector<std::uint8_t> window)
    {
      if (stencil_active)
        layout.restrict_to_window(std::move(window));
    }

    /** See restrict_to_window(). */
    void
    clear_window()
    {
      if (stencil_active)
        layout.clear_window();
    }

    /** After entries of state changed: refresh the stencil view. */
    void
    states_changed();

    /** After the bonds @p broken broke (the fracture pass): refresh the stencil view there. */
    void
    bonds_broke(const std::vector<StoredBond> &broken);

    /**
     * Break the intact bonds @p breaking of the stencil layout (found broken in a pass over
     * it) and refresh the layout: returns them as stored, in storage order.
     */
    std::vector<StoredBond>
    break_stencil_bonds(const std::vector<SlotBond> &breaking);

    /** The broken bonds stored here, as ordered pairs of the particle ids @p ids of the ends. */
    IdPairs
    broken_bonds(ArrayView<const types::particle_index> ids) const;
    /**
     * Break the stored bonds whose ends' ids (@p ghosts numbers them) are a pair in
     * @p broken_pairs.
     */
    void
    break_bonds(const IdPairs &broken_pairs, const GhostExchange<dim> &ghosts);

    unsigned int n_owned = 0;
    /** Owned plus ghost particles. */
    unsigned int n_total = 0;

    std::vector<StencilEntry> stencil;
    /** The stored bonds of owned particle i are n in [family_begin[i], family_begin[i + 1]). */
    std::vector<unsigned int>  family_begin;
    std::vector<std::uint16_t> stencil_index;
    std::vector<std::uint8_t>  state;
    /** Reference weighted volume q = sum x^2 V_J v_IJ over the full family, owned and ghosts. */
    std::vector<double> weighted_volume;

    /**
     * Extension e = |xi + eta| - |xi| of a bond whose ends moved apart by eta = u_J - u_I,
     * and its deformed length. e is computed as (2 xi.eta + eta.eta) / (|xi + eta| + |xi|):
     * no cancellation of nearly equal lengths, so small strains keep full relative
     * precision; and the result is exactly the same seen from either end (eta and xi change
     * sign exactly), so both ranks holding a bond agree on it to the last bit.
     */
    static std::pair<double, double>
    extension(const StencilEntry &bond, const Tensor<1, dim> &eta)
    {
      const double length = (bond.xi + eta).norm();
      return {(2. * (bond.xi * eta) + eta * eta) / (length + bond.length), length};
    }

    /**
     * Per owned particle, 1 if it or a held particle within its stencil is @p picked (one
     * flag per owned and ghost particle): the particles whose stored bonds can touch a picked
     * one. On the bond lists (no stencil to search) every owned particle is 1.
     */
    std::vector<std::uint8_t>
    owned_within_reach(const std::vector<bool> &picked) const;

    /** Bonds stored here. */
    std::size_t
    n_bonds() const
    {
      return stencil_index.size();
    }

    /** The local index (owned or ghost) of the neighbour of stored bond @p n of owned particle @p
     * i. */
    unsigned int
    neighbor(const unsigned int i, const std::size_t n) const
    {
      return stencil_active ? layout.neighbor(i, stencil_index[n]) : neighbor_index[n];
    }

    /** Whether the neighbour of stored bond @p n of owned particle @p i is owned (and so takes its
     * share). */
    bool
    neighbor_is_owned(const unsigned int i, const std::size_t n) const
    {
      return neighbor(i, n) < n_owned;
    }

    /** Bond ends at owned particles (a bond between two owned particles counts twice). */
    std::size_t
    n_bond_ends() const;
    /** Bond ends at owned particles whose bond is broken. */
    std::size_t
    n_broken_bond_ends() const;
    /**
     * The sum of @p term(i, n) over the broken bonds n stored at owned particles i, on the
     * threads of this rank in fixed chunks of particles: the sum does not depend on the
     * number of threads.
     */
    template <typename T, typename Term>
    T
    sum_over_broken_bonds(const Term &term) const
    {
      return sum_over_chunks<T>(n_owned, [&](const unsigned int first, const unsigned int end) {
        T sum = T();
        for (unsigned int i = first; i < end; ++i)
          for (std::size_t n = family_begin[i]; n < family_begin[i + 1]; ++n)
            if (state[n] == broken)
              sum += term(i, n);
        return sum;
      });
    }
    /** Damage 1 - (intact bond volume)/(initial bond volume) of every owned particle. */
    std::vector<double>
    damage() const;
    /**
     * The owned particles of non-zero damage, ascending, with their damage (the values of
     * damage(), to the bit): under the stencil at the cost of the bonds of the particles
     * with a broken bond, not of every bond.
     */
    std::vector<std::pair<unsigned int, double>>
    damaged_particles() const;

  private:
    /**
     * Per owned particle, the owned index before whose family it keeps (invalid: build it), for
     * a layout just placed. Copies keep the storage rule (a bond between two owned particles
     * at the lower index) only if the particles held before keep their order: else none.
     */
    std::vector<unsigned int>
    families_to_keep(const PreviousNumbering &previous, const unsigned int n_owned_before) const;

    /**
     * Set the state of the bonds in @p broken_pairs to broken, without refreshing the layout;
     * with @p kept (per owned particle, valid if its family was kept as stored, breaks
     * included) only in the families not kept.
     */
    void
    mark_broken(const IdPairs                   &broken_pairs,
                const GhostExchange<dim>        &ghosts,
                const std::vector<unsigned int> *kept = nullptr);

    StencilLayout<dim> layout;
    bool               stencil_active = false;
    /** The neighbour of every stored bond, only with the bond lists (else empty). */
    std::vector<unsigned int> neighbor_index;
  };
} // namespace PeriArlequin

#endif
