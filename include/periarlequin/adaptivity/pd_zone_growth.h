#ifndef periarlequin_adaptivity_pd_zone_growth_h
#define periarlequin_adaptivity_pd_zone_growth_h

#include <periarlequin/adaptivity/conversion_criterion.h>
#include <periarlequin/base/parameters.h>
#include <periarlequin/coupling/blending_field.h>
#include <periarlequin/fe/fe_zone.h>
#include <periarlequin/pd/pd_parameters.h>
#include <periarlequin/pd/pd_zone.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <functional>
#include <memory>
#include <string>

namespace PeriArlequin
{
  using namespace dealii;

  namespace Parameters
  {
    /** Subsection "Adaptive PD zone": which criteria convert FE cells, and how often. */
    template <int dim>
    struct AdaptivePDZone
    {
      /** "none" (a fixed PD zone) or a list of registered ConversionCriterion names. */
      std::string  conversion_criterion = "none";
      unsigned int check_interval       = 10;
      double       imbalance_tolerance  = 0.1;
      double       settling_time        = 0;
      double       lead_distance        = 0;

      void
      entries(ParameterEntries &entries);
    };
  } // namespace Parameters

  /**
   * The growth of an adaptive PD zone, between steps: the FE cells that one of the conversion
   * criteria flags become pure PD. They join the PD region (as boxes, or as cells of a general
   * mesh); the overlap band and the
   * slave layer move outward; new particles fill the lattice sites the grown zone needs, with
   * displacement, velocity and acceleration interpolated from the FE field (which still lives
   * in the converted cells); the FE zone drops the DoFs of the converted cells; the caller
   * rebuilds the coupling and the accelerations; the free particles that gained mass take the
   * momentum the two quadratures of the blended mass disagree on, so that a conversion
   * conserves linear momentum. Existing particles keep their state and broken bonds. The new
   * pure-PD particles settle into the PD state over the settling time (a force that fades out
   * makes up the difference between the FE and the PD acceleration at first), so that the
   * switch from the FE to the PD forces makes no overshoot.
   *
   * A crack cannot outrun the zone: besides the criterion's checks every Check interval
   * steps, every step in which a bond breaks within the trigger distance of an FE cell
   * (two bond reaches plus a wave's run in a step) converts the cells around the new damage
   * at once, out to the conversion distance (GrowthContext). The overlap stop of the PD zone
   * stays as the last guard.
   *
   * A growth also converts the FE cells within the lead distance of the running damage (the
   * bonds broken since the last growth: the running crack tips, not a pre-crack or old crack
   * faces), so that every running tip gets room for several check intervals at once and the
   * zone grows less often. The lead stops a band width short of the boundary: a
   * growth that no damage asks for does not put the PD surface layer of an edge in or next
   * to the band.
   */
  template <int dim>
  class PDZoneGrowth
  {
  public:
    /** Declare subsection "Adaptive PD zone" and the criteria's subsections inside it. */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * The growth that subsection "Adaptive PD zone" asks for, or nullptr (Conversion
     * criterion = none). A clear error if the case cannot grow its PD zone (the zones are not
     * coupled across a band).
     */
    static std::unique_ptr<PDZoneGrowth<dim>>
    create(ParameterHandler                    &prm,
           const Parameters::Coupling          &coupling,
           const Parameters::Peridynamics<dim> &pd_parameters);

    /** A growth that converts the cells any of @p criteria flags. */
    PDZoneGrowth(const Parameters::AdaptivePDZone<dim>                 &parameters,
                 std::vector<std::unique_ptr<ConversionCriterion<dim>>> criteria,
                 const Parameters::Peridynamics<dim>                   &parameters_of_pd);

    /**
     * The trigger distance, the settling time (given to @p pd_zone), the loaded boundaries of
     * @p data and the criterion's automatic defaults from the material and the time step
     * @p time_step; check the criterion against the zones. New particles settle only in a
     * @p dynamic run: a static solve takes them to their PD equilibrium itself, where a
     * settling force (which fades in time) would be a load.
     */
    void
    initialize(const FEZone<dim>      &fe_zone,
               PDZone<dim>            &pd_zone,
               const ProblemData<dim> &data,
               const double            time_step,
               const bool              dynamic);

    /** Is @p name among the conversion criteria? */
    bool
    uses_criterion(const std::string &name) const;

    /**
     * Damage this near an FE cell converts it in the step it appears (set by initialize())
     * [m].
     */
    double
    trigger_distance() const;

    /** Is the criterion asked after step @p step (every Check interval steps)? */
    bool
    due(const unsigned int step) const;

    /**
     * Take the damage of the last step: the particles whose bonds broke join the running
     * damage (the lead of the next growth); returned (those of all ranks) if one of them
     * lies within the trigger distance of an FE cell, else nothing: a growth is needed now,
     * whatever the check interval (collective; costs one reduction in a step that broke no
     * bond near an FE cell).
     */
    std::vector<Point<dim>>
    take_new_damage(const FEZone<dim> &fe_zone, const PDZone<dim> &pd_zone);

    /**
     * Convert the cells the criterion flags and the FE cells within the conversion distance
     * (GrowthContext) of @p new_damage (collective). @p rebuild_coupling rebuilds what
     * depends on the zones (contact, coupling) and the accelerations of the current state.
     * Each phase is timed in @p timer (sections "growth: ...").
     * Returns the number of cells converted over all ranks (0: nothing changed).
     * A growth that would leave no FE cell is refused with an error that says so at @p time
     * [s]: a coupled run needs an FE zone to couple to.
     */
    unsigned int
    grow(FEZone<dim>                   &fe_zone,
         PDZone<dim>                   &pd_zone,
         BlendingField<dim>            &blending,
         const std::function<void()>   &rebuild_coupling,
         TimerOutput                   &timer,
         const std::vector<Point<dim>> &new_damage,
         const double                   time);

    /** The distances and speeds the growth works with (set by initialize()). */
    const GrowthContext &
    get_context() const;
    /**
     * What a user should know about these settings, one sentence each, for the start-up
     * summary (set by initialize()): cracks the criteria cannot see, a settling too short to
     * avoid an overshoot.
     */
    const std::vector<std::string> &
    get_notes() const;

    /** Cells converted since the start, over all ranks. */
    unsigned int
    n_converted_cells() const;

    /** Sum over the conversions of the change of kinetic plus strain energy each caused [J]. */
    double
    energy_change() const;

    /**
     * The running damage of all ranks (reference positions of the particles whose bonds
     * broke since the last growth), for a checkpoint (collective).
     */
    std::vector<Point<dim>>
    gather_running_damage(const MPI_Comm communicator) const;

    /**
     * The totals and the running damage of a checkpointed run, to go on from (the running
     * damage of all ranks may be given to one rank: it is gathered before use).
     */
    void
    restore(const unsigned int             converted_cells,
            const double                   energy_change,
            const std::vector<Point<dim>> &running_damage);

    /** Adaptive PD zone/Load imbalance tolerance [-]. */
    double
    imbalance_tolerance() const;

  private:
    /**
     * The cells that are FE now and flagged by a criterion, near @p new_damage or in the
     * lead (no nearer than @p band_width to the boundary), gathered from all ranks: as boxes
     * on a box mesh, as cells on a general one. On a general mesh, cells nearer to a loaded
     * face than @p band_width and the particle reach stay FE (see loaded_faces).
     */
    Region<dim>
    flagged_cells(const FEZone<dim>      &fe_zone,
                  const PDZone<dim>      &pd_zone,
                  std::vector<Point<dim>> new_damage,
                  const double            band_width) const;
    /**
     * If a cell converts (flagged and not PD yet): flag in @p convert the FE cells within the
     * lead distance of the running damage, except those nearer than @p band_width to the
     * boundary (collective).
     */
    void
    add_lead(const FEZone<dim> &fe_zone,
             const PDZone<dim> &pd_zone,
             const double       band_width,
             std::vector<bool> &convert) const;
    /**
     * Give the new pure-PD particles (those @p previous does not know) settling forces that
     * restore @p acceleration_before, the FE field's, from @p time on; their mass-weighted
     * mean is removed, so the momentum is kept.
     */
    void
    settle_new_particles(PDZone<dim>                       &pd_zone,
                         const std::vector<unsigned int>   &previous,
                         const std::vector<Tensor<1, dim>> &acceleration_before,
                         const double                       time) const;

    const Parameters::AdaptivePDZone<dim>                  parameters;
    std::vector<std::unique_ptr<ConversionCriterion<dim>>> criteria;
    /** The particles the grown zone holds: within this distance of its PD part [m]. */
    const double             particle_reach;
    GrowthContext            context;
    std::vector<std::string> notes;
    /**
     * Reference positions of the owned particles whose bonds broke since the last growth
     * (where the cracks run; pre-cracks and old crack faces are not in it), each at least
     * once: the damage whose lead the next growth gives.
     */
    std::vector<Point<dim>> running_damage;
    /** The vertices of the boundary faces of the mesh (all ranks), for the lead. */
    std::vector<Point<dim>> boundary_vertices;
    /**
     * On a general mesh, the boundary faces that carry a traction or a displacement (all
     * ranks), as their centres and half diameters: there the PD zone carries no boundary
     * condition, so its non-slave particles must stay two bond reaches away from them.
     */
    std::vector<std::pair<Point<dim>, double>> loaded_faces;
    /** The size of running_damage after its duplicates were last removed. */
    std::size_t  running_damage_compacted = 0;
    unsigned int converted_cells          = 0;
    double       conversion_energy        = 0.;
  };
} // namespace PeriArlequin

#endif
