#ifndef periarlequin_adaptivity_conversion_criterion_h
#define periarlequin_adaptivity_conversion_criterion_h

#include <periarlequin/base/parameters.h>
#include <periarlequin/base/plugin_registry.h>
#include <periarlequin/fe/fe_zone.h>
#include <periarlequin/pd/pd_zone.h>

#include <deal.II/base/parameter_handler.h>

#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * Which FE cells an adaptive PD zone takes next: selected by name in "Adaptive PD
   * zone/Conversion criterion" (none: the PD zone is fixed); a criterion's own parameters
   * live in "Adaptive PD zone/<name>". Every "Check interval" steps the simulator asks it to
   * flag locally owned cells; the flagged FE cells become pure PD (whole cells), and the
   * overlap band and the slave layer move outward with them.
   *
   * Users add a criterion by deriving from this class and registering it with
   * PERIARLEQUIN_REGISTER_CONVERSION_CRITERION in their own source file.
   */
  template <int dim>
  class ConversionCriterion
  {
  public:
    virtual ~ConversionCriterion() = default;

    /** Read the parameters declared by the class's static declare_parameters(). */
    virtual void
    parse_parameters(ParameterHandler &prm);

    /**
     * Check the parameters against the case once the zones exist (a clear error naming the
     * parameter if they cannot work with it).
     */
    virtual void
    initialize(const FEZone<dim> &fe_zone, const PDZone<dim> &pd_zone);

    /**
     * Set @p convert[cell->active_cell_index()] for the locally owned cells that should be
     * peridynamic now (the vector has one entry per active cell, all false). Flags on cells
     * that are PD already are ignored. Collective: every rank calls it.
     */
    virtual void
    mark_cells(const FEZone<dim> &fe_zone,
               const PDZone<dim> &pd_zone,
               std::vector<bool> &convert) const = 0;
  };

  /** The registry of conversion criteria. */
  template <int dim>
  using ConversionCriterionRegistry = PluginRegistry<ConversionCriterion<dim>>;

  extern template class PluginRegistry<ConversionCriterion<2>>;
  extern template class PluginRegistry<ConversionCriterion<3>>;

  /**
   * Cells within a distance of damage become PD: a cell is flagged if some particle with
   * damage above the threshold lies within "Distance" of it. The PD region then holds the
   * ball of that radius around every damaged particle, so a crack tip stays that far from the
   * overlap as long as it runs less than the margin between two checks. The distance must
   * exceed two bond reaches, 2 (delta + dx/2): bonds that far from the overlap are the ones
   * whose breaking stops a coupled run.
   */
  template <int dim>
  class DamageProximityCriterion : public ConversionCriterion<dim>
  {
  public:
    /** The entries of subsection "Adaptive PD zone/<name>", declared and parsed. */
    void
    entries(ParameterEntries &entries);
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm) override;
    void
    initialize(const FEZone<dim> &fe_zone, const PDZone<dim> &pd_zone) override;
    void
    mark_cells(const FEZone<dim> &fe_zone,
               const PDZone<dim> &pd_zone,
               std::vector<bool> &convert) const override;

  private:
    double distance         = 0;
    double damage_threshold = 0;
  };

  /**
   * Cells where the continuum is strained towards failure become PD: a cell is flagged if
   * the largest principal strain of the FE field at its centre reaches "Strain", or, if that
   * is 0, "Fraction of critical stretch" times the fracture criterion's critical stretch.
   * Cells next to a flagged cell (within "Buffer" [m] of it) are flagged too, so the zone
   * runs ahead of the strain concentration.
   */
  template <int dim>
  class StrainCriterion : public ConversionCriterion<dim>
  {
  public:
    /** The entries of subsection "Adaptive PD zone/<name>", declared and parsed. */
    void
    entries(ParameterEntries &entries);
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm) override;
    void
    initialize(const FEZone<dim> &fe_zone, const PDZone<dim> &pd_zone) override;
    void
    mark_cells(const FEZone<dim> &fe_zone,
               const PDZone<dim> &pd_zone,
               std::vector<bool> &convert) const override;

  private:
    double strain_threshold = 0;
    double stretch_fraction = 0.5;
    double buffer           = 0;
  };
} // namespace PeriArlequin

/**
 * Register a conversion criterion class template (instantiated for dim = 2 and 3, default
 * constructed; with its static declare_parameters(ParameterHandler &) if it has one) under
 * @p name.
 */
#define PERIARLEQUIN_REGISTER_CONVERSION_CRITERION(classname, name, description)            \
  namespace                                                                                 \
  {                                                                                         \
    const bool periarlequin_registered_conversion_##classname =                             \
      PeriArlequin::register_plugin_template<PeriArlequin::ConversionCriterion, classname>( \
        name,                                                                               \
        description);                                                                       \
  }

#endif
