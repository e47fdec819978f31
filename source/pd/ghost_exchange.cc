#include <periarlequin/pd/ghost_exchange.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <iterator>
#include <numeric>

namespace PeriArlequin
{
  template <int dim>
  GhostExchange<dim>::GhostExchange(Particles::ParticleHandler<dim> &particle_handler,
                                    const MPI_Comm                   communicator)
    : particle_handler(particle_handler)
    , communicator(communicator)
  {}

  template <int dim>
  void
  GhostExchange<dim>::reinit()
  {
    particle_handler.exchange_ghost_particles(true);
    particle_ids.clear();
    positions.clear();
    const std::size_t n_held =
      particle_handler.n_locally_owned_particles() +
      std::distance(particle_handler.begin_ghost(), particle_handler.end_ghost());
    particle_ids.reserve(n_held);
    positions.reserve(n_held);
    for (const auto &particle : particle_handler)
      {
        particle_ids.push_back(particle.get_id());
        positions.push_back(particle.get_location());
      }
    n_owned_particles = particle_ids.size();

    // Number the owned particles of all ranks consecutively; the ghosts learn their number
    // through the particle handler, once.
    const types::global_dof_index n_local = n_owned_particles;
    first_index                           = 0;
    MPI_Exscan(&n_local,
               &first_index,
               1,
               Utilities::MPI::mpi_type_id_for_type<types::global_dof_index>,
               MPI_SUM,
               communicator);
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      first_index = 0;
    n_global = Utilities::MPI::sum(n_local, communicator);
    {
      unsigned int i = 0;
      for (auto &particle : particle_handler)
        particle.get_properties()[0] = static_cast<double>(first_index + i++);
    }
    particle_handler.update_ghost_particles();
    struct Ghost
    {
      types::global_dof_index index;
      types::particle_index   id;
      Point<dim>              position;
    };
    std::vector<Ghost> ghosts;
    ghosts.reserve(n_held - n_owned_particles);
    for (auto ghost = particle_handler.begin_ghost(); ghost != particle_handler.end_ghost();
         ++ghost)
      ghosts.push_back({static_cast<types::global_dof_index>(ghost->get_properties()[0]),
                        ghost->get_id(),
                        ghost->get_location()});
    std::sort(ghosts.begin(), ghosts.end(), [](const Ghost &a, const Ghost &b) {
      return a.index < b.index;
    });
    ghost_indices.clear();
    ghost_indices.reserve(ghosts.size());
    for (const auto &ghost : ghosts)
      {
        ghost_indices.push_back(ghost.index);
        particle_ids.push_back(ghost.id);
        positions.push_back(ghost.position);
      }

    index_of_id.clear();
    index_by_id.clear();
    if (!particle_ids.empty())
      {
        const auto [lowest, highest] =
          std::minmax_element(particle_ids.begin(), particle_ids.end());
        first_id = *lowest;
        if (*highest - *lowest < types::particle_index(max_table_span) * particle_ids.size())
          {
            index_by_id.assign(*highest - *lowest + 1, numbers::invalid_unsigned_int);
            for (unsigned int i = 0; i < particle_ids.size(); ++i)
              index_by_id[particle_ids[i] - first_id] = i;
          }
        else
          {
            index_of_id.reserve(particle_ids.size());
            for (unsigned int i = 0; i < particle_ids.size(); ++i)
              index_of_id[particle_ids[i]] = i;
          }
      }
    partitioners.clear();
  }

  template <int dim>
  const Utilities::MPI::Partitioner &
  GhostExchange<dim>::partitioner(const unsigned int n)
  {
    auto &pattern = partitioners[n];
    if (!pattern)
      {
        IndexSet owned(n * n_global), ghosted(n * n_global);
        owned.add_range(n * first_index, n * (first_index + n_owned_particles));
        std::vector<types::global_dof_index> entries;
        entries.reserve(n * ghost_indices.size());
        for (const auto index : ghost_indices)
          for (unsigned int k = 0; k < n; ++k)
            entries.push_back(n * index + k);
        ghosted.add_indices(entries.begin(), entries.end());
        pattern = std::make_unique<Utilities::MPI::Partitioner>(owned, ghosted, communicator);
      }
    return *pattern;
  }

  template <int dim>
  unsigned int
  GhostExchange<dim>::n_owned() const
  {
    return n_owned_particles;
  }

  template <int dim>
  unsigned int
  GhostExchange<dim>::n_total() const
  {
    return particle_ids.size();
  }

  template <int dim>
  ArrayView<const types::particle_index>
  GhostExchange<dim>::ids() const
  {
    return make_array_view(particle_ids);
  }

  template <int dim>
  ArrayView<const Point<dim>>
  GhostExchange<dim>::reference_positions() const
  {
    return make_array_view(positions);
  }

  template <int dim>
  void
  GhostExchange<dim>::update_ghosts(ArrayView<double> values, const unsigned int n_per_particle)
  {
    AssertDimension(values.size(), n_per_particle * n_total());
    const Utilities::MPI::Partitioner &pattern = partitioner(n_per_particle);
    send_buffer.resize(pattern.n_import_indices());
    const std::size_t       n_owned_values = n_per_particle * std::size_t(n_owned_particles);
    const ArrayView<double> ghost_values(values.data() + n_owned_values,
                                         values.size() - n_owned_values);
    pattern.export_to_ghosted_array_start<double>(0,
                                                  ArrayView<const double>(values.data(),
                                                                          n_owned_values),
                                                  make_array_view(send_buffer),
                                                  ghost_values,
                                                  requests);
    pattern.export_to_ghosted_array_finish(ghost_values, requests);
  }

  template <int dim>
  void
  GhostExchange<dim>::update_ghosts(ArrayView<Tensor<1, dim>> values)
  {
    // An array of vectors is an array of dim n doubles.
    static_assert(sizeof(Tensor<1, dim>) == dim * sizeof(double));
    AssertDimension(values.size(), n_total());
    if (n_total() > 0)
      update_ghosts(ArrayView<double>(values[0].begin_raw(), dim * values.size()), dim);
    else
      update_ghosts(ArrayView<double>(), dim);
  }

  template class GhostExchange<2>;
  template class GhostExchange<3>;
} // namespace PeriArlequin
