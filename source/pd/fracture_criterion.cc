#include <periarlequin/pd/fracture_criterion.h>

namespace PeriArlequin
{
  template <int dim>
  void
  FractureCriterion<dim>::parse_parameters(ParameterHandler &)
  {}

  template <int dim>
  void
  CriticalStretchCriterion<dim>::initialize(const Parameters::Peridynamics<dim> &parameters,
                                            const PDMaterialModel<dim>          &model)
  {
    if (parameters.critical_stretch == 0 && !(parameters.energy_release_rate > 0))
      throw_invalid_parameter("Peridynamics/Critical energy release rate",
                              parameters.energy_release_rate,
                              "a value > 0 [J/m^2] when Fracture = true (or set 'Critical "
                              "stretch' > 0)");
    stretch = parameters.critical_stretch > 0 ?
                parameters.critical_stretch :
                model.critical_stretch(parameters.energy_release_rate, parameters.horizon());
  }

  template <int dim>
  void
  CriticalStretchCriterion<dim>::break_bonds(BondFamilies<dim>                 &bonds,
                                             ArrayView<const Tensor<1, dim>>  u) const
  {
    for (unsigned int i = 0; i < bonds.n_owned; ++i)
      for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
        {
          if (bonds.state[n] != BondFamilies<dim>::intact)
            continue;
          const auto  &bond = bonds.stencil[bonds.stencil_index[n]];
          const double e =
            BondFamilies<dim>::extension(bond, u[bonds.neighbor[n]] - u[i]).first;
          if (e > stretch * bond.length)
            bonds.state[n] = BondFamilies<dim>::broken;
        }
  }

  template <int dim>
  double
  CriticalStretchCriterion<dim>::critical_stretch() const
  {
    return stretch;
  }

  template class FractureCriterion<2>;
  template class FractureCriterion<3>;
  template class CriticalStretchCriterion<2>;
  template class CriticalStretchCriterion<3>;
  template class PluginRegistry<FractureCriterion<2>>;
  template class PluginRegistry<FractureCriterion<3>>;

  PERIARLEQUIN_REGISTER_FRACTURE_CRITERION(
    CriticalStretchCriterion,
    "critical stretch",
    "a bond breaks when its stretch exceeds Critical stretch, or the material model's "
    "critical stretch of G0")
} // namespace PeriArlequin
