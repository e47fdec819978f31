#ifndef periarlequin_pd_stencil_layout_h
#define periarlequin_pd_stencil_layout_h

#include <periarlequin/base/parallel_loops.h>
#include <periarlequin/pd/lattice.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/types.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  template <int dim>
  class BondFamilies;

  /** A bond as the bond families store it: the owned particle holding it, its storage number. */
  struct StoredBond
  {
    unsigned int particle;
    std::size_t  index;
  };

  /**
   * A bond as the stencil layout sees it: the slot of its end with the lower slot and its
   * half offset (StencilLayout::half_offsets).
   */
  struct SlotBond
  {
    std::size_t  slot;
    unsigned int half_offset;
  };

  /**
   * The bonds of one rank as a lattice stencil: the particles it holds (owned and ghosts)
   * placed in a box of lattice sites (x fastest, padded by the stencil's reach on every side),
   * so that the neighbour at stencil offset o of the site in slot s is in slot s + delta(o)
   * for every site. A force pass then loops over half of the offsets (delta > 0, each bond
   * once) and, for each, over a contiguous run of slots, with no neighbour indices: it
   * streams contiguous arrays and vectorises.
   *
   * A run is the held slots of one lattice line (from its first to its last held site); the
   * bond state is one byte per (slot of a run, half offset): for a bond with at least one
   * owned end its state in the CSR arrays (BondFamilies::BondState: 1 intact, 2 unbreakable),
   * 0 otherwise: broken, pre-cut, to a site not held
   * (outside the PD zone, a hole), or between two ghosts. The BondFamilies' CSR arrays stay
   * the description of the bonds; this is a view of them, refreshed by update_mask() after
   * their states change.
   *
   * The passes visit the slabs of even index, then those of odd index (see slabs); in a slab
   * the runs in the order of their lattice lines, per run the offsets in the stencil's order
   * and per offset the slots in order, a slot's term as the upper end of a bond before its
   * term as the lower end. A particle thus gets the term of each bond in an order fixed by
   * the lattice alone: its sums do not depend on the partition or on the number of threads
   * (bonds without an owned end add zero).
   */
  template <int dim>
  class StencilLayout
  {
  public:
    /** One lattice line's held slots. */
    struct Run
    {
      /** First slot. */
      std::size_t  begin;
      unsigned int length;
      /** Its bond states: mask[mask_begin + h length + (s - begin)] for half offset h. */
      std::size_t mask_begin;
    };

    /** One of the half of the stencil offsets whose slot shift is positive. */
    struct HalfOffset
    {
      std::size_t  delta;
      unsigned int stencil_index;
    };

    /**
     * Place the held particles, ids @p ids in local order, of @p lattice in the box, for the
     * stencil of @p bonds (built; its CSR arrays need not be): the bond states are all 0
     * until update_mask().
     */
    void
    place(const Lattice<dim>                    &lattice,
          ArrayView<const types::particle_index> ids,
          const BondFamilies<dim>               &bonds);

    /**
     * Let the force pass skip the bonds whose pair force is not used: those with no end in
     * @p force_used (per held particle, local index: its force density is used, an owned
     * particle of non-zero force weight) and those with no end in @p state_used (its force
     * state enters the pair forces, a non-zero state weight). Their terms are zero or go to
     * forces nobody reads. Holds until the next place().
     */
    void
    restrict_force_pass(const std::vector<bool> &force_used, const std::vector<bool> &state_used);

    /** The three passes over the bonds, for the slots each visits (pass_slots()). */
    enum class Pass
    {
      intact_volume,
      dilatation,
      force
    };

    /**
     * Let the next dilatation passes visit only the bonds with an end in the scalar window
     * and the next force passes only those with an end in the force window, until
     * clear_window(): after a change confined to a few particles (a growth of the zone), the
     * sums of the rest are known. @p window per held particle (local index): bit 0 in the
     * scalar window, bit 1 in the force window. A particle of a window gets every term of
     * its sums, in the order of a full pass, so the same bits; the sums of the other slots
     * are partial and must not be read (in_window()). The force pass needs the coefficients
     * of window_reach() only (for_each_read_particle()); it and the dilatation pass need the
     * displacements of every held particle (a visited bond without an end in a window must
     * not break on a stale one).
     */
    void
    restrict_to_window(std::vector<std::uint8_t> flags);
    /** Every pass visits all its slots again. */
    void
    clear_window();

    /** Whether restrict_to_window() holds. */
    bool
    has_window() const
    {
      return !window.empty();
    }

    /** Whether the sums of held particle @p i by the passes @p pass are complete. */
    bool
    in_window(const unsigned int i, const Pass pass) const
    {
      return window.empty() || pass == Pass::intact_volume ||
             (window[i] & (pass == Pass::force ? 2 : 1)) != 0;
    }

    /**
     * Under a window, the held particles within the stencil of a particle of either window
     * (the ends of the bonds the passes visit), in order; empty without one.
     */
    const std::vector<unsigned int> &
    window_reach() const
    {
      return reach_of_window;
    }

    /**
     * @p visit(i) for the held particles whose force coefficients the force pass reads: the
     * window_reach() under a window, else all @p n_held; on the threads.
     */
    template <typename Visitor>
    void
    for_each_read_particle(const unsigned int n_held, const Visitor &visit) const;

    /** The slots [first, end) of each (run, half offset) that the pass @p pass visits. */
    const std::vector<std::pair<unsigned int, unsigned int>> &
    pass_slots(const Pass pass) const
    {
      if (pass == Pass::intact_volume)
        return block_slots;
      if (window.empty())
        return pass == Pass::force ? force_block_slots : block_slots;
      return pass == Pass::force ? window_force_block_slots : window_block_slots;
    }

    /** The bond states from the CSR states of @p bonds (after they were built or bonds broke). */
    void
    update_mask(const BondFamilies<dim> &bonds);
    /**
     * The same after the held particles grew, at the cost of the families that changed: the
     * states of the lattice lines that @p before held are taken from it, then those of the
     * owned particles whose family was not kept (@p kept: the old local number of each owned
     * particle whose family, and relative order, are as before, else invalid) are written.
     * Right because particles were only added: every bond @p before knew is still stored at
     * the same end.
     */
    void
    update_mask(const BondFamilies<dim>         &bonds,
                const StencilLayout<dim>        &before,
                const std::vector<unsigned int> &kept);

    /**
     * The bond states after the bonds @p broken of @p bonds broke (their states are broken
     * now): what update_mask() gives, at the cost of the broken bonds, not of all bonds.
     */
    void
    clear_bonds(const BondFamilies<dim> &bonds, const std::vector<StoredBond> &broken);

    /**
     * The local index of the held particle at stencil entry @p k of held particle @p i, or
     * numbers::invalid_unsigned_int if that site is not held: the CSR arrays need no
     * neighbour indices of their own under the stencil.
     */
    unsigned int
    neighbor(const unsigned int i, const unsigned int k) const
    {
      return local_of_slot[neighbor_slot(i, k)];
    }

    /**
     * The slot of the lattice site at stencil entry @p k of held particle @p i, held or not
     * (the box's padding holds every site within the stencil of a held particle).
     */
    std::size_t
    neighbor_slot(const unsigned int i, const unsigned int k) const
    {
      return slot[i] + entry_shift[k];
    }

    /** The local indices of the ends of @p bond, the lower slot's first. */
    std::pair<unsigned int, unsigned int>
    ends(const SlotBond &bond) const
    {
      return {local_of_slot[bond.slot],
              local_of_slot[bond.slot + half_offsets[bond.half_offset].delta]};
    }

    /**
     * Call @p visit(h) for every bond of state non-zero with an end in the held slot @p s,
     * h its half offset, in the order in which the passes add the bonds' terms to the slot
     * (the slabs' phases, the runs, the half offsets, a slot's term as the upper end before
     * its term as the lower end): a sum in this order has the bits of a pass's sum, so a
     * slot's sum can be formed again alone after bonds broke.
     */
    template <typename Visitor>
    void
    for_each_bond_in_pass_order(const std::size_t s, const Visitor &visit) const;

    /**
     * Slots the dilatation pass and the force pass visit (sums of the lengths of
     * block_slots and force_block_slots): the work of each pass.
     */
    std::pair<std::size_t, std::size_t>
    visited_slots() const
    {
      std::pair<std::size_t, std::size_t> sums{0, 0};
      for (std::size_t b = 0; b < block_slots.size(); ++b)
        {
          sums.first += block_slots[b].second - block_slots[b].first;
          sums.second += force_block_slots[b].second - force_block_slots[b].first;
        }
      return sums;
    }

    /** Slots in the padded box. */
    std::size_t
    n_slots() const
    {
      return n_box_slots;
    }

    /** Slots of the box per held particle (1 for a full box; the cost of the layout). */
    double
    fill_ratio() const;

    /** Changes whenever the bond states change (unique over all layouts): for caches of what
     * derives from them. */
    unsigned int
    mask_version() const
    {
      return version;
    }

    /** The slot of every held particle, by local index. */
    std::vector<std::size_t>  slot;
    std::vector<Run>          runs;
    std::vector<HalfOffset>   half_offsets;
    std::vector<std::uint8_t> mask;
    /**
     * Per (run, half offset), run-major: the slots [first, end) of the run, counted from its
     * first slot, from the first to the last of its intact bonds with an owned end (first =
     * end if it has none). The passes visit only these: the slots outside them add zeros
     * (the ends of ghost lines, the surfaces).
     */
    std::vector<std::pair<unsigned int, unsigned int>> block_slots;
    /**
     * The same for the force pass: the slots of the bonds whose pair force is used (see
     * restrict_force_pass()); block_slots until that is called.
     */
    std::vector<std::pair<unsigned int, unsigned int>> force_block_slots;
    /** The longest run. */
    unsigned int max_run_length = 0;

    /**
     * The runs by slab: a slab is the lattice lines whose outermost lattice coordinate
     * (z in 3D, y in 2D) divided by the stencil's reach has one value k. A bond from a run of
     * slab k ends in slab k or k + 1, so the slabs of even k can be done at once, by
     * different threads, then those of odd k. slabs[p] holds the [first, end) run ranges of
     * the slabs with k % 2 = p, in order. k counts from the lattice's origin, so that a
     * particle gets its terms in the same order on every partition (for any thread count).
     */
    std::array<std::vector<std::pair<unsigned int, unsigned int>>, 2> slabs;

  private:
    /**
     * The run and the mask position of the bond at stencil entry @p k of held particle @p i,
     * whose slot lies on lattice line @p line.
     */
    std::pair<unsigned int, std::size_t>
    mask_entry(const unsigned int i, const std::size_t line, const unsigned int k) const
    {
      const unsigned int r = run_of_line[line + lower_end_line_shift[k]];
      return {r,
              runs[r].mask_begin + half_of_entry[k] * std::size_t(runs[r].length) +
                (slot[i] + lower_end_shift[k] - runs[r].begin)};
    }

    /** block_slots of run @p r and half offset @p h from the mask. */
    void
    trim_block(const unsigned int r, const std::size_t h);
    /** trim_block() of every run and half offset, on the threads. */
    void
    trim_blocks();

    std::array<std::size_t, dim> stride;
    std::array<int, dim>         lower;
    /** Per stencil entry: the half offset of the bond, seen from the end with the lower slot. */
    std::vector<unsigned int> half_of_entry;
    /** Per stencil entry: whether its own slot shift is positive (its owner is that end). */
    std::vector<bool> entry_is_half;
    /** Per stencil entry: its slot shift. */
    std::vector<std::ptrdiff_t> entry_shift;
    /**
     * Per stencil entry: the shift from a particle's slot to the lower slot of the bond (0 or
     * entry_shift), and from its lattice line to that slot's line. The box's padding keeps
     * every neighbour on the line its offset says, so the mask position of a bond needs no
     * division per bond.
     */
    std::vector<std::ptrdiff_t> lower_end_shift, lower_end_line_shift;
    /** The local index of the particle in every slot of the box, or invalid_unsigned_int. */
    std::vector<unsigned int> local_of_slot;
    std::size_t               n_box_slots = 0;
    /** The run of each lattice line of the box (by slot / stride[1]), or -1. */
    std::vector<int> run_of_line;
    /**
     * Per slot, bit 0: the force density of its particle is used; bit 1: its force state is
     * (restrict_force_pass(); empty: every bond's pair force is used).
     */
    std::vector<std::uint8_t> force_use;
    /**
     * Per held particle, bit 0: in the dilatation pass's window, bit 1: in the force pass's
     * (restrict_to_window(); empty: no window), and the slots of block_slots and
     * force_block_slots that hold the bonds with an end in each window.
     */
    std::vector<std::uint8_t>                          window;
    std::vector<std::pair<unsigned int, unsigned int>> window_block_slots, window_force_block_slots;
    /** See window_reach(). */
    std::vector<unsigned int> reach_of_window;
    /** The phase (0: even slabs, 1: odd) in which the passes visit each run. */
    std::vector<std::uint8_t> run_phase;
    unsigned int              n_held  = 0;
    unsigned int              version = 0;
  };
  template <int dim>
  template <typename Visitor>
  void
  StencilLayout<dim>::for_each_read_particle(const unsigned int n_held, const Visitor &visit) const
  {
    if (!has_window())
      for_each_subrange(n_held, [&](const unsigned int first, const unsigned int end) {
        for (unsigned int i = first; i < end; ++i)
          visit(i);
      });
    else
      for_each_subrange(reach_of_window.size(),
                        [&](const unsigned int first, const unsigned int end) {
                          for (unsigned int k = first; k < end; ++k)
                            visit(reach_of_window[k]);
                        });
  }

  template <int dim>
  template <typename Visitor>
  void
  StencilLayout<dim>::for_each_bond_in_pass_order(const std::size_t s, const Visitor &visit) const
  {
    // (phase, run, half offset, 0 for the upper end and 1 for the lower) of each bond.
    std::vector<std::array<std::size_t, 4>> terms;
    terms.reserve(2 * half_offsets.size());
    const std::size_t line_length = stride[1];
    const auto        add_term =
      [&](const std::size_t lower_slot, const unsigned int h, const std::size_t end) {
        const int r = run_of_line[lower_slot / line_length];
        if (r < 0 || lower_slot < runs[r].begin || lower_slot >= runs[r].begin + runs[r].length)
          return;
        if (mask[runs[r].mask_begin + h * std::size_t(runs[r].length) +
                 (lower_slot - runs[r].begin)] != 0)
          terms.push_back({{run_phase[r], std::size_t(r), h, end}});
      };
    for (unsigned int h = 0; h < half_offsets.size(); ++h)
      {
        add_term(s, h, 1);
        if (s >= half_offsets[h].delta)
          add_term(s - half_offsets[h].delta, h, 0);
      }
    std::sort(terms.begin(), terms.end());
    for (const auto &term : terms)
      visit(static_cast<unsigned int>(term[2]));
  }
} // namespace PeriArlequin

#endif
