#include <periarlequin/pd/bond_families.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace PeriArlequin
{
  template <int dim>
  void
  BondFamilies<dim>::build_stencil(const double dx, const double horizon)
  {
    stencil.clear();
    const int            reach = static_cast<int>(std::ceil(horizon / dx + 0.5));
    std::array<int, dim> o;
    const double         cell_volume = std::pow(dx, dim);
    const auto           visit       = [&](const auto &self, const unsigned int d) -> void {
      if (d == dim)
        {
          StencilEntry entry;
          entry.offset = o;
          bool zero    = true;
          for (unsigned int k = 0; k < dim; ++k)
            {
              entry.xi[k] = o[k] * dx;
              zero        = zero && o[k] == 0;
            }
          entry.length = entry.xi.norm();
          if (zero || entry.length >= horizon + 0.5 * dx)
            return;
          const double factor =
            entry.length <= horizon - 0.5 * dx ? 1. : (horizon - entry.length) / dx + 0.5;
          entry.volume = factor * cell_volume;
          stencil.push_back(entry);
          return;
        }
      for (o[d] = -reach; o[d] <= reach; ++o[d])
        self(self, d + 1);
    };
    visit(visit, 0);
    AssertThrow(stencil.size() < std::numeric_limits<std::uint16_t>::max(),
                ExcMessage("The horizon holds too many lattice neighbours (" +
                           std::to_string(stencil.size()) + "): reduce the horizon factor."));
  }

  template <int dim>
  std::size_t
  BondFamilies<dim>::n_bond_ends() const
  {
    std::size_t ends = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int n = family_begin[i]; n < family_begin[i + 1]; ++n)
        ends += neighbor_is_owned(i, n) ? 2 : 1;
    return ends;
  }

  template <int dim>
  std::size_t
  BondFamilies<dim>::n_broken_bond_ends() const
  {
    return sum_over_broken_bonds<std::size_t>(
      [&](const unsigned int i, const std::size_t n) -> std::size_t {
        return neighbor_is_owned(i, n) ? 2 : 1;
      });
  }

  template <int dim>
  std::vector<double>
  BondFamilies<dim>::damage() const
  {
    std::vector<double> all(n_owned, 0.), kept(n_owned, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int n = family_begin[i]; n < family_begin[i + 1]; ++n)
        {
          const double v        = stencil[stencil_index[n]].volume;
          const double intact_v = state[n] != broken ? v : 0.;
          all[i] += v;
          kept[i] += intact_v;
          const unsigned int j = neighbor(i, n);
          if (j < n_owned)
            {
              all[j] += v;
              kept[j] += intact_v;
            }
        }
    for (unsigned int i = 0; i < n_owned; ++i)
      all[i] = all[i] > 0 ? 1. - kept[i] / all[i] : 0.;
    return all;
  }

  template <int dim>
  std::vector<std::pair<unsigned int, double>>
  BondFamilies<dim>::damaged_particles() const
  {
    if (!stencil_active)
      {
        std::vector<std::pair<unsigned int, double>> damaged;
        const std::vector<double>                    all = damage();
        for (unsigned int i = 0; i < n_owned; ++i)
          if (all[i] > 0)
            damaged.emplace_back(i, all[i]);
        return damaged;
      }
    // On the threads: a chunk marks its own particles with a broken bond and lists the
    // owned other ends of those bonds (few), marked after.
    std::vector<std::uint8_t>       has_broken(n_owned, 0);
    const std::vector<unsigned int> other_ends = join_over_chunks<unsigned int>(
      n_owned,
      [&](const unsigned int first, const unsigned int end, std::vector<unsigned int> &ends) {
        for (unsigned int i = first; i < end; ++i)
          for (unsigned int n = family_begin[i]; n < family_begin[i + 1]; ++n)
            if (state[n] == broken)
              {
                has_broken[i] = 1;
                if (const unsigned int j = neighbor(i, n); j < n_owned)
                  ends.push_back(j);
              }
      });
    for (const unsigned int j : other_ends)
      has_broken[j] = 1;
    // damage() adds to a particle the bonds stored at the owned particles below it first, in
    // their order, then its own family: the same order here gives the same bits. The stencil
    // is symmetric and in lexicographic order, so the entry opposite k is size - 1 - k.
    const unsigned int n_entries = stencil.size();
    return join_over_chunks<std::pair<unsigned int, double>>(
      n_owned,
      [&](const unsigned int                            first,
          const unsigned int                            end,
          std::vector<std::pair<unsigned int, double>> &damaged) {
        std::vector<std::pair<unsigned int, std::uint16_t>> lower;
        for (unsigned int i = first; i < end; ++i)
          if (has_broken[i])
            {
              lower.clear();
              for (unsigned int k = 0; k < n_entries; ++k)
                if (const unsigned int j = layout.neighbor(i, k); j < i)
                  lower.emplace_back(j, static_cast<std::uint16_t>(n_entries - 1 - k));
              std::sort(lower.begin(), lower.end());
              double all = 0, kept = 0;
              for (const auto &[j, k] : lower)
                {
                  const auto first = stencil_index.begin() + family_begin[j];
                  const auto found =
                    std::lower_bound(first, stencil_index.begin() + family_begin[j + 1], k);
                  const std::size_t n = found - stencil_index.begin();
                  Assert(n < family_begin[j + 1] && stencil_index[n] == k && neighbor(j, n) == i,
                         ExcMessage("A bond to a particle below is not stored at that particle."));
                  const double v = stencil[k].volume;
                  all += v;
                  kept += state[n] != broken ? v : 0.;
                }
              for (unsigned int n = family_begin[i]; n < family_begin[i + 1]; ++n)
                {
                  const double v = stencil[stencil_index[n]].volume;
                  all += v;
                  kept += state[n] != broken ? v : 0.;
                }
              if (all > 0 && 1. - kept / all > 0)
                damaged.emplace_back(i, 1. - kept / all);
            }
      });
  }

  namespace
  {
    template <int dim>
    std::string
    point_text(const Point<dim> &x)
    {
      std::ostringstream text;
      text << x;
      return text.str();
    }
  } // namespace

  template <int dim>
  void
  BondFamilies<dim>::build(const Lattice<dim>                            &lattice,
                           GhostExchange<dim>                            &ghosts,
                           const std::function<bool(const Point<dim> &)> &extent,
                           const std::vector<PreCrack<dim>>              &pre_cracks,
                           const std::vector<bool>                       &no_fail,
                           const IdPairs                                 &broken_pairs,
                           const Kernel                                   kernel,
                           const PreviousNumbering                       *previous)
  {
    // The families being replaced, for those that stay as they were.
    const bool                 was_stencil  = stencil_active;
    const unsigned int         owned_before = n_owned;
    std::vector<unsigned int>  begin_before;
    std::vector<std::uint16_t> index_before;
    std::vector<std::uint8_t>  state_before;
    std::vector<double>        volume_before;
    if (previous)
      {
        begin_before.swap(family_begin);
        index_before.swap(stencil_index);
        state_before.swap(state);
        volume_before.swap(weighted_volume);
      }

    const unsigned int owned = ghosts.n_owned();
    const auto         x     = ghosts.reference_positions();
    const auto         ids   = ghosts.ids();
    n_owned                  = owned;
    n_total                  = ghosts.n_total();

    // The layout first: under the stencil a bond needs no neighbour index of its own. The
    // one replaced still knows the bond states of the families kept.
    StencilLayout<dim> layout_before;
    if (previous && was_stencil)
      layout_before = std::move(layout);
    layout         = StencilLayout<dim>();
    stencil_active = false;
    if (kernel != Kernel::bond_list)
      {
        layout.place(lattice, ids, *this);
        stencil_active = kernel == Kernel::stencil || layout.fill_ratio() <= max_stencil_fill_ratio;
        if (!stencil_active)
          layout = StencilLayout<dim>();
      }
    const std::vector<unsigned int> kept =
      previous && was_stencil && stencil_active ?
        families_to_keep(*previous, owned_before) :
        std::vector<unsigned int>(owned, numbers::invalid_unsigned_int);

    // visit_family(i, held) calls held(j, k) for every held neighbour j (stencil entry k) of
    // owned particle i, in the stencil's order. A bond between two owned particles is stored
    // at the lower local index only. Twice: to count the stored bonds, so that the arrays are
    // allocated once at their size, then to fill them.
    const auto stored_at = [owned](const unsigned int i, const unsigned int j) {
      return j >= owned || j > i;
    };
    // Under the stencil a site missing from a family is checked against the extent once, not
    // once for every family that misses it (1: checked, by its slot in the layout's box).
    std::vector<std::uint8_t> missing_site_checked(stencil_active ? layout.n_slots() : 0, 0);

    const auto visit_family = [&](const unsigned int i, const auto &held) {
      const auto site = lattice.site(ids[i]);
      for (unsigned int k = 0; k < stencil.size(); ++k)
        {
          // The layout finds a held neighbour at once; the lattice and the ids decide the rest.
          unsigned int j = stencil_active ? layout.neighbor(i, k) : numbers::invalid_unsigned_int;
          if (j != numbers::invalid_unsigned_int)
            {
              held(j, k);
              continue;
            }
          if (stencil_active)
            {
              std::uint8_t &checked = missing_site_checked[layout.neighbor_slot(i, k)];
              if (checked)
                continue;
              checked = 1;
            }
          const auto other = lattice.neighbour(site, stencil[k].offset);
          if (!other)
            continue;
          j = ghosts.local_index(lattice.id(*other));
          if (j == numbers::invalid_unsigned_int)
            {
              AssertThrow(!extent(lattice.position(*other)),
                          ExcMessage("Invalid input: a neighbour within the horizon of the "
                                     "particle at " +
                                     point_text(x[i]) +
                                     " m is neither owned nor a ghost particle: one layer "
                                     "of ghost cells does not cover the bonds there "
                                     "(Peridynamics/Horizon factor and Lattice spacing); "
                                     "allowed: background cells at least delta + dx/2 wide "
                                     "wherever particles are, also around them."));
              continue;
            }
          held(j, k);
        }
    };
    // A bond can cross a pre-crack only if its ends lie within a bond length of the crack's
    // bounding box: the crack is tested for those bonds alone.
    double longest_bond = 0;
    for (const auto &entry : stencil)
      longest_bond = std::max(longest_bond, entry.length);
    std::vector<std::uint8_t> near_crack(n_total, 0);
    for (const auto &crack : pre_cracks)
      {
        Box<dim> box{crack.origin, crack.origin};
        for (const auto &corner : {crack.origin + crack.edge_a,
                                   crack.origin + crack.edge_b,
                                   crack.origin + crack.edge_a + crack.edge_b})
          for (unsigned int d = 0; d < dim; ++d)
            {
              box.lower[d] = std::min(box.lower[d], corner[d]);
              box.upper[d] = std::max(box.upper[d], corner[d]);
            }
        for_each_subrange(n_total, [&](const unsigned int first, const unsigned int end) {
          for (unsigned int i = first; i < end; ++i)
            near_crack[i] = near_crack[i] || box.distance(x[i]) <= 1.01 * longest_bond;
        });
      }

    // One pass: about half of the stencil is stored a particle (a bond between two owned
    // particles once), more at the ghosts; reserved at that, the arrays rarely grow.
    const std::size_t estimate = static_cast<std::size_t>(owned) * (stencil.size() / 2 + 1);
    family_begin.assign(owned + 1, 0);
    stencil_index.clear();
    stencil_index.reserve(estimate);
    state.clear();
    state.reserve(estimate);
    neighbor_index.clear();
    if (!stencil_active)
      neighbor_index.reserve(estimate);
    weighted_volume.assign(n_total, 0.);
    bool any_kept = false;
    for (unsigned int i = 0; i < owned;)
      {
        if (const unsigned int p = kept[i]; p != numbers::invalid_unsigned_int)
          {
            // Kept families with consecutive old numbers are consecutive in the old arrays:
            // copied at once.
            unsigned int n = 1;
            while (i + n < owned && kept[i + n] == p + n)
              ++n;
            const std::size_t first = state.size();
            stencil_index.insert(stencil_index.end(),
                                 index_before.begin() + begin_before[p],
                                 index_before.begin() + begin_before[p + n]);
            state.insert(state.end(),
                         state_before.begin() + begin_before[p],
                         state_before.begin() + begin_before[p + n]);
            for (unsigned int m = 0; m < n; ++m)
              {
                weighted_volume[i + m]  = volume_before[p + m];
                family_begin[i + m + 1] = first + (begin_before[p + m + 1] - begin_before[p]);
              }
            i += n;
            any_kept = true;
            continue;
          }
        visit_family(i, [&](const unsigned int j, const unsigned int k) {
          // The full family gives the weighted volume.
          weighted_volume[i] += stencil[k].length * stencil[k].length * stencil[k].volume;
          if (!stored_at(i, j))
            return;
          // Test the crack with the ends in the order of their global ids, so that the
          // ranks holding the two ends decide alike even for a bond grazing a crack tip.
          const bool        i_first = ids[i] < ids[j];
          const Point<dim> &first   = x[i_first ? i : j];
          const Point<dim> &second  = x[i_first ? j : i];
          BondState         bond    = intact;
          if (near_crack[i] && near_crack[j])
            for (const auto &crack : pre_cracks)
              if (crack.cuts(first, second))
                bond = broken;
          if (bond != broken && (no_fail[i] || no_fail[j]))
            bond = unbreakable;
          state.push_back(bond);
          stencil_index.push_back(static_cast<std::uint16_t>(k));
          if (!stencil_active)
            neighbor_index.push_back(j);
        });
        family_begin[i + 1] = state.size();
        ++i;
      }
    ghosts.update_ghosts(make_array_view(weighted_volume), 1);
    mark_broken(broken_pairs, ghosts, any_kept ? &kept : nullptr);
    if (stencil_active && any_kept)
      layout.update_mask(*this, layout_before, kept);
    else if (stencil_active)
      layout.update_mask(*this);
  }

  template <int dim>
  std::vector<unsigned int>
  BondFamilies<dim>::families_to_keep(const PreviousNumbering &previous,
                                      const unsigned int       n_owned_before) const
  {
    AssertDimension(previous.owned_index.size(), n_owned);
    AssertDimension(previous.touched.size(), n_total);
    std::vector<unsigned int> keep(n_owned, numbers::invalid_unsigned_int);
    unsigned int              last = numbers::invalid_unsigned_int;
    for (unsigned int i = 0; i < n_owned; ++i)
      if (const unsigned int p = previous.owned_index[i]; p != numbers::invalid_unsigned_int)
        {
          if (p >= n_owned_before || (last != numbers::invalid_unsigned_int && p <= last))
            return std::vector<unsigned int>(n_owned, numbers::invalid_unsigned_int);
          keep[i] = last = p;
        }
    // A touched particle changes its own family and those of its stencil neighbours.
    const std::vector<std::uint8_t> changed = owned_within_reach(previous.touched);
    for (unsigned int i = 0; i < n_owned; ++i)
      if (changed[i])
        keep[i] = numbers::invalid_unsigned_int;
    return keep;
  }

  template <int dim>
  std::vector<std::uint8_t>
  BondFamilies<dim>::owned_within_reach(const std::vector<bool> &picked) const
  {
    AssertDimension(picked.size(), n_total);
    std::vector<std::uint8_t> reach(n_owned, stencil_active ? 0 : 1);
    if (stencil_active)
      for (unsigned int t = 0; t < n_total; ++t)
        if (picked[t])
          {
            if (t < n_owned)
              reach[t] = 1;
            for (unsigned int k = 0; k < stencil.size(); ++k)
              if (const unsigned int j = layout.neighbor(t, k); j < n_owned)
                reach[j] = 1;
          }
    return reach;
  }

  template <int dim>
  void
  BondFamilies<dim>::states_changed()
  {
    if (stencil_active)
      layout.update_mask(*this);
  }

  template <int dim>
  void
  BondFamilies<dim>::bonds_broke(const std::vector<StoredBond> &broken)
  {
    if (stencil_active)
      layout.clear_bonds(*this, broken);
  }

  template <int dim>
  std::vector<StoredBond>
  BondFamilies<dim>::break_stencil_bonds(const std::vector<SlotBond> &breaking)
  {
    std::vector<StoredBond> stored;
    stored.reserve(breaking.size());
    for (const SlotBond &bond : breaking)
      {
        // Ghosts are numbered after the owned particles: the end of lower local index is
        // owned, and stores the bond (see the class documentation).
        const auto [lower, upper] = layout.ends(bond);
        const unsigned int owner = std::min(lower, upper), other = std::max(lower, upper);
        unsigned int       n = family_begin[owner];
        while (n < family_begin[owner + 1] && neighbor(owner, n) != other)
          ++n;
        Assert(n < family_begin[owner + 1] && state[n] == intact,
               ExcMessage("A bond broken on the stencil is not an intact stored bond."));
        state[n] = broken;
        stored.push_back({owner, n});
      }
    std::sort(stored.begin(), stored.end(), [](const StoredBond &a, const StoredBond &b) {
      return a.index < b.index;
    });
    if (!stored.empty())
      layout.clear_bonds(*this, stored);
    return stored;
  }

  template <int dim>
  typename BondFamilies<dim>::IdPairs
  BondFamilies<dim>::broken_bonds(ArrayView<const types::particle_index> ids) const
  {
    // On the threads (a scan of every family, at each growth), joined in the order of a loop.
    return join_over_chunks<typename IdPairs::value_type>(
      n_owned,
      [&](const unsigned int first, const unsigned int end, IdPairs &broken_pairs) {
        for (unsigned int i = first; i < end; ++i)
          for (unsigned int n = family_begin[i]; n < family_begin[i + 1]; ++n)
            if (state[n] == broken)
              broken_pairs.emplace_back(std::minmax(ids[i], ids[neighbor(i, n)]));
      });
  }

  template <int dim>
  void
  BondFamilies<dim>::mark_broken(const IdPairs                   &broken_pairs,
                                 const GhostExchange<dim>        &ghosts,
                                 const std::vector<unsigned int> *kept)
  {
    // Per broken pair, the families of its owned ends: a few lookups per pair instead of one
    // per stored bond.
    const auto ids = ghosts.ids();
    for (const auto &pair : broken_pairs)
      for (const auto &[end, other] : {pair, std::make_pair(pair.second, pair.first)})
        {
          const unsigned int i = ghosts.local_index(end);
          if (i >= n_owned || (kept && (*kept)[i] != numbers::invalid_unsigned_int))
            continue;
          for (unsigned int n = family_begin[i]; n < family_begin[i + 1]; ++n)
            if (ids[neighbor(i, n)] == other)
              state[n] = broken;
        }
  }

  template <int dim>
  void
  BondFamilies<dim>::break_bonds(const IdPairs &broken_pairs, const GhostExchange<dim> &ghosts)
  {
    mark_broken(broken_pairs, ghosts);
    states_changed();
  }

  template class BondFamilies<2>;
  template class BondFamilies<3>;
} // namespace PeriArlequin
