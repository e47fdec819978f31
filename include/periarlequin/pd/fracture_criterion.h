#ifndef periarlequin_pd_fracture_criterion_h
#define periarlequin_pd_fracture_criterion_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/array_view.h>
#include <deal.II/base/tensor.h>

#include <periarlequin/base/plugin_registry.h>
#include <periarlequin/pd/bond_families.h>
#include <periarlequin/pd/material_model.h>
#include <periarlequin/pd/pd_parameters.h>

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

    /** Once the material model is initialised: the constants the criterion needs. */
    virtual void
    initialize(const Parameters::Peridynamics<dim> &parameters,
               const PDMaterialModel<dim>          &model) = 0;

    /**
     * Mark the intact bonds of the owned particles' families that fail under the
     * displacements @p displacement (owned and ghost particles) as broken. A bond to a
     * ghost is held by two ranks, which must decide alike: decide from the bond's reference
     * vector and the displacement difference of its ends (BondFamilies::extension is
     * bit-identical on both).
     */
    virtual void
    break_bonds(BondFamilies<dim> &bonds, ArrayView<const Tensor<1, dim>>  displacement) const = 0;

    /** The critical bond stretch [-] for the run's summary; 0 if the criterion has none. */
    virtual double
    critical_stretch() const = 0;
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
               const PDMaterialModel<dim>          &model) override;
    void
    break_bonds(BondFamilies<dim>                 &bonds,
                ArrayView<const Tensor<1, dim>>  displacement) const override;
    double
    critical_stretch() const override;

  private:
    double stretch = 0;
  };
} // namespace PeriArlequin

/**
 * Register a fracture criterion class template (instantiated for dim = 2 and 3, default
 * constructed; with its static declare_parameters(ParameterHandler &) if it has one) under
 * @p name.
 */
#define PERIARLEQUIN_REGISTER_FRACTURE_CRITERION(classname, name, description)               \
  namespace                                                                                  \
  {                                                                                          \
    const bool periarlequin_registered_fracture_criterion_##classname =                      \
      PeriArlequin::register_plugin_template<PeriArlequin::FractureCriterion, classname>(    \
        name, description);                                                                  \
  }

#endif
