#include <periarlequin/pd/bond_families.h>

#include <sstream>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <limits>
#include <unordered_map>

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
          const double factor = entry.length <= horizon - 0.5 * dx ?
                                  1. :
                                  (horizon - entry.length) / dx + 0.5;
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
  void
  BondFamilies<dim>::begin_family()
  {
    family_begin.push_back(family_begin.back());
  }

  template <int dim>
  void
  BondFamilies<dim>::add_bond(const unsigned int neighbor_index,
                              const unsigned int stencil_entry,
                              const BondState    bond_state)
  {
    neighbor.push_back(neighbor_index);
    stencil_index.push_back(static_cast<std::uint16_t>(stencil_entry));
    state.push_back(bond_state);
    ++family_begin.back();
  }

  template <int dim>
  void
  BondFamilies<dim>::end_families(const unsigned int owned, const unsigned int total)
  {
    AssertThrow(family_begin.size() == owned + 1, ExcInternalError());
    n_owned = owned;
    n_total = total;
  }

  template <int dim>
  std::size_t
  BondFamilies<dim>::n_bond_ends() const
  {
    std::size_t ends = 0;
    for (std::size_t n = 0; n < neighbor.size(); ++n)
      ends += neighbor_is_owned(n) ? 2 : 1;
    return ends;
  }

  template <int dim>
  std::size_t
  BondFamilies<dim>::n_broken_bond_ends() const
  {
    std::size_t ends = 0;
    for (std::size_t n = 0; n < neighbor.size(); ++n)
      if (state[n] == broken)
        ends += neighbor_is_owned(n) ? 2 : 1;
    return ends;
  }

  template <int dim>
  std::vector<double>
  BondFamilies<dim>::damage() const
  {
    std::vector<double> all(n_owned, 0.), kept(n_owned, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int n = family_begin[i]; n < family_begin[i + 1]; ++n)
        {
          const double v         = stencil[stencil_index[n]].volume;
          const double intact_v  = state[n] != broken ? v : 0.;
          all[i] += v;
          kept[i] += intact_v;
          if (neighbor_is_owned(n))
            {
              all[neighbor[n]] += v;
              kept[neighbor[n]] += intact_v;
            }
        }
    for (unsigned int i = 0; i < n_owned; ++i)
      all[i] = all[i] > 0 ? 1. - kept[i] / all[i] : 0.;
    return all;
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
  BondFamilies<dim>::build(const Lattice<dim>                           &lattice,
                           GhostExchange<dim>                           &ghosts,
                           const std::function<bool(const Point<dim> &)> &extent,
                           const std::vector<PreCrack<dim>>             &pre_cracks,
                           const std::function<bool(const Point<dim> &)> &no_fail,
                           const Kernel                                  kernel)
  {
    const unsigned int owned = ghosts.n_owned();
    const auto         x       = ghosts.reference_positions();
    const auto         ids     = ghosts.ids();
    family_begin.assign(1, 0);
    neighbor.clear();
    stencil_index.clear();
    state.clear();
    weighted_volume.assign(ghosts.n_total(), 0.);

    for (unsigned int i = 0; i < owned; ++i)
      {
        const auto site = lattice.site(ids[i]);
        begin_family();
        for (unsigned int k = 0; k < stencil.size(); ++k)
          {
            const auto other = lattice.neighbour(site, stencil[k].offset);
            if (!other)
              continue;
            const unsigned int j = ghosts.local_index(lattice.id(*other));
            if (j == numbers::invalid_unsigned_int)
              {
                AssertThrow(!extent(lattice.position(*other)),
                            ExcMessage("Invalid input: a neighbour within the horizon of the "
                                       "particle at " + point_text(x[i]) +
                                       " m is neither owned nor a ghost particle: one layer "
                                       "of ghost cells does not cover the bonds there "
                                       "(Peridynamics/Horizon factor and Lattice spacing); "
                                       "allowed: background cells at least delta + dx/2 wide "
                                       "wherever particles are, also around them."));
                continue;
              }
            // The full family gives the weighted volume; a bond between two owned particles
            // is stored only at the lower local index.
            weighted_volume[i] +=
              stencil[k].length * stencil[k].length * stencil[k].volume;
            if (j < owned && j < i)
              continue;
            // Test the crack with the ends in the order of their global ids, so that the
            // ranks holding the two ends decide alike even for a bond grazing a crack tip.
            const bool        i_first = ids[i] < ids[j];
            const Point<dim> &first   = x[i_first ? i : j];
            const Point<dim> &second  = x[i_first ? j : i];
            auto              bond_state = BondFamilies<dim>::intact;
            for (const auto &crack : pre_cracks)
              if (crack.cuts(first, second))
                bond_state = BondFamilies<dim>::broken;
            if (bond_state != BondFamilies<dim>::broken && (no_fail(x[i]) || no_fail(x[j])))
              bond_state = BondFamilies<dim>::unbreakable;
            add_bond(j, k, bond_state);
          }
      }
    end_families(owned, ghosts.n_total());
    ghosts.update_ghosts(make_array_view(weighted_volume), 1);

    layout         = StencilLayout<dim>();
    stencil_active = false;
    if (kernel != Kernel::bond_list)
      {
        layout.build(lattice, ids, *this);
        stencil_active =
          kernel == Kernel::stencil || layout.fill_ratio() <= max_stencil_fill_ratio;
        if (!stencil_active)
          layout = StencilLayout<dim>();
      }
  }

  template <int dim>
  void
  BondFamilies<dim>::states_changed()
  {
    if (stencil_active)
      layout.update_mask(*this);
  }

  template <int dim>
  std::set<typename BondFamilies<dim>::IdPair>
  BondFamilies<dim>::broken_bonds(ArrayView<const types::particle_index> ids) const
  {
    std::set<IdPair> broken_pairs;
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int n = family_begin[i]; n < family_begin[i + 1]; ++n)
        if (state[n] == broken)
          broken_pairs.emplace(std::minmax(ids[i], ids[neighbor[n]]));
    return broken_pairs;
  }

  template <int dim>
  void
  BondFamilies<dim>::break_bonds(const std::set<IdPair>               &broken_pairs,
                                 ArrayView<const types::particle_index> ids)
  {
    // Per broken pair, the families of its owned ends: a few lookups per pair instead of one
    // per stored bond.
    std::unordered_map<types::particle_index, unsigned int> owned_index;
    owned_index.reserve(n_owned);
    for (unsigned int i = 0; i < n_owned; ++i)
      owned_index.emplace(ids[i], i);
    for (const auto &pair : broken_pairs)
      for (const auto &[end, other] : {pair, std::make_pair(pair.second, pair.first)})
        {
          const auto found = owned_index.find(end);
          if (found == owned_index.end())
            continue;
          const unsigned int i = found->second;
          for (unsigned int n = family_begin[i]; n < family_begin[i + 1]; ++n)
            if (ids[neighbor[n]] == other)
              state[n] = broken;
        }
    states_changed();
  }

  template class BondFamilies<2>;
  template class BondFamilies<3>;
} // namespace PeriArlequin
