#include <periarlequin/base/parallel_loops.h>
#include <periarlequin/pd/prescribed_particles.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>

namespace PeriArlequin
{
  namespace
  {
    /** Bit d for each prescribed component d, and bit 7: the particle is held. */
    template <std::size_t n>
    std::uint8_t
    component_bits(const std::array<bool, n> &components)
    {
      std::uint8_t bits = 0x80;
      for (unsigned int d = 0; d < n; ++d)
        if (components[d])
          bits |= std::uint8_t(1u << d);
      return bits;
    }
  } // namespace

  template <int dim>
  PrescribedParticles<dim>::PrescribedParticles(const Parameters::Peridynamics<dim> &parameters)
    : parameters(parameters)
  {}

  template <int dim>
  void
  PrescribedParticles<dim>::reinit(ArrayView<const Point<dim>> positions,
                                   const unsigned int          n_owned)
  {
    particles.clear();
    held_components.assign(n_owned, 0);
    if (parameters.prescribed.empty())
      return;
    // The region tests on the threads (every particle of a zone after each growth); the
    // particles made in their order, with the first region that holds each.
    const std::vector<std::pair<unsigned int, unsigned int>> held =
      join_over_chunks<std::pair<unsigned int, unsigned int>>(
        n_owned,
        [&](const unsigned int                                  first,
            const unsigned int                                  end,
            std::vector<std::pair<unsigned int, unsigned int>> &list) {
          for (unsigned int i = first; i < end; ++i)
            for (unsigned int r = 0; r < parameters.prescribed.size(); ++r)
              if (parameters.prescribed[r].region.contains(positions[i]))
                {
                  list.emplace_back(i, r);
                  break;
                }
        });
    for (const auto &[i, r] : held)
      {
        const auto           &region = parameters.prescribed[r];
        std::array<bool, dim> components;
        for (unsigned int d = 0; d < dim; ++d)
          components[d] = region.components[d];
        particles.push_back(make_particle(i,
                                          region.function.get(),
                                          components,
                                          region.prescribes_velocity,
                                          positions[i],
                                          2 * dim + r));
        held_components[i] = component_bits(components);
      }
  }

  template <int dim>
  void
  PrescribedParticles<dim>::add(const unsigned int           i,
                                const Point<dim>            &position,
                                Function<dim>               &function,
                                const std::array<bool, dim> &components,
                                const unsigned int           boundary_id)
  {
    if (held_components[i] != 0)
      return;
    particles.push_back(make_particle(i, &function, components, false, position, boundary_id));
    held_components[i] = component_bits(components);
  }

  template <int dim>
  typename PrescribedParticles<dim>::Particle
  PrescribedParticles<dim>::make_particle(const unsigned int           local_index,
                                          Function<dim>               *function,
                                          const std::array<bool, dim> &components,
                                          const bool                   prescribes_velocity,
                                          const Point<dim>            &position,
                                          const unsigned int           support)
  {
    const auto *separable = dynamic_cast<const SeparableField<dim> *>(function);
    return {local_index,
            function,
            components,
            prescribes_velocity,
            position,
            Tensor<1, dim>(),
            Tensor<1, dim>(),
            support,
            separable,
            separable ? separable->spatial_field(position) : Tensor<1, dim>()};
  }

  template <int dim>
  bool
  PrescribedParticles<dim>::contains(const unsigned int i) const
  {
    return held_components[i] != 0;
  }

  template <int dim>
  bool
  PrescribedParticles<dim>::empty(const MPI_Comm communicator) const
  {
    return !Utilities::MPI::logical_or(!particles.empty(), communicator);
  }

  template <int dim>
  void
  PrescribedParticles<dim>::impose(const double time, const double dt, ParticleState<dim> &state)
  {
    Vector<double>   before(dim), now(dim), after(dim);
    TimeFactors<dim> time_factors(time, dt);
    for (auto &p : particles)
      {
        if (p.separable)
          {
            const std::array<double, 3> &g = time_factors(*p.separable);
            for (unsigned int d = 0; d < dim; ++d)
              {
                before(d) = g[0] * p.spatial_field[d];
                now(d)    = g[1] * p.spatial_field[d];
                after(d)  = g[2] * p.spatial_field[d];
              }
          }
        else
          {
            auto &function = *p.function;
            function.set_time(time - dt);
            function.vector_value(p.position, before);
            function.set_time(time);
            function.vector_value(p.position, now);
            function.set_time(time + dt);
            function.vector_value(p.position, after);
          }
        for (unsigned int d = 0; d < dim; ++d)
          {
            if (!p.components[d])
              continue;
            if (p.prescribes_velocity)
              {
                p.velocity[d]     = now(d);
                p.acceleration[d] = (after(d) - before(d)) / (2. * dt);
              }
            else
              {
                state.displacements()[p.local_index][d] = now(d);
                p.velocity[d]                           = (after(d) - before(d)) / (2. * dt);
                p.acceleration[d] = (after(d) - 2. * now(d) + before(d)) / (dt * dt);
              }
          }
      }
    restore_velocities(state);
    restore_accelerations(state);
  }

  template <int dim>
  void
  PrescribedParticles<dim>::restore_velocities(ParticleState<dim> &state) const
  {
    const auto velocities = state.velocities();
    for (const auto &p : particles)
      for (unsigned int d = 0; d < dim; ++d)
        if (p.components[d])
          velocities[p.local_index][d] = p.velocity[d];
  }

  template <int dim>
  void
  PrescribedParticles<dim>::restore_accelerations(ParticleState<dim> &state) const
  {
    const auto accelerations = state.accelerations();
    for (const auto &p : particles)
      for (unsigned int d = 0; d < dim; ++d)
        if (p.components[d])
          accelerations[p.local_index][d] = p.acceleration[d];
  }

  template class PrescribedParticles<2>;
  template class PrescribedParticles<3>;
} // namespace PeriArlequin
