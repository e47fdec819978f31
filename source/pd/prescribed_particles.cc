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
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int r = 0; r < parameters.prescribed.size(); ++r)
        if (parameters.prescribed[r].region.contains(positions[i]))
          {
            particles.push_back({i, r, positions[i], Tensor<1, dim>(), Tensor<1, dim>()});
            break;
          }
  }

  template <int dim>
  bool
  PrescribedParticles<dim>::empty(const MPI_Comm communicator) const
  {
    return !Utilities::MPI::logical_or(!particles.empty(), communicator);
  }

  template <int dim>
  void
  PrescribedParticles<dim>::impose(const double        time,
                                   const double        dt,
                                   ParticleState<dim> &state)
  {
    Vector<double> before(dim), now(dim), after(dim);
    for (auto &p : particles)
      {
        const auto &condition = parameters.prescribed[p.region];
        auto       &function  = *condition.function;
        const Point<dim> &x         = p.position;
        function.set_time(time - dt);
        function.vector_value(x, before);
        function.set_time(time);
        function.vector_value(x, now);
        function.set_time(time + dt);
        function.vector_value(x, after);
        for (unsigned int d = 0; d < dim; ++d)
          {
            if (!condition.components[d])
              continue;
            if (condition.prescribes_velocity)
              {
                p.velocity[d]     = now(d);
                p.acceleration[d] = (after(d) - before(d)) / (2. * dt);
              }
            else
              {
                state.displacements()[p.local_index][d] = now(d);
                p.velocity[d]     = (after(d) - before(d)) / (2. * dt);
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
        if (parameters.prescribed[p.region].components[d])
          velocities[p.local_index][d] = p.velocity[d];
  }

  template <int dim>
  void
  PrescribedParticles<dim>::restore_accelerations(ParticleState<dim> &state) const
  {
    const auto accelerations = state.accelerations();
    for (const auto &p : particles)
      for (unsigned int d = 0; d < dim; ++d)
        if (parameters.prescribed[p.region].components[d])
          accelerations[p.local_index][d] = p.acceleration[d];
  }

  template class PrescribedParticles<2>;
  template class PrescribedParticles<3>;
} // namespace PeriArlequin
