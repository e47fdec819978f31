#include <periarlequin/pd/prescribed_particles.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>

namespace PeriArlequin
{
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
    is_prescribed.assign(n_owned, false);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int r = 0; r < parameters.prescribed.size(); ++r)
        if (const auto &region = parameters.prescribed[r]; region.region.contains(positions[i]))
          {
            std::array<bool, dim> components;
            for (unsigned int d = 0; d < dim; ++d)
              components[d] = region.components[d];
            particles.push_back({i,
                                 region.function.get(),
                                 components,
                                 region.prescribes_velocity,
                                 positions[i],
                                 Tensor<1, dim>(),
                                 Tensor<1, dim>(),
                                 2 * dim + r});
            is_prescribed[i] = true;
            break;
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
    if (is_prescribed[i])
      return;
    particles.push_back(
      {i, &function, components, false, position, Tensor<1, dim>(), Tensor<1, dim>(), boundary_id});
    is_prescribed[i] = true;
  }

  template <int dim>
  bool
  PrescribedParticles<dim>::contains(const unsigned int i) const
  {
    return is_prescribed[i];
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
    Vector<double> before(dim), now(dim), after(dim);
    for (auto &p : particles)
      {
        auto             &function = *p.function;
        const Point<dim> &x        = p.position;
        function.set_time(time - dt);
        function.vector_value(x, before);
        function.set_time(time);
        function.vector_value(x, now);
        function.set_time(time + dt);
        function.vector_value(x, after);
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
