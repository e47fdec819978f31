#include <periarlequin/pd/fracture_criterion.h>

namespace PeriArlequin
{
  template <int dim>
  void
  FractureCriterion<dim>::parse_parameters(ParameterHandler &)
  {}

  template <int dim>
  bool
  FractureCriterion<dim>::needs_particle_scalars() const
  {
    return false;
  }

  template <int dim>
  double
  FractureCriterion<dim>::critical_stretch() const
  {
    return 0;
  }

  template <int dim>
  void
  FractureCriterion<dim>::break_bonds(BreakableBonds<dim> &, ArrayView<const double>) const
  {
    AssertThrow(false,
                ExcMessage("A fracture criterion breaks bonds in break_bonds() unless it "
                           "returns a critical_stretch() > 0."));
  }

  template <int dim>
  void
  CriticalStretchCriterion<dim>::initialize(const Parameters::Peridynamics<dim> &parameters,
                                            const PDMaterialModel<dim>          &model,
                                            const BondFamilies<dim> &)
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
  double
  CriticalStretchCriterion<dim>::critical_stretch() const
  {
    return stretch;
  }

  template <int dim>
  void
  CriticalBondEnergyCriterion<dim>::initialize(const Parameters::Peridynamics<dim> &parameters,
                                               const PDMaterialModel<dim>          &material,
                                               const BondFamilies<dim>             &bonds)
  {
    if (!(parameters.energy_release_rate > 0))
      throw_invalid_parameter("Peridynamics/Critical energy release rate",
                              parameters.energy_release_rate,
                              "a value > 0 [J/m^2] with Fracture criterion = critical bond "
                              "energy");
    if (parameters.critical_stretch > 0)
      throw_invalid_parameter("Peridynamics/Critical stretch",
                              parameters.critical_stretch,
                              "0 with Fracture criterion = critical bond energy (its critical "
                              "bond energy comes from Critical energy release rate)");
    double cut_per_unit_area = 0;
    for (const auto &entry : bonds.stencil)
      if (entry.xi[0] > 0)
        cut_per_unit_area += entry.xi[0] * entry.volume;
    model            = &material;
    critical_energy_ = parameters.energy_release_rate / cut_per_unit_area;
  }

  template <int dim>
  void
  CriticalBondEnergyCriterion<dim>::break_bonds(BreakableBonds<dim>    &bonds,
                                                ArrayView<const double> scalars) const
  {
    model->compute_pair_energies(bonds.families(), bonds.displacements(), scalars, pair_energy);
    bonds.for_each_intact([&](const typename BreakableBonds<dim>::Bond &bond) {
      if (pair_energy[bond.index] >= critical_energy_ && bond.extension() > 0)
        bonds.break_bond(bond);
    });
  }

  template <int dim>
  bool
  CriticalBondEnergyCriterion<dim>::needs_particle_scalars() const
  {
    return true;
  }

  template <int dim>
  double
  CriticalBondEnergyCriterion<dim>::critical_energy() const
  {
    return critical_energy_;
  }

  template class FractureCriterion<2>;
  template class FractureCriterion<3>;
  template class CriticalStretchCriterion<2>;
  template class CriticalStretchCriterion<3>;
  template class CriticalBondEnergyCriterion<2>;
  template class CriticalBondEnergyCriterion<3>;
  template class PluginRegistry<FractureCriterion<2>>;
  template class PluginRegistry<FractureCriterion<3>>;

  PERIARLEQUIN_REGISTER_FRACTURE_CRITERION(
    CriticalStretchCriterion,
    "critical stretch",
    "a bond breaks when its stretch exceeds Critical stretch, or the material model's "
    "critical stretch of G0")

  PERIARLEQUIN_REGISTER_FRACTURE_CRITERION(
    CriticalBondEnergyCriterion,
    "critical bond energy",
    "a stretched bond breaks when its share of the material model's strain energy reaches the "
    "critical bond energy of G0")
} // namespace PeriArlequin
