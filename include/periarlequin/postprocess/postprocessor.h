#ifndef periarlequin_postprocess_postprocessor_h
#define periarlequin_postprocess_postprocessor_h

#include <periarlequin/base/plugin_registry.h>
#include <periarlequin/fe/fe_zone.h>
#include <periarlequin/io/energy_history.h>

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <optional>

namespace PeriArlequin
{
  using namespace dealii;

  template <int dim>
  class Simulator;

  /**
   * A diagnostic of the running simulation: at every recorded step (Output/Energy interval)
   * it adds named columns to the history, written as the energy CSV. Selected by name in
   * Output/Postprocessors; each one may declare its own parameters in the subsection
   * "Postprocess/<name>".
   *
   * Users add a postprocessor by deriving from this class and registering it with
   * PERIARLEQUIN_REGISTER_POSTPROCESSOR in their own source file.
   */
  template <int dim>
  class Postprocessor
  {
  public:
    virtual ~Postprocessor() = default;

    /** Read the parameters declared by the class's static declare_parameters(). */
    virtual void
    parse_parameters(ParameterHandler &prm);

    /** Add this step's values to @p history (EnergyHistory::add_value), on every rank. */
    virtual void
    execute(const Simulator<dim> &simulator, EnergyHistory &history) = 0;

    /**
     * What the postprocessor carries from one record to the next, as bytes for a
     * checkpoint (rank 0's is kept); empty for one that carries nothing.
     */
    virtual std::string
    save_state() const;
    /** Continue from what save_state() returned in the checkpointed run (on every rank). */
    virtual void
    load_state(const std::string &state);
  };

  /** The registry of postprocessors. */
  template <int dim>
  using PostprocessorRegistry = PluginRegistry<Postprocessor<dim>>;

  extern template class PluginRegistry<Postprocessor<2>>;
  extern template class PluginRegistry<Postprocessor<3>>;

  /**
   * Energies of the whole model [J]: kinetic and strain energy, the work of loads and support
   * reactions, the total (kinetic + strain - work, conserved without dissipation), the same
   * per zone, and the broken bonds (counted from both ends). The kinetic energy includes a
   * moving obstacle's (a rigid projectile's).
   */
  template <int dim>
  class EnergyPostprocessor : public Postprocessor<dim>
  {
  public:
    void
    execute(const Simulator<dim> &simulator, EnergyHistory &history) override;
  };

  /**
   * Kinetic and strain energy [J] of the PD particles in Output/Monitor region (the pure PD
   * zone of the coupled runs): what a coupling leaves behind when a wave should have left.
   */
  template <int dim>
  class MonitorRegionEnergies : public Postprocessor<dim>
  {
  public:
    void
    execute(const Simulator<dim> &simulator, EnergyHistory &history) override;
  };

  /**
   * The coupling constraint: |g| [m], |g_dot| [m/s] and the CG iterations of the last
   * multiplier solve (zeros for an uncoupled case).
   */
  template <int dim>
  class ConstraintResiduals : public Postprocessor<dim>
  {
  public:
    void
    execute(const Simulator<dim> &simulator, EnergyHistory &history) override;
  };

  /**
   * The largest stretch of the intact bonds [-] in three parts of the PD zone: pure PD (both
   * ends with alpha = 0), overlap (an end with 0 < alpha < 1, no slave) and slave layer (an
   * end a slave). A continuum under a load of nominal strain eps has stretches up to about
   * eps (twice that right after a sudden load); a coupling that lets the overlap move on
   * its own shows there first.
   */
  template <int dim>
  class BondStretches : public Postprocessor<dim>
  {
  public:
    void
    execute(const Simulator<dim> &simulator, EnergyHistory &history) override;
  };

  /**
   * Contact (Contact/Model): the total contact force on the bodies [N], per component, and
   * the number of nodes (and particles) in contact; zeros without contact. A rigid projectile
   * adds its position [m], velocity [m/s] and kinetic energy [J].
   */
  template <int dim>
  class ContactForces : public Postprocessor<dim>
  {
  public:
    void
    execute(const Simulator<dim> &simulator, EnergyHistory &history) override;
  };

  /**
   * Contact between PD particles (Peridynamics/Particle contact): the particles touching
   * another and the contact potential [J; J/m in 2D], part of the strain energy; zeros
   * without it.
   */
  template <int dim>
  class ParticleContactHistory : public Postprocessor<dim>
  {
  public:
    void
    execute(const Simulator<dim> &simulator, EnergyHistory &history) override;
  };

  /**
   * Velocity histories at points (Postprocess/probes/Points) [m/s], per component: where an
   * FE cell holds the point (the FE zone and the overlaps), the FE field there; elsewhere
   * (the pure PD zone) the nearest PD particle, the lowest in (z, y, x) among equally near
   * ones, so that the choice does not depend on the partition. Columns `probe_<k>_v_<axis>`,
   * k from 0 in the order given. Where each point lies is found once and again only after
   * the zones change (a repartition, cells converted to PD).
   */
  template <int dim>
  class Probes : public Postprocessor<dim>
  {
  public:
    /** The entries of subsection "Postprocess/probes", declared and parsed. */
    void
    entries(ParameterEntries &entries);
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm) override;
    void
    execute(const Simulator<dim> &simulator, EnergyHistory &history) override;

  private:
    /** Find where every point lies on this rank (the FE cell, else the nearest particle). */
    void
    locate(const Simulator<dim> &simulator);

    std::string             points_text;
    std::vector<Point<dim>> points;
    /** What the locations were found for: repartitions, converted cells, FE DoFs, particles. */
    std::array<std::size_t, 4> located_for{};
    bool                       located = false;
    /** Per point: the FE location on this rank, if any, and the rank that evaluates it. */
    std::vector<std::optional<typename FEZone<dim>::PointLocation>> fe_locations;
    std::vector<unsigned int>                                       fe_owner;
    /** Per point without FE: the nearest particle (local index) on the rank that has it. */
    std::vector<unsigned int> particle;
    std::vector<unsigned int> particle_owner;
  };

  /**
   * Load and displacement of each support: for every boundary with a displacement condition
   * and every Peridynamics/Prescribed region, per prescribed component, the sum of the
   * support reactions of its FE DoFs and PD particles [N, N/m in 2D] and their mean
   * displacement [m]. Columns `reaction_<support>_<axis>` and
   * `displacement_<support>_<axis>`, support `boundary<id>` or `region<r>`: the
   * load-displacement curve of a test specimen held or driven by a grip.
   */
  template <int dim>
  class SupportReactions : public Postprocessor<dim>
  {
  public:
    void
    execute(const Simulator<dim> &simulator, EnergyHistory &history) override;

  private:
    /** The recorded (support x dim + component)s: those prescribed at the first row. */
    std::vector<unsigned int> columns;
  };

  /** Linear momentum of both zones [N s], per component (lumped FE masses, PD particles). */
  template <int dim>
  class LinearMomentum : public Postprocessor<dim>
  {
  public:
    void
    execute(const Simulator<dim> &simulator, EnergyHistory &history) override;
  };

  /**
   * Size of the zones (an adaptive PD zone grows): PD particles, FE DoFs, cells converted to
   * PD so far and the energy change the conversions caused [J]. At the output steps it
   * writes the pure PD region as `<base>_pd_region_<step>.csv` (one box per line, lower and
   * upper corner), which scripts/plot_zone.sh draws.
   */
  template <int dim>
  class ZoneSizes : public Postprocessor<dim>
  {
  public:
    void
    execute(const Simulator<dim> &simulator, EnergyHistory &history) override;
  };
} // namespace PeriArlequin

/**
 * Register a postprocessor class template (instantiated for dim = 2 and 3, default
 * constructed; with its static declare_parameters(ParameterHandler &) if it has one) under
 * @p name.
 */
#define PERIARLEQUIN_REGISTER_POSTPROCESSOR(classname, name, description)                          \
  namespace                                                                                        \
  {                                                                                                \
    const bool periarlequin_registered_postprocessor_##classname =                                 \
      PeriArlequin::register_plugin_template<PeriArlequin::Postprocessor, classname>(name,         \
                                                                                     description); \
  }

#endif
