#include <periarlequin/pd/ghost_exchange.h>

namespace PeriArlequin
{
  template <int dim>
  GhostExchange<dim>::GhostExchange(Particles::ParticleHandler<dim> &particle_handler)
    : particle_handler(particle_handler)
  {}

  template <int dim>
  void
  GhostExchange<dim>::reinit()
  {
    particle_handler.exchange_ghost_particles(true);
    particle_ids.clear();
    positions.clear();
    for (const auto &particle : particle_handler)
      {
        particle_ids.push_back(particle.get_id());
        positions.push_back(particle.get_location());
      }
    n_owned_particles = particle_ids.size();
    for (auto ghost = particle_handler.begin_ghost(); ghost != particle_handler.end_ghost();
         ++ghost)
      {
        particle_ids.push_back(ghost->get_id());
        positions.push_back(ghost->get_location());
      }
    index_of_id.clear();
    index_of_id.reserve(particle_ids.size());
    for (unsigned int i = 0; i < particle_ids.size(); ++i)
      index_of_id[particle_ids[i]] = i;
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
  unsigned int
  GhostExchange<dim>::local_index(const types::particle_index id) const
  {
    const auto found = index_of_id.find(id);
    return found == index_of_id.end() ? numbers::invalid_unsigned_int : found->second;
  }

  template <int dim>
  void
  GhostExchange<dim>::update_ghosts(ArrayView<double> values, const unsigned int n_per_particle)
  {
    AssertDimension(values.size(), n_per_particle * n_total());
    unsigned int i = 0;
    for (auto &particle : particle_handler)
      {
        const ArrayView<double> properties = particle.get_properties();
        for (unsigned int k = 0; k < n_per_particle; ++k)
          properties[k] = values[n_per_particle * i + k];
        ++i;
      }
    particle_handler.update_ghost_particles();
    for (auto ghost = particle_handler.begin_ghost(); ghost != particle_handler.end_ghost();
         ++ghost, ++i)
      {
        AssertThrow(ghost->get_id() == particle_ids[i],
                    ExcMessage("Ghost particles changed order without GhostExchange::reinit()."));
        const ArrayView<const double> properties = ghost->get_properties();
        for (unsigned int k = 0; k < n_per_particle; ++k)
          values[n_per_particle * i + k] = properties[k];
      }
  }

  template <int dim>
  void
  GhostExchange<dim>::update_ghosts(ArrayView<Tensor<1, dim>> values)
  {
    AssertDimension(values.size(), n_total());
    buffer.resize(dim * n_total());
    for (unsigned int i = 0; i < n_owned_particles; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        buffer[dim * i + d] = values[i][d];
    update_ghosts(make_array_view(buffer), dim);
    for (unsigned int i = n_owned_particles; i < n_total(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        values[i][d] = buffer[dim * i + d];
  }

  template class GhostExchange<2>;
  template class GhostExchange<3>;
} // namespace PeriArlequin
