#ifndef periarlequin_adaptivity_conversion_criterion_h
#define periarlequin_adaptivity_conversion_criterion_h

#include <periarlequin/base/parameters.h>
#include <periarlequin/base/plugin_registry.h>
#include <periarlequin/base/regions.h>
#include <periarlequin/fe/fe_zone.h>
#include <periarlequin/pd/pd_zone.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <array>
#include <set>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * What a conversion criterion may need of the growth that asks it, to derive its defaults
   * from the material and the step.
   */
  struct GrowthContext
  {
    /** The time step [s]. */
    double time_step = 0;
    /** Steps between two regular checks (Adaptive PD zone/Check interval) [-]. */
    unsigned int check_interval = 1;
    /**
     * New damage closer than this to an FE cell converts cells at once, in the step it
     * appears: two bond reaches plus the distance a longitudinal wave runs in a step [m].
     */
    double trigger_distance = 0;
    /** An upper bound of a crack's speed: the shear-wave speed [m/s]. */
    double crack_speed_bound = 0;
    /**
     * The time over which the settling force of a new particle fades out (0: none), see
     * PDZone::start_settling() [s].
     */
    double settling_time = 0;
    /**
     * A growth converts the FE cells within this distance of the damage that caused it
     * (0: no lead) [m].
     */
    double lead_distance = 0;
    /** The boundary ids that carry a traction or a prescribed displacement. */
    std::set<types::boundary_id> loaded_boundaries;

    /**
     * The distance to convert around damage: the trigger distance plus how far a crack can
     * run between two regular checks, c_s dt (Check interval), so that the next growth is
     * due a check interval later at the soonest. That run is taken at most twice the trigger
     * distance, so that a long check interval does not convert the whole model (the trigger
     * keeps the zone ahead of the crack without it) [m].
     */
    double
    conversion_distance() const
    {
      return trigger_distance +
             std::min(crack_speed_bound * time_step * check_interval, 2. * trigger_distance);
    }
  };

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
     * parameter if they cannot work with it); automatic defaults from @p context.
     */
    virtual void
    initialize(const FEZone<dim>   &fe_zone,
               const PDZone<dim>   &pd_zone,
               const GrowthContext &context);

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

  /**
   * A criterion that decides by the centre of a cell alone (a region known in advance, a
   * prescribed sequence of growths): derive and say in converts() which centres become PD.
   */
  template <int dim>
  class CellCentreCriterion : public ConversionCriterion<dim>
  {
  public:
    /** Flag the locally owned cells whose centre converts() accepts. */
    void
    mark_cells(const FEZone<dim> &fe_zone,
               const PDZone<dim> &pd_zone,
               std::vector<bool> &convert) const override;

  protected:
    /** Should the cell with centre @p centre be PD now? */
    virtual bool
    converts(const Point<dim> &centre) const = 0;
  };

  /** The registry of conversion criteria. */
  template <int dim>
  using ConversionCriterionRegistry = PluginRegistry<ConversionCriterion<dim>>;

  extern template class PluginRegistry<ConversionCriterion<2>>;
  extern template class PluginRegistry<ConversionCriterion<3>>;

  namespace internal
  {
    /**
     * Points binned on a grid of bins at least a search distance wide (at most about four
     * bins a point), so that a box looks only at the bins it touches, widened by the
     * distance, not at every point.
     */
    template <int dim>
    class PointBins
    {
    public:
      /** Bin @p points for searches out to @p distance [m]. */
      PointBins(const std::vector<Point<dim>> &points, const double distance);

      /** Is one of the points closer than the distance to @p box? */
      bool
      any_near(const Box<dim> &box) const;

    private:
      /**
       * Call @p visit(p) for the points closer than the distance to @p box until it returns
       * true; whether it did.
       */
      template <typename Visitor>
      bool
      visit_near(const Box<dim> &box, const Visitor &visit) const;

      const double                  distance;
      Box<dim>                      bounds;
      double                        bin = 1;
      std::array<unsigned int, dim> n_bins;
      std::vector<std::size_t>      bin_start;
      std::vector<Point<dim>>       binned;
    };

    /**
     * Flag the locally owned FE cells (with DoFs) within @p distance of one of @p points (the
     * points of all ranks; binned here, so that each cell looks at the points near it only).
     */
    template <int dim>
    void
    mark_cells_near(const FEZone<dim>             &fe_zone,
                    const std::vector<Point<dim>> &points,
                    const double                   distance,
                    std::vector<bool>             &convert);

    /** The points of all ranks in one list, in rank order (collective). */
    template <int dim>
    std::vector<Point<dim>>
    gather_points(const std::vector<Point<dim>> &local, const MPI_Comm communicator);
  } // namespace internal

  /**
   * Cells within a distance of damage become PD: a cell is flagged if some particle with
   * damage above the threshold lies within "Distance" of it. The PD region then holds the
   * ball of that radius around every damaged particle, so a crack tip stays that far from the
   * overlap as long as it runs less than the margin between two checks. The distance must
   * reach the growth's trigger distance (two bond reaches, 2 (delta + dx/2), whose breaking
   * stops a coupled run, plus one step of a wave); by default it is the conversion distance
   * of GrowthContext, which a crack cannot cross between two checks.
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
    initialize(const FEZone<dim>   &fe_zone,
               const PDZone<dim>   &pd_zone,
               const GrowthContext &context) override;
    void
    mark_cells(const FEZone<dim> &fe_zone,
               const PDZone<dim> &pd_zone,
               std::vector<bool> &convert) const override;

  private:
    double distance         = 0;
    double damage_threshold = 0;
  };

  /**
   * Cells where the continuum is strained towards failure become PD, before any bond
   * breaks: a cell is flagged if the largest principal strain of the FE field at one of its
   * Gauss points (the stretch of the worst-aligned bond) reaches "Strain", or, if that is 0,
   * "Fraction of critical stretch" times the fracture criterion's critical stretch. Cells
   * next to a flagged cell (within "Buffer" [m] of it, by default the trigger distance) are
   * flagged too, so that a crack that starts there is inside the zone. Cells on a boundary
   * that carries a traction or a displacement are left to FE: in PD the first particle layers
   * carry such a load with about twice the continuum's strain (the surface effect), so a
   * converted loaded edge breaks bonds the continuum would not, right next to the band.
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
    initialize(const FEZone<dim>   &fe_zone,
               const PDZone<dim>   &pd_zone,
               const GrowthContext &context) override;
    void
    mark_cells(const FEZone<dim> &fe_zone,
               const PDZone<dim> &pd_zone,
               std::vector<bool> &convert) const override;

  private:
    double                       strain_threshold = 0;
    double                       stretch_fraction = 0.5;
    double                       buffer           = 0;
    std::set<types::boundary_id> loaded_boundaries;
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
