#include <periarlequin/base/parallel_loops.h>
#include <periarlequin/pd/bond_families.h>
#include <periarlequin/pd/stencil_layout.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <unordered_map>

namespace PeriArlequin
{
  namespace
  {
    /** Versions are unique over all layouts, so a cache keyed by one never mistakes a new layout.
     */
    std::atomic<unsigned int> next_mask_version{1};
  } // namespace

  template <int dim>
  void
  StencilLayout<dim>::place(const Lattice<dim>                    &lattice,
                            ArrayView<const types::particle_index> ids,
                            const BondFamilies<dim>               &bonds)
  {
    n_held    = ids.size();
    int reach = 0;
    for (const auto &entry : bonds.stencil)
      for (unsigned int d = 0; d < dim; ++d)
        reach = std::max(reach, std::abs(entry.offset[d]));

    // The box of the held sites, padded by the reach so that every neighbour of a held site
    // has a slot of its own.
    // The sites and slots on the threads (a division per axis and particle, at every growth).
    std::vector<typename Lattice<dim>::Site> sites(n_held);
    for_each_subrange(n_held, [&](const unsigned int first, const unsigned int end) {
      for (unsigned int i = first; i < end; ++i)
        sites[i] = lattice.site(ids[i]);
    });
    std::array<int, dim> upper;
    lower.fill(std::numeric_limits<int>::max());
    upper.fill(std::numeric_limits<int>::min());
    for (unsigned int i = 0; i < n_held; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = std::min(lower[d], static_cast<int>(sites[i][d]));
          upper[d] = std::max(upper[d], static_cast<int>(sites[i][d]));
        }
    n_box_slots = n_held > 0 ? 1 : 0;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] -= reach;
        stride[d] = n_box_slots;
        n_box_slots *= n_held > 0 ? static_cast<std::size_t>(upper[d] + reach - lower[d] + 1) : 0;
      }

    slot.resize(n_held);
    local_of_slot.assign(n_box_slots, numbers::invalid_unsigned_int);
    // Every held site has a slot of its own: the threads write different entries.
    for_each_subrange(n_held, [&](const unsigned int first, const unsigned int end) {
      for (unsigned int i = first; i < end; ++i)
        {
          slot[i] = 0;
          for (unsigned int d = 0; d < dim; ++d)
            slot[i] += static_cast<std::size_t>(sites[i][d] - lower[d]) * stride[d];
          local_of_slot[slot[i]] = i;
        }
    });

    // Runs: the held slots of each lattice line, in the order of the lines.
    const std::size_t line_length = n_held > 0 ? stride[1] : 1;
    run_of_line.assign(n_box_slots / line_length, -1);
    std::vector<std::pair<std::size_t, std::size_t>> extent(run_of_line.size(), {line_length, 0});
    for (unsigned int i = 0; i < n_held; ++i)
      {
        auto &[first, last] = extent[slot[i] / line_length];
        first               = std::min(first, slot[i] % line_length);
        last                = std::max(last, slot[i] % line_length);
      }

    // Half of the offsets: those with a positive slot shift, in the stencil's order.
    half_offsets.clear();
    half_of_entry.assign(bonds.stencil.size(), 0);
    entry_is_half.assign(bonds.stencil.size(), false);
    entry_shift.assign(bonds.stencil.size(), 0);
    std::unordered_map<std::ptrdiff_t, unsigned int> half_of_shift;
    for (unsigned int k = 0; k < bonds.stencil.size(); ++k)
      {
        for (unsigned int d = 0; d < dim; ++d)
          entry_shift[k] += bonds.stencil[k].offset[d] * static_cast<std::ptrdiff_t>(stride[d]);
        if (entry_shift[k] > 0)
          {
            half_of_shift[entry_shift[k]] = half_offsets.size();
            half_of_entry[k]              = half_offsets.size();
            entry_is_half[k]              = true;
            half_offsets.push_back({static_cast<std::size_t>(entry_shift[k]), k});
          }
      }
    // A rank that holds no particle has no box: no shifts and no bonds to look up.
    lower_end_shift.assign(bonds.stencil.size(), 0);
    lower_end_line_shift.assign(bonds.stencil.size(), 0);
    if (n_held > 0)
      for (unsigned int k = 0; k < bonds.stencil.size(); ++k)
        if (!entry_is_half[k])
          {
            half_of_entry[k]   = half_of_shift.at(-entry_shift[k]);
            lower_end_shift[k] = entry_shift[k];
            for (unsigned int d = 1; d < dim; ++d)
              lower_end_line_shift[k] +=
                bonds.stencil[k].offset[d] * static_cast<std::ptrdiff_t>(stride[d] / stride[1]);
          }

    runs.clear();
    max_run_length        = 0;
    std::size_t mask_size = 0;
    for (std::size_t line = 0; line < run_of_line.size(); ++line)
      if (extent[line].first <= extent[line].second)
        {
          const unsigned int length = extent[line].second - extent[line].first + 1;
          run_of_line[line]         = runs.size();
          runs.push_back({line * line_length + extent[line].first, length, mask_size});
          mask_size += half_offsets.size() * length;
          max_run_length = std::max(max_run_length, length);
        }
    mask.assign(mask_size, 0);
    block_slots.assign(runs.size() * half_offsets.size(), {0, 0});
    force_block_slots = block_slots;
    force_use.clear();
    clear_window();

    // Slabs of the outermost coordinate, counted from the lattice's origin.
    const unsigned int thickness = std::max(reach, 1);
    for (auto &ranges : slabs)
      ranges.clear();
    long previous_slab = -1;
    run_phase.resize(runs.size());
    for (unsigned int r = 0; r < runs.size(); ++r)
      {
        const long coordinate = static_cast<long>(runs[r].begin / stride[dim - 1]) + lower[dim - 1];
        const long slab       = coordinate / thickness;
        auto      &ranges     = slabs[slab % 2];
        run_phase[r]          = slab % 2;
        if (slab != previous_slab)
          ranges.emplace_back(r, r + 1);
        else
          ranges.back().second = r + 1;
        previous_slab = slab;
      }
  }

  template <int dim>
  void
  StencilLayout<dim>::trim_block(const unsigned int r, const std::size_t h)
  {
    const std::size_t   block  = r * half_offsets.size() + h;
    const std::uint8_t *states = mask.data() + runs[r].mask_begin + h * runs[r].length;
    const std::size_t   first = runs[r].begin, delta = half_offsets[h].delta;
    // [first, end) of the slots q of the run for which @p counts(q) holds, or {0, 0}.
    const auto bounds = [&](const auto &counts) -> std::pair<unsigned int, unsigned int> {
      unsigned int begin = 0, end = runs[r].length;
      while (begin < end && !counts(begin))
        ++begin;
      while (end > begin && !counts(end - 1))
        --end;
      return begin < end ? std::make_pair(begin, end) : std::make_pair(0u, 0u);
    };
    block_slots[block] = bounds([&](const unsigned int q) { return states[q] != 0; });
    if (force_use.empty())
      force_block_slots[block] = block_slots[block];
    else
      force_block_slots[block] = bounds([&](const unsigned int q) {
        const std::uint8_t lower = force_use[first + q], upper = force_use[first + q + delta];
        return states[q] != 0 && ((lower | upper) & 1) && ((lower | upper) & 2);
      });
  }

  template <int dim>
  void
  StencilLayout<dim>::trim_blocks()
  {
    for_each_subrange(
      runs.size(),
      [&](const unsigned int first, const unsigned int end) {
        for (unsigned int r = first; r < end; ++r)
          for (std::size_t h = 0; h < half_offsets.size(); ++h)
            trim_block(r, h);
      },
      64);
  }

  template <int dim>
  void
  StencilLayout<dim>::restrict_force_pass(const std::vector<bool> &force_used,
                                          const std::vector<bool> &state_used)
  {
    force_use.assign(n_box_slots, 0);
    for (unsigned int i = 0; i < slot.size(); ++i)
      force_use[slot[i]] = (force_used[i] ? 1 : 0) | (state_used[i] ? 2 : 0);
    trim_blocks();
  }

  template <int dim>
  void
  StencilLayout<dim>::restrict_to_window(std::vector<std::uint8_t> flags)
  {
    AssertDimension(flags.size(), n_held);
    window = std::move(flags);
    // Per run and window, the slots [first, end) from the first to the last particle in it,
    // counted from the run's first slot; the particles within reach of either window.
    constexpr unsigned int none = std::numeric_limits<unsigned int>::max();
    std::array<std::vector<std::pair<unsigned int, unsigned int>>, 2> run_window;
    for (auto &bounds : run_window)
      bounds.assign(runs.size(), {none, 0});
    const std::size_t         line_length = stride[1];
    std::vector<std::uint8_t> in_reach(n_held, 0);
    for (unsigned int i = 0; i < n_held; ++i)
      if (window[i] != 0)
        {
          const int r = run_of_line[slot[i] / line_length];
          for (unsigned int w = 0; w < 2; ++w)
            if (window[i] & (1u << w))
              {
                const unsigned int q    = slot[i] - runs[r].begin;
                run_window[w][r].first  = std::min(run_window[w][r].first, q);
                run_window[w][r].second = std::max(run_window[w][r].second, q + 1);
              }
          in_reach[i] = 1;
          for (const std::ptrdiff_t shift : entry_shift)
            if (const unsigned int j = local_of_slot[slot[i] + shift];
                j != numbers::invalid_unsigned_int)
              in_reach[j] = 1;
        }
    reach_of_window.clear();
    for (unsigned int i = 0; i < n_held; ++i)
      if (in_reach[i])
        reach_of_window.push_back(i);
    // A block's lower ends are the slots of its run, its upper ends those slots shifted by
    // delta, on one other line: the slots whose lower or upper end is in a window span the
    // hull of two intervals, cut to the slots the pass visits anyway.
    const auto window_bounds = [&](const std::vector<std::pair<unsigned int, unsigned int>> &all,
                                   const std::vector<std::pair<unsigned int, unsigned int>> &in,
                                   std::vector<std::pair<unsigned int, unsigned int>> &bounds) {
      bounds.assign(all.size(), {0, 0});
      for (unsigned int r = 0; r < runs.size(); ++r)
        for (std::size_t h = 0; h < half_offsets.size(); ++h)
          {
            const std::size_t block = r * half_offsets.size() + h;
            long first = std::numeric_limits<long>::max(), end = std::numeric_limits<long>::min();
            if (in[r].first != none)
              {
                first = in[r].first;
                end   = in[r].second;
              }
            const std::size_t upper_line = (runs[r].begin + half_offsets[h].delta) / line_length;
            if (upper_line < run_of_line.size() && run_of_line[upper_line] >= 0)
              {
                const unsigned int u = run_of_line[upper_line];
                if (in[u].first != none)
                  {
                    const long shift = static_cast<long>(runs[u].begin) -
                                       static_cast<long>(runs[r].begin + half_offsets[h].delta);
                    first = std::min(first, shift + in[u].first);
                    end   = std::max(end, shift + in[u].second);
                  }
              }
            first = std::max(first, static_cast<long>(all[block].first));
            end   = std::min(end, static_cast<long>(all[block].second));
            if (first < end)
              bounds[block] = {static_cast<unsigned int>(first), static_cast<unsigned int>(end)};
          }
    };
    window_bounds(block_slots, run_window[0], window_block_slots);
    window_bounds(force_block_slots, run_window[1], window_force_block_slots);
  }

  template <int dim>
  void
  StencilLayout<dim>::clear_window()
  {
    window.clear();
    reach_of_window.clear();
    window_block_slots.clear();
    window_force_block_slots.clear();
  }

  template <int dim>
  void
  StencilLayout<dim>::update_mask(const BondFamilies<dim> &bonds)
  {
    // No old layout, no family kept: every family written.
    update_mask(bonds,
                StencilLayout<dim>(),
                std::vector<unsigned int>(bonds.n_owned, numbers::invalid_unsigned_int));
  }

  template <int dim>
  void
  StencilLayout<dim>::update_mask(const BondFamilies<dim>         &bonds,
                                  const StencilLayout<dim>        &before,
                                  const std::vector<unsigned int> &kept)
  {
    AssertDimension(kept.size(), bonds.n_owned);
    Assert(before.n_held == 0 || before.half_offsets.size() == half_offsets.size(),
           ExcMessage("The old layout has another stencil."));
    std::fill(mask.begin(), mask.end(), 0);
    // The box's extent in direction d (the lattice lines run along direction 0).
    const auto extent = [](const StencilLayout<dim> &layout, const unsigned int d) {
      return (d + 1 < dim ? layout.stride[d + 1] : layout.n_box_slots) / layout.stride[d];
    };
    // Each run on a line the old box held: the old states of its sites. A line's held
    // sites only grew, so the old run lies within the new one.
    if (before.n_held > 0)
      for_each_subrange(
        runs.size(),
        [&](const unsigned int first, const unsigned int end) {
          for (unsigned int r = first; r < end; ++r)
            {
              std::size_t line = runs[r].begin / stride[1], old_slot = 0;
              bool        inside = true;
              for (unsigned int d = 1; d < dim; ++d)
                {
                  const long site = static_cast<long>(line % extent(*this, d)) + lower[d];
                  line /= extent(*this, d);
                  const long old_coordinate = site - before.lower[d];
                  inside                    = inside && old_coordinate >= 0 &&
                           old_coordinate < static_cast<long>(extent(before, d));
                  old_slot += old_coordinate * before.stride[d];
                }
              if (!inside || before.run_of_line[old_slot / before.stride[1]] < 0)
                continue;
              const Run &old    = before.runs[before.run_of_line[old_slot / before.stride[1]]];
              const long offset = static_cast<long>(old.begin % before.stride[1]) +
                                  before.lower[0] -
                                  (static_cast<long>(runs[r].begin % stride[1]) + lower[0]);
              Assert(offset >= 0 && offset + old.length <= runs[r].length,
                     ExcMessage("A lattice line held fewer sites after the particles grew."));
              for (std::size_t h = 0; h < half_offsets.size(); ++h)
                std::copy_n(before.mask.begin() + old.mask_begin + h * old.length,
                            old.length,
                            mask.begin() + runs[r].mask_begin + h * runs[r].length + offset);
            }
        },
        64);
    // The families that changed.
    for_each_subrange(bonds.n_owned, [&](const unsigned int first, const unsigned int end) {
      for (unsigned int i = first; i < end; ++i)
        if (kept[i] == numbers::invalid_unsigned_int)
          {
            const std::size_t line = slot[i] / stride[1];
            for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
              mask[mask_entry(i, line, bonds.stencil_index[n]).second] = bonds.state[n];
          }
    });
    trim_blocks();
    version = next_mask_version++;
  }

  template <int dim>
  void
  StencilLayout<dim>::clear_bonds(const BondFamilies<dim>       &bonds,
                                  const std::vector<StoredBond> &broken)
  {
    // The (run, half offset) blocks whose bounds may move, each trimmed once.
    std::vector<std::pair<unsigned int, std::size_t>> blocks;
    blocks.reserve(broken.size());
    for (const auto &bond : broken)
      {
        const unsigned int k       = bonds.stencil_index[bond.index];
        const auto [run, position] = mask_entry(bond.particle, slot[bond.particle] / stride[1], k);
        mask[position]             = 0;
        blocks.emplace_back(run, half_of_entry[k]);
      }
    std::sort(blocks.begin(), blocks.end());
    blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
    for (const auto &[r, h] : blocks)
      trim_block(r, h);
    version = next_mask_version++;
  }

  template <int dim>
  double
  StencilLayout<dim>::fill_ratio() const
  {
    return n_held > 0 ? static_cast<double>(n_box_slots) / n_held : 1.;
  }

  template class StencilLayout<2>;
  template class StencilLayout<3>;
} // namespace PeriArlequin
