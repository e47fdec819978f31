#ifndef periarlequin_coupling_coupling_h
#define periarlequin_coupling_coupling_h

#include <periarlequin/base/plugin_registry.h>
#include <periarlequin/coupling/blending_field.h>
#include <periarlequin/fe/fe_zone.h>
#include <periarlequin/pd/pd_zone.h>

#include <deal.II/base/types.h>

#include <memory>
#include <utility>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * How the PD zone and the FE zone are glued across the overlap: the interface that
   * PredictorCorrector calls between the parts of a step. An implementation is created by
   * name (Coupling/Method) from the coupling parameters when the case is read; it says which
   * blending profile it needs before the zones exist, and is initialised once they do.
   *
   * Users add a coupling by deriving from this class and registering it with
   * PERIARLEQUIN_REGISTER_COUPLING in their own source file; its own parameters (declared by
   * its static declare_parameters()) live in "Coupling/<name>".
   */
  template <int dim>
  class Coupling
  {
  public:
    virtual ~Coupling() = default;

    /** Read the parameters declared by the class's static declare_parameters(). */
    virtual void
    parse_parameters(ParameterHandler &prm);

    /**
     * The shape of alpha across the overlap. With a linear profile the FE mass and
     * stiffness are weighted with alpha; with a step (alpha 0 or 1) both zones keep their
     * full mass and stiffness where they live.
     */
    virtual BlendingProfile
    blending_profile() const = 0;

    /**
     * Build the operators once both zones are set up (after FEZone::initialize_state() and
     * PDZone::setup()); may set the FE zone's nodal force weights. Called again, from scratch,
     * after an adaptive PD zone grew (FEZone::restrict_to(), PDZone::extend()).
     */
    virtual void
    initialize(const BlendingField<dim> &blending,
               FEZone<dim>              &fe_zone,
               PDZone<dim>              &pd_zone,
               const double              time_step) = 0;

    /** Slaves follow their masters' displacements (after the predictor). */
    virtual void
    set_slave_displacements() = 0;
    /**
     * Eq. 58-59: between the zones' forces and their accelerations at @p time, the forces
     * and loads of the slaves act on the nodes they follow (N^T f on the FE nodes).
     */
    virtual void
    add_interface_forces(const double time) = 0;

    /** Eq. 76-79: damp the fine-scale motion (after the trial accelerations). */
    virtual void
    apply_damping() = 0;

    /**
     * The stable step of the coupled zones given their undamped one @p undamped_step: lower
     * where the coupling's damping is explicit.
     */
    virtual double
    stable_time_step(const double undamped_step) const
    {
      return undamped_step;
    }

    /** Eq. 62-69: make d/dt g vanish at the new time (after the trial velocities). */
    virtual void
    enforce_constraint() = 0;

    /** Slaves follow their masters' velocities and accelerations (end of a step). */
    virtual void
    set_slave_velocities() = 0;

    /** |g| [m] and |g_dot| [m/s] of the constraint (l2 over all rows); 0 without one. */
    virtual std::pair<double, double>
    constraint_residuals() const = 0;

    /** Number of multipliers (over all ranks and components). */
    virtual types::global_dof_index
    n_multipliers() const = 0;

    /** Overlap PD nodes and slave particles over all ranks. */
    virtual std::pair<types::global_dof_index, types::global_dof_index>
    n_coupled_particles() const = 0;

    /** Iterations of the last multiplier solve (0 for a direct or diagonal one). */
    virtual unsigned int
    last_solver_iterations() const = 0;

    /**
     * Why a static solve by conjugate gradients cannot run with this coupling (it needs
     * forces that derive from an energy and a constraint it can project on exactly), or
     * empty if it can.
     */
    virtual std::string
    conjugate_gradient_obstacle() const
    {
      return "the coupling's forces do not derive from an energy";
    }
    /** Solve the multipliers exactly while @p exact (a static solve by conjugate gradients). */
    virtual void
    solve_multipliers_exactly(const bool /*exact*/)
    {}
  };

  template <int dim>
  class SlaveLayer;

  /**
   * Force blending: the FE internal force is weighted per node with alpha_I (the FE zone's
   * nodal force weights). Shared by the couplings; nothing under the other blendings.
   */
  template <int dim>
  void
  set_fe_force_weights(const Parameters::Coupling &parameters,
                       const BlendingField<dim>   &blending,
                       FEZone<dim>                &fe_zone);

  /**
   * The FE side of add_interface_forces(): the slaves' loads add to the FE applied forces
   * (under any blending), their PD forces N^T f to the FE interface forces (energy blending).
   * Shared by the couplings.
   */
  template <int dim>
  void
  add_slave_forces(const Parameters::Coupling &parameters,
                   SlaveLayer<dim>            &slaves,
                   const double                time,
                   FEZone<dim>                &fe_zone);

  /** The registry of couplings: a coupling is created from the coupling parameters. */
  template <int dim>
  using CouplingRegistry = PluginRegistry<Coupling<dim>, const Parameters::Coupling &>;

  extern template class PluginRegistry<Coupling<2>, const Parameters::Coupling &>;
  extern template class PluginRegistry<Coupling<3>, const Parameters::Coupling &>;
} // namespace PeriArlequin

/**
 * Register a coupling class template (instantiated for dim = 2 and 3, constructed from the
 * Parameters::Coupling; with its static declare_parameters(ParameterHandler &) if it has one)
 * under @p name,
 * e.g. PERIARLEQUIN_REGISTER_COUPLING(MyCoupling, "mine", "what it does").
 */
#define PERIARLEQUIN_REGISTER_COUPLING(classname, name, description)                      \
  namespace                                                                               \
  {                                                                                       \
    const bool periarlequin_registered_coupling_##classname =                             \
      PeriArlequin::register_plugin_template<PeriArlequin::Coupling,                      \
                                             classname,                                   \
                                             const PeriArlequin::Parameters::Coupling &>( \
        name,                                                                             \
        description);                                                                     \
  }

#endif
