#include <periarlequin/pd/bond_families.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <limits>

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
    family_begin.assign(1, 0);
    neighbor.clear();
    stencil_index.clear();
    state.clear();
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

  template class BondFamilies<2>;
  template class BondFamilies<3>;
} // namespace PeriArlequin
