#include <periarlequin/base/parallel_loops.h>
#include <periarlequin/base/parameters.h>
#include <periarlequin/pd/particle_contact.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <sstream>
#include <utility>

namespace PeriArlequin
{
  template <int dim>
  ParticleContact<dim>::ParticleContact(const Parameters::ParticleContact &parameters,
                                        const double                       lattice_spacing,
                                        const double                       youngs_modulus,
                                        const MPI_Comm                     communicator)
    : contact_distance(parameters.distance_factor * lattice_spacing)
    // A skin of 0.09 dx: with d_c = 0.9 dx the list reaches 0.99 dx, so at rest it holds no
    // pair of lattice neighbours; rebuilt once particles moved 0.09 dx relative to each other.
    , skin(0.09 * lattice_spacing)
    , pair_stiffness(parameters.stiffness_factor * youngs_modulus *
                     std::pow(lattice_spacing, dim - 2))
    , communicator(communicator)
  {}

  template <int dim>
  void
  ParticleContact<dim>::reinit(std::vector<types::global_cell_index>        particle_cells,
                               std::unordered_set<types::global_cell_index> held_cells)
  {
    this->particle_cells = std::move(particle_cells);
    this->held_cells     = std::move(held_cells);
    list_current         = false;
  }

  template <int dim>
  double
  ParticleContact<dim>::eigenvalue_bound(const double particle_mass) const
  {
    return 2. * (2. * (dim - 1)) * pair_stiffness / particle_mass;
  }

  template <int dim>
  void
  ParticleContact<dim>::check_partners_held(const std::vector<Point<dim>> &position,
                                            ArrayView<const double>        alpha) const
  {
    if (Utilities::MPI::n_mpi_processes(communicator) == 1)
      return;
    // Per owned cell, the box of its particles' current positions: (cell, lower, upper).
    std::map<types::global_cell_index, std::pair<Point<dim>, Point<dim>>> own_boxes;
    for (unsigned int i = 0; i < particle_cells.size(); ++i)
      if (alpha[i] == 0)
        {
          const auto [box, inserted] =
            own_boxes.try_emplace(particle_cells[i], position[i], position[i]);
          if (!inserted)
            for (unsigned int d = 0; d < dim; ++d)
              {
                box->second.first[d]  = std::min(box->second.first[d], position[i][d]);
                box->second.second[d] = std::max(box->second.second[d], position[i][d]);
              }
        }
    std::vector<double> flat;
    for (const auto &[cell, box] : own_boxes)
      {
        flat.push_back(cell);
        for (unsigned int d = 0; d < dim; ++d)
          flat.push_back(box.first[d]);
        for (unsigned int d = 0; d < dim; ++d)
          flat.push_back(box.second[d]);
      }
    const std::vector<std::vector<double>> all = Utilities::MPI::all_gather(communicator, flat);

    // The cells this rank does not hold, against its own boxes grown by the cutoff, by a
    // sweep along x over both lists sorted by their lower x.
    const double cutoff = contact_distance + skin;
    using Box           = std::pair<Point<dim>, Point<dim>>;
    std::vector<Box> own, foreign;
    for (const auto &[cell, box] : own_boxes)
      {
        Box grown = box;
        for (unsigned int d = 0; d < dim; ++d)
          {
            grown.first[d] -= cutoff;
            grown.second[d] += cutoff;
          }
        own.push_back(grown);
      }
    for (const std::vector<double> &boxes : all)
      for (std::size_t k = 0; k < boxes.size(); k += 1 + 2 * dim)
        if (held_cells.count(static_cast<types::global_cell_index>(boxes[k])) == 0)
          {
            Box box;
            for (unsigned int d = 0; d < dim; ++d)
              {
                box.first[d]  = boxes[k + 1 + d];
                box.second[d] = boxes[k + 1 + dim + d];
              }
            foreign.push_back(box);
          }
    const auto by_lower_x = [](const Box &a, const Box &b) { return a.first[0] < b.first[0]; };
    std::sort(own.begin(), own.end(), by_lower_x);
    std::sort(foreign.begin(), foreign.end(), by_lower_x);
    const auto overlap = [](const Box &a, const Box &b) {
      for (unsigned int d = 0; d < dim; ++d)
        if (a.second[d] < b.first[d] || b.second[d] < a.first[d])
          return false;
      return true;
    };
    double largest_own_width = 0;
    for (const Box &box : own)
      largest_own_width = std::max(largest_own_width, box.second[0] - box.first[0]);
    const Box *met = nullptr;
    for (const Box &box : foreign)
      {
        // Own boxes that can reach box start at most their largest width before it.
        auto first =
          std::lower_bound(own.begin(),
                           own.end(),
                           Box(box.first - largest_own_width * Point<dim>::unit_vector(0),
                               Point<dim>()),
                           by_lower_x);
        for (; first != own.end() && !(first->first[0] > box.second[0]); ++first)
          if (overlap(*first, box))
            {
              met = &box;
              break;
            }
        if (met)
          break;
      }
    // One message, naming the lowest rank that met such a cell; all ranks stop.
    const unsigned int rank =
      Utilities::MPI::min(met ? Utilities::MPI::this_mpi_process(communicator) :
                                numbers::invalid_unsigned_int,
                          communicator);
    if (rank == numbers::invalid_unsigned_int)
      return;
    std::ostringstream message;
    message << "Particle contact on several ranks: particles of background cells that are not "
               "neighbours have come within the contact search distance of each other, and no "
               "rank holds both (a fragment, or faces sliding past each other across a rank "
               "boundary; first seen on rank "
            << rank;
    if (met && Utilities::MPI::this_mpi_process(communicator) == rank)
      message << ", by the particles of a cell in " << met->first << " : " << met->second << " m";
    message << "). Contact across ranks is computed between the particles of neighbouring "
               "cells only: run this case on one rank (threads), or with coarser background "
               "cells (Geometry/Subdivisions).";
    AssertThrow(false, ExcMessage(message.str()));
  }

  template <int dim>
  bool
  ParticleContact<dim>::list_outdated(ArrayView<const Tensor<1, dim>> displacement,
                                      const unsigned int              n_owned) const
  {
    if (!(list_current && displacement_at_build.size() == n_owned))
      return true;
    // Per component, the largest and the negated smallest drift since the list was built,
    // over the owned particles of all ranks: the diagonal of that box bounds how much any
    // two particles moved relative to each other.
    using Extremes      = std::array<double, 2 * dim>;
    const auto extremes = [&](const unsigned int first, const unsigned int end) {
      Extremes largest;
      largest.fill(std::numeric_limits<double>::lowest());
      for (unsigned int i = first; i < end; ++i)
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double drift = displacement[i][d] - displacement_at_build[i][d];
            largest[d]         = std::max(largest[d], drift);
            largest[dim + d]   = std::max(largest[dim + d], -drift);
          }
      return largest;
    };
    // Fixed chunks on the threads, their extremes combined after.
    constexpr unsigned int n_chunks = 16;
    std::vector<Extremes>  chunk_extremes(n_chunks);
    for_each_subrange(
      n_chunks,
      [&](const unsigned int first, const unsigned int end) {
        for (unsigned int c = first; c < end; ++c)
          chunk_extremes[c] = extremes(n_owned * c / n_chunks, n_owned * (c + 1) / n_chunks);
      },
      1);
    Extremes largest = chunk_extremes[0];
    for (const Extremes &chunk : chunk_extremes)
      for (unsigned int k = 0; k < largest.size(); ++k)
        largest[k] = std::max(largest[k], chunk[k]);
    Utilities::MPI::max(ArrayView<const double>(largest.data(), largest.size()),
                        communicator,
                        ArrayView<double>(largest.data(), largest.size()));
    double square = 0;
    for (unsigned int d = 0; d < dim; ++d)
      square += std::pow(std::max(largest[d] + largest[dim + d], 0.), 2);
    return std::sqrt(square) > skin;
  }

  namespace
  {
    /**
     * The stored bond joining held particles @p i (owned) and @p j, or @p none: a bond between
     * two owned particles is stored at the lower local index, one to a ghost at the owned end.
     */
    template <int dim>
    std::size_t
    stored_bond(const BondFamilies<dim> &bonds,
                const unsigned int       i,
                const unsigned int       j,
                const std::size_t        none)
    {
      const bool         at_j  = j < bonds.n_owned && j < i;
      const unsigned int owner = at_j ? j : i, other = at_j ? i : j;
      for (std::size_t n = bonds.family_begin[owner]; n < bonds.family_begin[owner + 1]; ++n)
        if (bonds.neighbor(owner, n) == other)
          return n;
      return none;
    }

    /**
     * Sort (key, particle) pairs by key, then particle: by counting when the keys, in
     * [0, @p n_keys), are not many more than the pairs (a compact body), else by comparison.
     */
    void
    sort_by_key(std::vector<std::pair<std::int64_t, unsigned int>> &entries,
                const std::int64_t                                  n_keys)
    {
      if (n_keys > 4 * static_cast<std::int64_t>(entries.size()) + 1024)
        {
          std::sort(entries.begin(), entries.end());
          return;
        }
      std::vector<unsigned int> start(n_keys + 1, 0);
      for (const auto &entry : entries)
        ++start[entry.first + 1];
      std::partial_sum(start.begin(), start.end(), start.begin());
      // Entries arrive in particle order, so each key's run keeps it.
      std::vector<std::pair<std::int64_t, unsigned int>> sorted(entries.size());
      for (const auto &entry : entries)
        sorted[start[entry.first]++] = entry;
      entries.swap(sorted);
    }
  } // namespace

  template <int dim>
  void
  ParticleContact<dim>::build_list(const BondFamilies<dim>               &bonds,
                                   ArrayView<const Point<dim>>            reference_position,
                                   ArrayView<const types::particle_index> ids,
                                   ArrayView<const double>                alpha,
                                   ArrayView<const Tensor<1, dim>>        displacement)
  {
    const unsigned int      n_total = reference_position.size(), n_owned = bonds.n_owned;
    const double            cutoff = contact_distance + skin;
    std::vector<Point<dim>> position(n_total);
    Point<dim>              lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = std::numeric_limits<double>::max();
        upper[d] = std::numeric_limits<double>::lowest();
      }
    for (unsigned int i = 0; i < n_total; ++i)
      {
        position[i] = reference_position[i] + displacement[i];
        if (alpha[i] == 0)
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] = std::min(lower[d], position[i][d]);
              upper[d] = std::max(upper[d], position[i][d]);
            }
      }

    check_partners_held(position, alpha);

    // Bins of edge `cutoff` over the particles outside the overlap, as (key, particle) sorted
    // by key: a pair closer than the cutoff lies in the same or in neighbouring bins. A layer
    // of empty bins around makes every neighbour of a bin a bin: its neighbours along x are
    // the keys before and after it, and each row of three along x is the key shifted by a
    // fixed offset.
    std::array<std::int64_t, dim> n_bins, stride;
    for (unsigned int d = 0; d < dim; ++d)
      n_bins[d] = (upper[d] < lower[d] ? 1 : std::floor((upper[d] - lower[d]) / cutoff) + 1) + 2;
    stride[0] = 1;
    for (unsigned int d = 1; d < dim; ++d)
      stride[d] = stride[d - 1] * n_bins[d - 1];
    const auto key_of = [&](const Point<dim> &x) {
      std::int64_t key = 0;
      for (unsigned int d = 0; d < dim; ++d)
        key += stride[d] *
               (1 + std::min<std::int64_t>(std::floor((x[d] - lower[d]) / cutoff), n_bins[d] - 3));
      return key;
    };
    std::vector<std::pair<std::int64_t, unsigned int>> binned;
    for (unsigned int i = 0; i < n_total; ++i)
      if (alpha[i] == 0)
        binned.emplace_back(key_of(position[i]), i);
    sort_by_key(binned, stride[dim - 1] * n_bins[dim - 1]);

    // The key offsets of the rows of neighbouring bins (3^(dim-1)); visited in key order,
    // each row's first candidate only moves forward.
    std::vector<std::int64_t> row_offset(1, 0);
    for (unsigned int d = 1; d < dim; ++d)
      {
        std::vector<std::int64_t> extended;
        for (const std::int64_t offset : row_offset)
          for (const int shift : {-1, 0, 1})
            extended.push_back(offset + shift * stride[d]);
        row_offset = extended;
      }

    // The sorted entries in chunks searched on the threads, each chunk's pairs kept apart and
    // joined in chunk order: the list does not depend on the number of threads.
    struct Chunk
    {
      std::vector<unsigned int> particles, n_partners, partners;
      std::vector<std::size_t>  partner_bonds;
    };
    constexpr unsigned int n_chunks = 16;
    std::vector<Chunk>     chunks(n_chunks);
    const auto             search = [&](const unsigned int c) {
      Chunk     &chunk = chunks[c];
      const auto begin = binned.cbegin() + binned.size() * c / n_chunks;
      const auto end   = binned.cbegin() + binned.size() * (c + 1) / n_chunks;
      if (begin == end)
        return;
      std::vector<typename decltype(binned)::const_iterator> row_start(row_offset.size());
      for (unsigned int row = 0; row < row_offset.size(); ++row)
        row_start[row] = std::lower_bound(binned.cbegin(),
                                          binned.cend(),
                                          std::make_pair(begin->first + row_offset[row] - 1, 0u));
      std::vector<unsigned int> found;
      for (auto entry = begin; entry != end; ++entry)
        {
          const auto [key, i] = *entry;
          if (i >= n_owned)
            continue;
          found.clear();
          for (unsigned int row = 0; row < row_offset.size(); ++row)
            {
              const std::int64_t first_key = key + row_offset[row] - 1;
              auto              &candidate = row_start[row];
              while (candidate != binned.cend() && candidate->first < first_key)
                ++candidate;
              for (auto c = candidate; c != binned.cend() && c->first <= first_key + 2; ++c)
                if (const unsigned int j = c->second;
                    j != i && (position[j] - position[i]).norm_square() < cutoff * cutoff)
                  found.push_back(j);
            }
          if (found.empty())
            continue;
          // Partners in the order of their ids: the same summation order on any partition.
          std::sort(found.begin(), found.end(), [&](const unsigned int a, const unsigned int b) {
            return ids[a] < ids[b];
          });
          chunk.particles.push_back(i);
          chunk.n_partners.push_back(found.size());
          for (const unsigned int j : found)
            {
              chunk.partners.push_back(j);
              chunk.partner_bonds.push_back(stored_bond(bonds, i, j, no_bond));
            }
        }
    };
    for_each_subrange(
      n_chunks,
      [&](const unsigned int first, const unsigned int end) {
        for (unsigned int c = first; c < end; ++c)
          search(c);
      },
      1);

    particles_with_partners.clear();
    partner_begin.assign(1, 0);
    partner.clear();
    partner_bond.clear();
    for (const Chunk &chunk : chunks)
      {
        particles_with_partners.insert(particles_with_partners.end(),
                                       chunk.particles.begin(),
                                       chunk.particles.end());
        for (const unsigned int n : chunk.n_partners)
          partner_begin.push_back(partner_begin.back() + n);
        partner.insert(partner.end(), chunk.partners.begin(), chunk.partners.end());
        partner_bond.insert(partner_bond.end(),
                            chunk.partner_bonds.begin(),
                            chunk.partner_bonds.end());
      }
    displacement_at_build.assign(displacement.begin(), displacement.begin() + n_owned);
    list_current = true;
  }

  template <int dim>
  void
  ParticleContact<dim>::add_forces(const BondFamilies<dim>               &bonds,
                                   ArrayView<const Point<dim>>            reference_position,
                                   ArrayView<const types::particle_index> ids,
                                   ArrayView<const double>                alpha,
                                   ArrayView<const Tensor<1, dim>>        displacement,
                                   const double                           particle_volume,
                                   std::vector<Tensor<1, dim>>           &force_density,
                                   std::vector<double>                   &energy_density)
  {
    if (list_outdated(displacement, bonds.n_owned))
      build_list(bonds, reference_position, ids, alpha, displacement);

    const double d = contact_distance, k = pair_stiffness;
    const double per_volume = 1. / particle_volume;
    // Each particle's contact energy: positive exactly where it touches another.
    std::vector<double> energies(particles_with_partners.size(), 0.);
    for_each_subrange(
      particles_with_partners.size(),
      [&](const unsigned int first, const unsigned int end) {
        for (unsigned int p = first; p < end; ++p)
          {
            const unsigned int i = particles_with_partners[p];
            Tensor<1, dim>     force;
            double             pair_energy = 0;
            for (unsigned int q = partner_begin[p]; q < partner_begin[p + 1]; ++q)
              {
                const std::size_t n = partner_bond[q];
                if (n != no_bond && bonds.state[n] != BondFamilies<dim>::broken)
                  continue;
                const unsigned int j = partner[q];
                // Formed from (x_j - x_i) and (u_j - u_i): exactly the negative seen from j.
                const Tensor<1, dim> eta = (reference_position[j] - reference_position[i]) +
                                           (displacement[j] - displacement[i]);
                const double r2 = eta.norm_square();
                if (!(r2 < d * d))
                  continue;
                const double r       = std::sqrt(r2);
                const double overlap = d - r;
                if (r > 0)
                  force -= (k * overlap / r) * eta;
                pair_energy += 0.25 * k * overlap * overlap;
              }
            energies[p] = pair_energy;
            force_density[i] += per_volume * force;
            energy_density[i] += per_volume * pair_energy;
          }
      },
      256);
    touching =
      std::count_if(energies.begin(), energies.end(), [](const double e) { return e > 0; });
    energy = std::accumulate(energies.begin(), energies.end(), 0.);
  }

  template class ParticleContact<2>;
  template class ParticleContact<3>;
} // namespace PeriArlequin
