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
  connect_fe_forces(const Parameters::Coupling &parameters,
                    const BlendingField<dim>   &blending,
                    FEZone<dim>                &fe_zone,
                    SlaveLayer<dim>            &slaves)
  {
    if (parameters.blending == Parameters::Blending::force)
      {
        std::vector<unsigned int> dofs, components;
        std::vector<Point<dim>>   points;
        fe_zone.support_points(dofs, points, components);
        std::vector<double> alpha(fe_zone.lumped_mass().locally_owned_size(), 1.);
        for (unsigned int k = 0; k < dofs.size(); ++k)
          alpha[dofs[k]] = blending.value(points[k]);
        fe_zone.set_nodal_force_weights(alpha);
      }
    fe_zone.set_additional_load(
      [&slaves](const double time, LinearAlgebra::distributed::Vector<double> &force) {
        slaves.add_loads(time, force);
      });
    if (parameters.blending == Parameters::Blending::energy)
      fe_zone.set_interface_force(
        [&slaves](LinearAlgebra::distributed::Vector<double> &force) { slaves.add_forces(force); });
  }

  template void
  connect_fe_forces(const Parameters::Coupling &,
                    const BlendingField<2> &,
                    FEZone<2> &,
                    SlaveLayer<2> &);
  template void
  connect_fe_forces(const Parameters::Coupling &,
                    const BlendingField<3> &,
                    FEZone<3> &,
                    SlaveLayer<3> &);

  template class Coupling<2>;
  template class Coupling<3>;
  template class PluginRegistry<Coupling<2>, const Parameters::Coupling &>;
  template class PluginRegistry<Coupling<3>, const Parameters::Coupling &>;
} // namespace PeriArlequin
