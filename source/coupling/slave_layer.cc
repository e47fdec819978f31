#include <periarlequin/coupling/slave_layer.h>

namespace PeriArlequin
{
  template <int dim>
  void
  SlaveLayer<dim>::initialize(FEZone<dim> &fe, PDZone<dim> &pd)
  {
    fe_zone = &fe;
    pd_zone = &pd;
    particles.clear();
    for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
      if (pd.is_slave(i))
        particles.push_back(i);
    interpolation.reinit(fe, pd, particles);
    fe.initialize_vector(scratch);
    forces.resize(particles.size());

    // The slaves' masses move with the FE field: N^T m, the row sums of N^T M N.
    for (unsigned int r = 0; r < particles.size(); ++r)
      for (unsigned int d = 0; d < dim; ++d)
        forces[r][d] = pd.particle_mass(particles[r]);
    interpolation.Tvmult(scratch, forces);
    fe.add_lumped_mass(scratch);
  }

  template <int dim>
  void
  SlaveLayer<dim>::follow_displacements()
  {
    const VectorType &u = fe_zone->get_state().displacement;
    u.update_ghost_values();
    interpolation.for_each_row_range([&](const unsigned int first, const unsigned int end) {
      for (unsigned int r = first; r < end; ++r)
        pd_zone->set_displacement(particles[r], interpolation.interpolate(u, r));
    });
  }

  template <int dim>
  void
  SlaveLayer<dim>::follow_velocities()
  {
    const auto &state = fe_zone->get_state();
    state.velocity.update_ghost_values();
    state.acceleration.update_ghost_values();
    interpolation.for_each_row_range([&](const unsigned int first, const unsigned int end) {
      for (unsigned int r = first; r < end; ++r)
        pd_zone->set_velocity_and_acceleration(particles[r],
                                               interpolation.interpolate(state.velocity, r),
                                               interpolation.interpolate(state.acceleration, r));
    });
  }

  template <int dim>
  void
  SlaveLayer<dim>::add_forces(VectorType &force)
  {
    interpolation.for_each_row_range([&](const unsigned int first, const unsigned int end) {
      for (unsigned int r = first; r < end; ++r)
        forces[r] = pd_zone->blended_force(particles[r]);
    });
    interpolation.Tvmult(scratch, forces);
    force.add(1., scratch);
  }

  template <int dim>
  void
  SlaveLayer<dim>::add_loads(const double time, VectorType &force)
  {
    for (unsigned int r = 0; r < particles.size(); ++r)
      forces[r] = pd_zone->blended_load(particles[r], time);
    interpolation.Tvmult(scratch, forces);
    force.add(1., scratch);
  }

  template <int dim>
  types::global_dof_index
  SlaveLayer<dim>::n_global_slaves() const
  {
    return Utilities::MPI::sum(static_cast<types::global_dof_index>(particles.size()),
                               scratch.get_mpi_communicator());
  }

  template class SlaveLayer<2>;
  template class SlaveLayer<3>;
} // namespace PeriArlequin
