#include <periarlequin/coupling/coupling.h>
#include <periarlequin/coupling/slave_layer.h>

namespace PeriArlequin
{
  template <int dim>
  void
  Coupling<dim>::parse_parameters(ParameterHandler &)
  {}

  template <int dim>
  void
  set_fe_force_weights(const Parameters::Coupling &parameters,
                       const BlendingField<dim>   &blending,
                       FEZone<dim>                &fe_zone)
  {
    if (parameters.blending != Parameters::Blending::force)
      return;
    std::vector<unsigned int> dofs, components;
    std::vector<Point<dim>>   points;
    fe_zone.support_points(dofs, points, components);
    std::vector<double> alpha(fe_zone.lumped_mass().locally_owned_size(), 1.);
    for (unsigned int k = 0; k < dofs.size(); ++k)
      alpha[dofs[k]] = blending.value(points[k]);
    fe_zone.set_nodal_force_weights(alpha);
  }

  template <int dim>
  void
  add_slave_forces(const Parameters::Coupling &parameters,
                   SlaveLayer<dim>            &slaves,
                   const double                time,
                   FEZone<dim>                &fe_zone)
  {
    slaves.add_loads(time, fe_zone.applied_forces());
    if (parameters.blending == Parameters::Blending::energy)
      slaves.add_forces(fe_zone.interface_forces());
  }

  template void
  set_fe_force_weights(const Parameters::Coupling &, const BlendingField<2> &, FEZone<2> &);
  template void
  set_fe_force_weights(const Parameters::Coupling &, const BlendingField<3> &, FEZone<3> &);
  template void
  add_slave_forces(const Parameters::Coupling &, SlaveLayer<2> &, const double, FEZone<2> &);
  template void
  add_slave_forces(const Parameters::Coupling &, SlaveLayer<3> &, const double, FEZone<3> &);

  template class Coupling<2>;
  template class Coupling<3>;
  template class PluginRegistry<Coupling<2>, const Parameters::Coupling &>;
  template class PluginRegistry<Coupling<3>, const Parameters::Coupling &>;
} // namespace PeriArlequin
