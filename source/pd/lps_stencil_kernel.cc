// The LPS dilatation and force passes on the stencil layout of the bonds (see StencilLayout):
// for each run of slots and each half offset, a loop over contiguous slots that the
// compiler vectorises (#pragma omp simd; this file is compiled with -fopenmp-simd, no
// OpenMP runtime). Debian's deal.II is built for generic x86-64, so the passes are compiled
// for AVX-512, AVX2 and the baseline and the loader picks one (target_clones); the file is
// compiled without FMA contraction (-ffp-contract=off), so all three give the same bits.
#include <periarlequin/base/parallel_loops.h>
#include <periarlequin/pd/material_model.h>

#include <deal.II/base/parallel.h>

#include <algorithm>
#include <mutex>

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#  define PERIARLEQUIN_KERNEL_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#  define PERIARLEQUIN_KERNEL_CLONES
#endif

namespace PeriArlequin
{
  namespace
  {
    /** Slots per chunk of a run: the chunk's bond values stay in the L1 cache. */
    constexpr unsigned int chunk_length = 256;

    /** What a pass over one (run, half offset) block reads: the bond and the two ends. */
    template <int dim>
    struct Block
    {
      double      xi[dim];
      double      length, volume;
      std::size_t first, delta;
      /** The half offset (StencilLayout::half_offsets) and the number of slots. */
      unsigned int        half, n;
      const std::uint8_t *mask;
      /**
       * Whether the pass may add to both ends inside its vector loop: the ends are at least
       * simd_distance slots apart, so no two lanes write one slot and a slot's terms come in
       * the order of the slots (else the pass goes through the chunk, upper ends first, in
       * the same order).
       */
      bool direct;
    };

    /** The ends of a block may share a vector of this many lanes only this far apart. */
    constexpr unsigned int simd_distance = 8;

    /** Runs [first, end) of a layout, and the scratch of a thread for a chunk of a run. */
    struct RunRange
    {
      unsigned int first, end;
      double      *chunk;
    };

    /**
     * Visit the blocks of the runs @p range of @p layout chunk by chunk: @p visit(block) for
     * each run, half offset and chunk of the block's slots that the @p pass visits
     * (StencilLayout::pass_slots()), in this order: the slots outside them would add zeros,
     * or terms nobody reads.
     */
    template <int dim, typename Visitor>
    inline __attribute__((always_inline)) void
    for_each_block(const StencilLayout<dim>                                    &layout,
                   const std::vector<typename BondFamilies<dim>::StencilEntry> &stencil,
                   const RunRange                                              &range,
                   const Visitor                                               &visit,
                   const typename StencilLayout<dim>::Pass                      pass)
    {
      const auto &bounds = layout.pass_slots(pass);
      Block<dim>  block;
      for (unsigned int r = range.first; r < range.end; ++r)
        for (unsigned int h = 0; h < layout.half_offsets.size(); ++h)
          {
            const auto [begin, end] = bounds[r * layout.half_offsets.size() + h];
            if (begin == end)
              continue;
            const auto &run  = layout.runs[r];
            const auto &half = layout.half_offsets[h];
            const auto &bond = stencil[half.stencil_index];
            for (unsigned int d = 0; d < dim; ++d)
              block.xi[d] = bond.xi[d];
            block.length = bond.length;
            block.volume = bond.volume;
            block.delta  = half.delta;
            block.half   = h;
            block.direct = half.delta >= simd_distance;
            const std::uint8_t *mask =
              layout.mask.data() + run.mask_begin + h * std::size_t(run.length);
            for (unsigned int first = begin; first < end; first += chunk_length)
              {
                block.first = run.begin + first;
                block.n     = std::min(chunk_length, end - first);
                block.mask  = mask + first;
                visit(block);
              }
          }
    }

    /**
     * The deformed length |xi + eta| of the bond q of a block, from the displacement
     * components @p ui at its lower ends and @p uj at its upper ends, and the numerator
     * 2 xi.eta + eta.eta of its extension e = numerator / (|xi + eta| + |xi|): the terms of
     * BondFamilies::extension().
     */
    template <int dim>
    inline __attribute__((always_inline)) double
    deformed_length(const double        *xi,
                    const double *const *ui,
                    const double *const *uj,
                    const int            q,
                    double              &numerator)
    {
      // Component by component, without a loop: a loop here keeps the compiler from
      // vectorising over q.
      double     xi_eta = 0, eta_eta = 0, length_squared = 0;
      const auto add = [&](const unsigned int d) __attribute__((always_inline))
      {
        const double eta = uj[d][q] - ui[d][q];
        xi_eta += xi[d] * eta;
        eta_eta += eta * eta;
        const double y = xi[d] + eta;
        length_squared += y * y;
      };
      add(0);
      add(1);
      if constexpr (dim == 3)
        add(2);
      numerator = 2. * xi_eta + eta_eta;
      return std::sqrt(length_squared);
    }

    /** The pointers to the @p dim components of @p values (n_slots each) at slot @p first. */
    template <int dim>
    inline __attribute__((always_inline)) void
    component_pointers(const double     *values,
                       const std::size_t n_slots,
                       const std::size_t first,
                       const double    **pointers)
    {
      for (unsigned int d = 0; d < dim; ++d)
        pointers[d] = values + d * n_slots + first;
    }

    /** The bond states of a block as doubles (1 or 0): all lanes of the passes are doubles. */
    inline __attribute__((always_inline)) void
    unpack_mask(const std::uint8_t *mask, const int n, double *__restrict intact)
    {
#pragma omp simd
      for (int q = 0; q < n; ++q)
        intact[q] = mask[q];
    }

    /**
     * Add the chunk's values to the upper ends (times @p upper_sign), then to the lower ends:
     * a slot that is both gets its lower neighbour's term first, as in a loop over the slots
     * in order, whatever the chunk boundaries (they depend on where a rank's run starts).
     */
    inline __attribute__((always_inline)) void
    add_to_ends(double       *lower_end,
                double       *upper_end,
                const double *values,
                const double  upper_sign,
                const int     n)
    {
#pragma omp simd
      for (int q = 0; q < n; ++q)
        upper_end[q] += upper_sign * values[q];
#pragma omp simd
      for (int q = 0; q < n; ++q)
        lower_end[q] += values[q];
    }

    /** Sum of x^2 V v over the intact bonds of every slot. */
    template <int dim>
    inline __attribute__((always_inline)) void
    intact_volume_pass_impl(const StencilLayout<dim>                                    &layout,
                            const std::vector<typename BondFamilies<dim>::StencilEntry> &stencil,
                            double                                                      *volume,
                            const RunRange                                              &range)
    {
      double *const chunk = range.chunk;
      for_each_block(
        layout,
        stencil,
        range,
        [&](const Block<dim> &block) __attribute__((always_inline)) {
          const double weighted = block.length * block.length * block.volume;
#pragma omp simd
          for (unsigned int q = 0; q < block.n; ++q)
            chunk[q] = block.mask[q] ? weighted : 0.;
          add_to_ends(volume + block.first, volume + block.first + block.delta, chunk, 1., block.n);
        },
        StencilLayout<dim>::Pass::intact_volume);
    }

    /**
     * Where the moment pass breaks bonds: every breakable bond (state intact, 1) whose
     * stretch e / |xi| exceeds @p stretch breaks before its term is added, and its slot and
     * half offset go to @p bonds (under @p lock: the threads of a pass share it).
     */
    struct BondBreaking
    {
      double                 stretch;
      std::vector<SlotBond> *bonds;
      std::mutex            *lock;
    };

    /**
     * Sum of x e V v over the intact bonds of every slot; with @p breaking (Breaks) the
     * bonds that it breaks are left out. A bond breaks on the comparison
     * BreakableBonds::break_above_stretch() makes, with the extension in the same
     * operations, so the two break the same bonds.
     */
    template <int dim, bool breaks>
    inline __attribute__((always_inline)) void
    moment_pass_impl(const StencilLayout<dim>                                    &layout,
                     const std::vector<typename BondFamilies<dim>::StencilEntry> &stencil,
                     const double                                                *u,
                     double                                                      *moment,
                     const BondBreaking                                          &breaking,
                     const RunRange                                              &range)
    {
      const std::size_t n_slots = layout.n_slots();
      double *const     chunk   = range.chunk;
      for_each_block(
        layout,
        stencil,
        range,
        [=](const Block<dim> &block) __attribute__((always_inline)) {
          const Block<dim>    b    = block;
          const std::uint8_t *mask = b.mask;
          const double       *ui[dim], *uj[dim];
          component_pointers<dim>(u, n_slots, b.first, ui);
          component_pointers<dim>(u, n_slots, b.first + b.delta, uj);
          const int n               = b.n;
          double *__restrict values = chunk, *__restrict intact = chunk + chunk_length,
                             *__restrict broke = chunk + 2 * chunk_length;
          unpack_mask(mask, n, intact);
          const double limit = breaks ? breaking.stretch * b.length : 0.;
          // The term of bond q, and 1 in broke[q] if it breaks here (else 0).
          const auto term = [&](const int q) __attribute__((always_inline))
          {
            double       numerator;
            const double l = deformed_length<dim>(b.xi, ui, uj, q, numerator);
            const double e = numerator / (l + b.length);
            if constexpr (breaks)
              {
                broke[q] = intact[q] == double(BondFamilies<dim>::intact) && e > limit ? 1. : 0.;
                return intact[q] != 0. && broke[q] == 0. ? b.length * e * b.volume : 0.;
              }
            return intact[q] != 0. ? b.length * e * b.volume : 0.;
          };
          double *moment_i = moment + b.first, *moment_j = moment_i + b.delta;
          if (b.direct)
            {
#pragma omp simd safelen(simd_distance)
              for (int q = 0; q < n; ++q)
                {
                  const double m = term(q);
                  moment_i[q] += m;
                  moment_j[q] += m;
                }
            }
          else
            {
#pragma omp simd
              for (int q = 0; q < n; ++q)
                values[q] = term(q);
              add_to_ends(moment_i, moment_j, values, 1., n);
            }
          if constexpr (breaks)
            {
              double n_broke = 0;
#pragma omp simd reduction(+ : n_broke)
              for (int q = 0; q < n; ++q)
                n_broke += broke[q];
              if (n_broke > 0)
                {
                  std::lock_guard<std::mutex> guard(*breaking.lock);
                  for (int q = 0; q < n; ++q)
                    if (broke[q] != 0.)
                      breaking.bonds->push_back({b.first + q, b.half});
                }
            }
        },
        StencilLayout<dim>::Pass::dilatation);
    }

    /**
     * Pair forces (t_ij + t_ji) V v (xi + eta) / |xi + eta| and deviatoric sums
     * omega e_d^2 V v of both ends, from the coefficients beta, a, theta / 3 of every slot
     * (LinearPeridynamicSolid::compute_coefficients()).
     */
    template <int dim>
    inline __attribute__((always_inline)) void
    force_pass_impl(const StencilLayout<dim>                                    &layout,
                    const std::vector<typename BondFamilies<dim>::StencilEntry> &stencil,
                    const double                                                *u,
                    const double                                                *coefficients,
                    double                                                      *force,
                    double                                                      *deviatoric,
                    const RunRange                                              &range)
    {
      const std::size_t n_slots = layout.n_slots();
      double *const     chunk   = range.chunk;
      const double     *beta = coefficients, *a = coefficients + n_slots,
                   *theta_3 = coefficients + 2 * n_slots;
      for_each_block(
        layout,
        stencil,
        range,
        [=](const Block<dim> &block) __attribute__((always_inline)) {
          const Block<dim>    b    = block;
          const std::size_t   j    = b.delta;
          const std::uint8_t *mask = b.mask;
          const double       *ui[dim], *uj[dim];
          component_pointers<dim>(u, n_slots, b.first, ui);
          component_pointers<dim>(u, n_slots, b.first + j, uj);
          const double *beta_i = beta + b.first, *beta_j = beta_i + j, *a_i = a + b.first,
                       *a_j = a_i + j, *theta_3_i = theta_3 + b.first, *theta_3_j = theta_3_i + j;
          const int n               = b.n;
          double *__restrict values = chunk, *__restrict intact = chunk + (dim + 2) * chunk_length;
          unpack_mask(mask, n, intact);
          // Pair force components p and both ends' deviatoric terms of bond q.
          const auto terms = [&](const int q,
                                 double   &p_0,
                                 double   &p_1,
                                 double   &p_2,
                                 double   &dev_i,
                                 double   &dev_j) __attribute__((always_inline))
          {
            // One division for the two quotients e = numerator / (l + |xi|) and 1 / l.
            double       numerator;
            const double l = deformed_length<dim>(b.xi, ui, uj, q, numerator);
            const double r = 1. / ((l + b.length) * l);
            const double e = numerator * (l * r);
            const double t = (beta_i[q] + beta_j[q]) * e + (a_i[q] + a_j[q]) * b.length;
            const double w = intact[q] != 0. ? t * b.volume * ((l + b.length) * r) : 0.;
            p_0            = w * (b.xi[0] + (uj[0][q] - ui[0][q]));
            p_1            = w * (b.xi[1] + (uj[1][q] - ui[1][q]));
            if constexpr (dim == 3)
              p_2 = w * (b.xi[2] + (uj[2][q] - ui[2][q]));
            const double ed_i = e - theta_3_i[q] * b.length;
            const double ed_j = e - theta_3_j[q] * b.length;
            dev_i             = intact[q] != 0. ? ed_i * ed_i * b.volume : 0.;
            dev_j             = intact[q] != 0. ? ed_j * ed_j * b.volume : 0.;
          };
          double *f_i[dim], *f_j[dim];
          for (unsigned int d = 0; d < dim; ++d)
            {
              f_i[d] = force + d * n_slots + b.first;
              f_j[d] = f_i[d] + j;
            }
          double *deviatoric_i = deviatoric + b.first, *deviatoric_j = deviatoric_i + j;
          if (b.direct)
            {
#pragma omp simd safelen(simd_distance)
              for (int q = 0; q < n; ++q)
                {
                  double p_0, p_1, p_2 = 0, dev_i, dev_j;
                  terms(q, p_0, p_1, p_2, dev_i, dev_j);
                  f_i[0][q] += p_0;
                  f_j[0][q] -= p_0;
                  f_i[1][q] += p_1;
                  f_j[1][q] -= p_1;
                  if constexpr (dim == 3)
                    {
                      f_i[2][q] += p_2;
                      f_j[2][q] -= p_2;
                    }
                  deviatoric_i[q] += dev_i;
                  deviatoric_j[q] += dev_j;
                }
              return;
            }
#pragma omp      simd
          for (int q = 0; q < n; ++q)
            {
                   double p_2 = 0;
                   terms(q,
                    values[q],
                    values[chunk_length + q],
                    p_2,
                    values[dim * chunk_length + q],
                    values[(dim + 1) * chunk_length + q]);
                   if constexpr (dim == 3)
                values[2 * chunk_length + q] = p_2;
            }
               for (unsigned int d = 0; d < dim; ++d)
            add_to_ends(f_i[d], f_j[d], values + d * chunk_length, -1., n);
          const double *values_i = values + dim * chunk_length,
                       *values_j = values + (dim + 1) * chunk_length;
#pragma omp simd
          for (int q = 0; q < n; ++q)
            deviatoric_j[q] += values_j[q];
#pragma omp simd
          for (int q = 0; q < n; ++q)
            deviatoric_i[q] += values_i[q];
        },
        StencilLayout<dim>::Pass::force);
    }

    // One instance per dimension and instruction set.
#define PERIARLEQUIN_STENCIL_PASSES(dim)                                              \
  PERIARLEQUIN_KERNEL_CLONES void intact_volume_pass(                                 \
    const StencilLayout<dim>                                    &layout,              \
    const std::vector<typename BondFamilies<dim>::StencilEntry> &stencil,             \
    double                                                      *volume,              \
    const RunRange                                              &range)               \
  {                                                                                   \
    intact_volume_pass_impl<dim>(layout, stencil, volume, range);                     \
  }                                                                                   \
  PERIARLEQUIN_KERNEL_CLONES void moment_pass(                                        \
    const StencilLayout<dim>                                    &layout,              \
    const std::vector<typename BondFamilies<dim>::StencilEntry> &stencil,             \
    const double                                                *u,                   \
    double                                                      *moment,              \
    const RunRange                                              &range)               \
  {                                                                                   \
    moment_pass_impl<dim, false>(layout, stencil, u, moment, {}, range);              \
  }                                                                                   \
  PERIARLEQUIN_KERNEL_CLONES void breaking_moment_pass(                               \
    const StencilLayout<dim>                                    &layout,              \
    const std::vector<typename BondFamilies<dim>::StencilEntry> &stencil,             \
    const double                                                *u,                   \
    double                                                      *moment,              \
    const BondBreaking                                          &breaking,            \
    const RunRange                                              &range)               \
  {                                                                                   \
    moment_pass_impl<dim, true>(layout, stencil, u, moment, breaking, range);         \
  }                                                                                   \
  PERIARLEQUIN_KERNEL_CLONES void force_pass(                                         \
    const StencilLayout<dim>                                    &layout,              \
    const std::vector<typename BondFamilies<dim>::StencilEntry> &stencil,             \
    const double                                                *u,                   \
    const double                                                *coefficients,        \
    double                                                      *force,               \
    double                                                      *deviatoric,          \
    const RunRange                                              &range)               \
  {                                                                                   \
    force_pass_impl<dim>(layout, stencil, u, coefficients, force, deviatoric, range); \
  }
    PERIARLEQUIN_STENCIL_PASSES(2)
    PERIARLEQUIN_STENCIL_PASSES(3)
#undef PERIARLEQUIN_STENCIL_PASSES

    /**
     * Call @p pass(range) on the runs of every slab of @p layout (StencilLayout::slabs):
     * those of even index at once on the threads of this rank (TBB), then those of odd index.
     * Each slab's runs go to one thread, in order, so the sums do not depend on the threads.
     */
    template <int dim, typename Pass>
    void
    for_each_slab(const StencilLayout<dim> &layout, const Pass &pass)
    {
      for (const auto &ranges : layout.slabs)
        parallel::apply_to_subranges(
          0u,
          static_cast<unsigned int>(ranges.size()),
          [&](const unsigned int first, const unsigned int end) {
            double chunk[(dim + 3) * chunk_length];
            for (unsigned int k = first; k < end; ++k)
              pass(RunRange{ranges[k].first, ranges[k].second, chunk});
          },
          1);
    }

    /** Resize @p values to @p n entries, zero where new (stale entries stay finite). */
    void
    fit(std::vector<double> &values, const std::size_t n)
    {
      if (values.size() != n)
        values.assign(n, 0.);
    }
  } // namespace

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::gather_displacements(const StencilLayout<dim>       &layout,
                                                    ArrayView<const Tensor<1, dim>> u) const
  {
    const std::size_t n_slots = layout.n_slots();
    // Every held particle, also under a window: the passes visit whole slot ranges, whose
    // bonds without an end in the window must not break on stale displacements.
    fit(box_displacement, dim * n_slots);
    for_each_subrange(layout.slot.size(), [&](const unsigned int first, const unsigned int end) {
      for (unsigned int i = first; i < end; ++i)
        for (unsigned int d = 0; d < dim; ++d)
          box_displacement[d * n_slots + layout.slot[i]] = u[i][d];
    });
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::compute_moments_on_stencil(const BondFamilies<dim>        &bonds,
                                                          ArrayView<const Tensor<1, dim>> u,
                                                          const double           critical_stretch,
                                                          std::vector<SlotBond> *breaking) const
  {
    const auto       &layout  = bonds.stencil_layout();
    const std::size_t n_slots = layout.n_slots();
    gather_displacements(layout, u);
    fill_zeros(box_moment, n_slots);
    if (breaking == nullptr)
      for_each_slab(layout, [&](const RunRange &range) {
        moment_pass(layout, bonds.stencil, box_displacement.data(), box_moment.data(), range);
      });
    else
      {
        std::mutex lock;
        for_each_slab(layout, [&](const RunRange &range) {
          breaking_moment_pass(layout,
                               bonds.stencil,
                               box_displacement.data(),
                               box_moment.data(),
                               BondBreaking{critical_stretch, breaking, &lock},
                               range);
        });
      }
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::update_intact_volumes(const BondFamilies<dim>     &bonds,
                                                     const std::vector<SlotBond> &broken,
                                                     const unsigned int version_before) const
  {
    const auto &layout = bonds.stencil_layout();
    if (box_volume_version != version_before || box_volume.size() != layout.n_slots())
      return;
    const auto resum = [&](const std::size_t s) {
      double volume = 0.;
      layout.for_each_bond_in_pass_order(s, [&](const unsigned int h) {
        const auto &bond = bonds.stencil[layout.half_offsets[h].stencil_index];
        volume += bond.length * bond.length * bond.volume;
      });
      box_volume[s] = volume;
    };
    for (const SlotBond &bond : broken)
      {
        resum(bond.slot);
        resum(bond.slot + layout.half_offsets[bond.half_offset].delta);
      }
    box_volume_version = layout.mask_version();
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::scalars_from_moments_on_stencil(const BondFamilies<dim> &bonds,
                                                               std::vector<double> &scalars) const
  {
    const auto       &layout  = bonds.stencil_layout();
    const std::size_t n_slots = layout.n_slots();
    if (box_volume_version != layout.mask_version() || box_volume.size() != n_slots)
      {
        box_volume.assign(n_slots, 0.);
        for_each_slab(layout, [&](const RunRange &range) {
          intact_volume_pass(layout, bonds.stencil, box_volume.data(), range);
        });
        box_volume_version = layout.mask_version();
      }
    for_each_subrange(bonds.n_owned, [&](const unsigned int first, const unsigned int end) {
      for (unsigned int i = first; i < end; ++i)
        {
          if (!layout.in_window(i, StencilLayout<dim>::Pass::dilatation))
            continue;
          const std::size_t s     = layout.slot[i];
          const double      theta = c * box_moment[s] / bonds.weighted_volume[i];
          scalars[2 * i]          = theta;
          scalars[2 * i + 1]      = box_moment[s] - theta * box_volume[s] / 3.;
        }
    });
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::compute_forces_on_stencil(const BondFamilies<dim>        &bonds,
                                                         ArrayView<const Tensor<1, dim>> u,
                                                         const std::vector<double>      &scalars,
                                                         const std::vector<double>   &state_weight,
                                                         std::vector<Tensor<1, dim>> &force_density,
                                                         std::vector<double> &energy_density) const
  {
    const auto       &layout  = bonds.stencil_layout();
    const std::size_t n_slots = layout.n_slots();
    compute_coefficients(bonds, make_array_view(scalars), state_weight);
    fit(box_coefficients, 3 * n_slots);
    layout.for_each_read_particle(bonds.n_total, [&](const unsigned int i) {
      for (unsigned int m = 0; m < 3; ++m)
        box_coefficients[m * n_slots + layout.slot[i]] = coefficients[3 * i + m];
    });
    gather_displacements(layout, u);
    fill_zeros(box_force, dim * n_slots);
    fill_zeros(box_deviatoric, n_slots);
    for_each_slab(layout, [&](const RunRange &range) {
      force_pass(layout,
                 bonds.stencil,
                 box_displacement.data(),
                 box_coefficients.data(),
                 box_force.data(),
                 box_deviatoric.data(),
                 range);
    });
    for_each_subrange(bonds.n_owned, [&](const unsigned int first, const unsigned int end) {
      for (unsigned int i = first; i < end; ++i)
        {
          if (!layout.in_window(i, StencilLayout<dim>::Pass::force))
            continue;
          const std::size_t s = layout.slot[i];
          for (unsigned int d = 0; d < dim; ++d)
            force_density[i][d] = box_force[d * n_slots + s];
          const double theta = scalars[2 * i];
          energy_density[i]  = 0.5 * state_weight[i] * k * theta * theta +
                              0.5 * coefficients[3 * i] * box_deviatoric[s];
        }
    });
  }

  // The class is instantiated in material_model.cc; the members defined here, here.
#define PERIARLEQUIN_INSTANTIATE(dim)                                                              \
  template void LinearPeridynamicSolid<dim>::gather_displacements(const StencilLayout<dim> &,      \
                                                                  ArrayView<const Tensor<1, dim>>) \
    const;                                                                                         \
  template void LinearPeridynamicSolid<dim>::compute_moments_on_stencil(                           \
    const BondFamilies<dim> &,                                                                     \
    ArrayView<const Tensor<1, dim>>,                                                               \
    const double,                                                                                  \
    std::vector<SlotBond> *) const;                                                                \
  template void LinearPeridynamicSolid<dim>::update_intact_volumes(const BondFamilies<dim> &,      \
                                                                   const std::vector<SlotBond> &,  \
                                                                   const unsigned int) const;      \
  template void LinearPeridynamicSolid<dim>::scalars_from_moments_on_stencil(                      \
    const BondFamilies<dim> &,                                                                     \
    std::vector<double> &) const;                                                                  \
  template void LinearPeridynamicSolid<dim>::compute_forces_on_stencil(                            \
    const BondFamilies<dim> &,                                                                     \
    ArrayView<const Tensor<1, dim>>,                                                               \
    const std::vector<double> &,                                                                   \
    const std::vector<double> &,                                                                   \
    std::vector<Tensor<1, dim>> &,                                                                 \
    std::vector<double> &) const;
  PERIARLEQUIN_INSTANTIATE(2)
  PERIARLEQUIN_INSTANTIATE(3)
#undef PERIARLEQUIN_INSTANTIATE
} // namespace PeriArlequin
