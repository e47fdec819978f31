#ifndef periarlequin_pd_fracture_criterion_h
#define periarlequin_pd_fracture_criterion_h

#include <periarlequin/base/plugin_registry.h>
#include <periarlequin/pd/bond_families.h>
#include <periarlequin/pd/breakable_bonds.h>
#include <periarlequin/pd/material_model.h>
#include <periarlequin/pd/pd_parameters.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * When bonds break (Peridynamics/Fracture = true): selected by name in
   * "Peridynamics/Fracture criterion"; a criterion's own parameters live in
   * "Peridynamics/<name>". Breaking is irreversible: a criterion only turns intact bonds into
   * broken ones (unbreakable bonds of a no-fail region stay).
   *
   * Users add a criterion by deriving from this class and registering it with
   * PERIARLEQUIN_REGISTER_FRACTURE_CRITERION in their own source file.
   */
  template <int dim>
  class FractureCriterion
  {
  public:
    virtual ~FractureCriterion() = default;

    /** Read the parameters declared by the class's static declare_parameters(). */
    virtual void
    parse_parameters(ParameterHandler &prm);

    /**
     * Once the bond families and the material model are initialised: the constants the
     * criterion needs.
     */
    virtual void
    initialize(const Parameters::Peridynamics<dim> &parameters,
               const PDMaterialModel<dim>          &model,
               const BondFamilies<dim>             &bonds) = 0;

    /**
     * Does break_bonds() read the material model's particle scalars? Then the PD zone
     * computes them for the current displacements first (one more pass over the bonds).
     */
    virtual bool
    needs_particle_scalars() const;

    /**
     * A criterion that is a critical stretch s_c returns it (> 0): the material model then
     * breaks the intact bonds whose stretch e / |xi| exceeds it where it forms the
     * extensions (PDMaterialModel::compute_particle_scalars_breaking()), and break_bonds()
     * is not called. 0 (the default): break_bonds() decides. The run's summary
     * prints it.
     */
    virtual double
    critical_stretch() const;

    /**
     * With critical_stretch() = 0: break the bonds that fail, visiting @p bonds (the intact
     * bonds of the owned particles with their extensions). @p scalars are the material
     * model's particle scalars (owned and ghost) of these displacements if
     * needs_particle_scalars(), otherwise of the last force evaluation.
     */
    virtual void
    break_bonds(BreakableBonds<dim> &bonds, ArrayView<const double> scalars) const;
  };

  /** The registry of fracture criteria. */
  template <int dim>
  using FractureCriterionRegistry = PluginRegistry<FractureCriterion<dim>>;

  extern template class PluginRegistry<FractureCriterion<2>>;
  extern template class PluginRegistry<FractureCriterion<3>>;

  /**
   * A bond breaks when its stretch e / |xi| exceeds the critical stretch s_c:
   * Peridynamics/Critical stretch if > 0, otherwise the material model's s_c of the critical
   * energy release rate G0 (Peridynamics/Critical energy release rate) and the horizon.
   */
  template <int dim>
  class CriticalStretchCriterion : public FractureCriterion<dim>
  {
  public:
    void
    initialize(const Parameters::Peridynamics<dim> &parameters,
               const PDMaterialModel<dim>          &model,
               const BondFamilies<dim>             &bonds) override;
    double
    critical_stretch() const override;

  private:
    double stretch = 0;
  };

  /**
   * A bond breaks when it is stretched (e > 0) and its energy, the material model's split of
   * the strain energy into bonds (PDMaterialModel::compute_pair_energies()), reaches the
   * critical bond energy w_c. w_c is set so that cutting the lattice along a lattice plane
   * with every cut bond at w_c costs G0 per unit area (Peridynamics/Critical energy release
   * rate): G0 = w_c sum over the stencil offsets xi with xi_0 > 0 of xi_0 V v, which is
   * w_c 2 delta^3 / 3 in 2D and w_c pi delta^4 / 4 in 3D for a continuous family. Unlike a
   * critical stretch derived from a pairwise (bond-based) energy, this takes the energy the
   * state-based model actually stores in the bond, its dilatation part included.
   */
  template <int dim>
  class CriticalBondEnergyCriterion : public FractureCriterion<dim>
  {
  public:
    void
    initialize(const Parameters::Peridynamics<dim> &parameters,
               const PDMaterialModel<dim>          &model,
               const BondFamilies<dim>             &bonds) override;
    void
    break_bonds(BreakableBonds<dim> &bonds, ArrayView<const double> scalars) const override;
    bool
    needs_particle_scalars() const override;

    /** The critical bond energy w_c [J/m^(2 dim)]. */
    double
    critical_energy() const;

  private:
    const PDMaterialModel<dim> *model            = nullptr;
    double                      critical_energy_ = 0;
    mutable std::vector<double> pair_energy;
  };
} // namespace PeriArlequin

/**
 * Register a fracture criterion class template (instantiated for dim = 2 and 3, default
 * constructed; with its static declare_parameters(ParameterHandler &) if it has one) under
 * @p name.
 */
#define PERIARLEQUIN_REGISTER_FRACTURE_CRITERION(classname, name, description)            \
  namespace                                                                               \
  {                                                                                       \
    const bool periarlequin_registered_fracture_criterion_##classname =                   \
      PeriArlequin::register_plugin_template<PeriArlequin::FractureCriterion, classname>( \
        name,                                                                             \
        description);                                                                     \
  }

#endif
