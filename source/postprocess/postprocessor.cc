#include <periarlequin/postprocess/postprocessor.h>
#include <periarlequin/simulator.h>

namespace PeriArlequin
{
  template <int dim>
  void
  Postprocessor<dim>::parse_parameters(ParameterHandler &)
  {}

  template <int dim>
  void
  EnergyPostprocessor<dim>::execute(const Simulator<dim> &simulator, EnergyHistory &history)
  {
    const FEZone<dim> *fe = simulator.has_fe_zone() ? &simulator.get_fe_zone() : nullptr;
    const PDZone<dim> *pd = simulator.get_pd_zone();
    const double fe_kinetic = fe ? fe->kinetic_energy() : 0., fe_strain = fe ? fe->strain_energy() : 0.;
    const double pd_kinetic = pd ? pd->kinetic_energy() : 0., pd_strain = pd ? pd->strain_energy() : 0.;
    const double work = (fe ? fe->external_work() : 0.) + (pd ? pd->external_work() : 0.);
    const double kinetic = fe_kinetic + pd_kinetic, strain = fe_strain + pd_strain;
    history.add_value("kinetic_energy", kinetic);
    history.add_value("strain_energy", strain);
    history.add_value("external_work", work);
    history.add_value("total_energy", kinetic + strain - work);
    history.add_value("fe_kinetic_energy", fe_kinetic);
    history.add_value("fe_strain_energy", fe_strain);
    history.add_value("pd_kinetic_energy", pd_kinetic);
    history.add_value("pd_strain_energy", pd_strain);
    history.add_value("broken_bonds", pd ? pd->n_global_broken_bonds() : 0.);
  }

  template <int dim>
  void
  MonitorRegionEnergies<dim>::execute(const Simulator<dim> &simulator, EnergyHistory &history)
  {
    const PDZone<dim> *pd = simulator.get_pd_zone();
    const auto energies =
      pd ? pd->energies_in(simulator.get_monitor_region()) : std::pair<double, double>();
    history.add_value("pure_pd_kinetic_energy", energies.first);
    history.add_value("pure_pd_strain_energy", energies.second);
    history.add_value("pure_pd_energy", energies.first + energies.second);
  }

  template <int dim>
  void
  ConstraintResiduals<dim>::execute(const Simulator<dim> &simulator, EnergyHistory &history)
  {
    const Coupling<dim> *coupling = simulator.get_coupling();
    const auto residuals =
      coupling ? coupling->constraint_residuals() : std::pair<double, double>();
    history.add_value("constraint_residual", residuals.first);
    history.add_value("constraint_rate_residual", residuals.second);
    history.add_value("multiplier_iterations", coupling ? coupling->last_solver_iterations() : 0.);
  }

  template class Postprocessor<2>;
  template class Postprocessor<3>;
  template class EnergyPostprocessor<2>;
  template class EnergyPostprocessor<3>;
  template class MonitorRegionEnergies<2>;
  template class MonitorRegionEnergies<3>;
  template class ConstraintResiduals<2>;
  template class ConstraintResiduals<3>;
  template class PluginRegistry<Postprocessor<2>>;
  template class PluginRegistry<Postprocessor<3>>;

  PERIARLEQUIN_REGISTER_POSTPROCESSOR(
    EnergyPostprocessor,
    "energies",
    "kinetic, strain and total energy, external work, per zone; broken bonds")
  PERIARLEQUIN_REGISTER_POSTPROCESSOR(
    MonitorRegionEnergies,
    "monitor region energies",
    "kinetic and strain energy of the PD particles in Output/Monitor region")
  PERIARLEQUIN_REGISTER_POSTPROCESSOR(
    ConstraintResiduals,
    "constraint residuals",
    "|g|, |g_dot| of the coupling constraint and the multiplier CG iterations")
} // namespace PeriArlequin
