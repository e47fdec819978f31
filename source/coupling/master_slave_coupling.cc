#include <periarlequin/coupling/master_slave_coupling.h>

namespace PeriArlequin
{
  template <int dim>
  MasterSlaveCoupling<dim>::MasterSlaveCoupling(const Parameters::Coupling &parameters)
    : parameters(parameters)
  {}

  template <int dim>
  BlendingProfile
  MasterSlaveCoupling<dim>::blending_profile() const
  {
    return BlendingProfile::step;
  }

  template <int dim>
  void
  MasterSlaveCoupling<dim>::initialize(const BlendingField<dim> &blending,
                                       FEZone<dim>              &fe,
                                       PDZone<dim>              &pd,
                                       const double)
  {
    fe_zone = &fe;
    pd_zone = &pd;
    slaves.initialize(fe, pd);
    // FE DoFs of the PD-side half of the overlap (alpha = 0 there) follow the PD field.
    std::vector<unsigned int> dofs, components;
    std::vector<Point<dim>>   points;
    fe.support_points(dofs, points, components);
    fe_slaves.clear();
    for (unsigned int k = 0; k < dofs.size(); ++k)
      if (blending.in_overlap(points[k]) && blending.value(points[k]) == 0)
        fe_slaves.push_back({dofs[k], components[k], pd.lattice_interpolation(points[k])});
    const MPI_Comm communicator = pd.get_communicator();
    AssertThrow(Utilities::MPI::sum(fe_slaves.size(), communicator) > 0 &&
                  slaves.n_global_slaves() > 0,
                ExcMessage("Invalid input: parameter 'Coupling/Overlap region' = '" +
                           parameters.overlap_text +
                           "'; allowed: an overlap whose halves hold FE nodes (PD side) "
                           "and PD particles (FE side) for the bad coupling."));
    set_fe_force_weights(parameters, blending, fe);
  }

  template <int dim>
  void
  MasterSlaveCoupling<dim>::set_slave_displacements()
  {
    pd_zone->update_ghost_displacements();
    for (const auto &slave : fe_slaves)
      {
        double value = 0;
        for (const auto &[j, w] : slave.weights)
          value += w * pd_zone->get_state().displacements()[j][slave.component];
        fe_zone->set_displacement(slave.dof, value);
      }
    slaves.follow_displacements();
  }

  template <int dim>
  void
  MasterSlaveCoupling<dim>::add_interface_forces(const double time)
  {
    add_slave_forces(parameters, slaves, time, *fe_zone);
  }

  template <int dim>
  void
  MasterSlaveCoupling<dim>::apply_damping()
  {}

  template <int dim>
  void
  MasterSlaveCoupling<dim>::enforce_constraint()
  {}

  template <int dim>
  void
  MasterSlaveCoupling<dim>::set_slave_velocities()
  {
    pd_motion.resize(2 * dim * pd_zone->reference_positions().size());
    for (unsigned int i = 0; i < pd_zone->n_owned_particles(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        {
          pd_motion[2 * dim * i + d]       = pd_zone->get_state().velocities()[i][d];
          pd_motion[2 * dim * i + dim + d] = pd_zone->get_state().accelerations()[i][d];
        }
    pd_zone->update_ghosts(pd_motion, 2 * dim);
    for (const auto &slave : fe_slaves)
      {
        double v = 0, a = 0;
        for (const auto &[j, w] : slave.weights)
          {
            v += w * pd_motion[2 * dim * j + slave.component];
            a += w * pd_motion[2 * dim * j + dim + slave.component];
          }
        fe_zone->set_velocity_and_acceleration(slave.dof, v, a);
      }
    slaves.follow_velocities();
  }

  template <int dim>
  std::pair<double, double>
  MasterSlaveCoupling<dim>::constraint_residuals() const
  {
    return {0., 0.};
  }

  template <int dim>
  types::global_dof_index
  MasterSlaveCoupling<dim>::n_multipliers() const
  {
    return 0;
  }

  template <int dim>
  std::pair<types::global_dof_index, types::global_dof_index>
  MasterSlaveCoupling<dim>::n_coupled_particles() const
  {
    return {0, slaves.n_global_slaves()};
  }

  template <int dim>
  unsigned int
  MasterSlaveCoupling<dim>::last_solver_iterations() const
  {
    return 0;
  }

  template class MasterSlaveCoupling<2>;
  template class MasterSlaveCoupling<3>;

  PERIARLEQUIN_REGISTER_COUPLING(MasterSlaveCoupling,
                                 "bad",
                                 "The paper's fig. 8: PD nodes of the FE-side half of the "
                                 "overlap follow the FE field, FE nodes of the PD-side half "
                                 "follow the PD field; no multipliers (the baseline that "
                                 "reflects).")
} // namespace PeriArlequin
