#ifndef periarlequin_fe_contact_h
#define periarlequin_fe_contact_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <periarlequin/base/plugin_registry.h>

#include <array>
#include <set>
#include <string>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  template <int dim>
  class FEZone;

  /**
   * Contact of the FE zone's boundary with an obstacle, inside the explicit step: selected by
   * name in "Contact/Model" (none by default); a model's own parameters live in
   * "Contact/<name>". The FE zone calls enforce() once its trial accelerations of a step are
   * known; the contact force counts as an applied force, so its work enters the energy
   * balance. The nodes that touch must not lie in an Arlequin overlap (the multiplier
   * correction that follows would move them again).
   *
   * Users add a model by deriving from this class and registering it with
   * PERIARLEQUIN_REGISTER_CONTACT in their own source file.
   */
  template <int dim>
  class Contact
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    virtual ~Contact() = default;

    /** Read the parameters declared by the class's static declare_parameters(). */
    virtual void
    parse_parameters(ParameterHandler &prm);

    /** Find the nodes that may touch; called once the zone's initial state is set. */
    virtual void
    initialize(const FEZone<dim> &zone) = 0;

    /**
     * Given the nodal @p mass, the displacements u_{n+1}, the half-step velocities
     * v_{n+1/2} and the trial accelerations a_{n+1} of the owned DoFs, add the contact
     * accelerations to @p acceleration and the contact forces to @p applied_force.
     */
    virtual void
    enforce(const double      time_step,
            const VectorType &mass,
            const VectorType &displacement,
            const VectorType &velocity,
            VectorType       &acceleration,
            VectorType       &applied_force) = 0;

    /**
     * The total contact force on the body at the last enforce() [N], summed over ranks
     * (collective: call it on every rank; the time loop itself needs no sum).
     */
    virtual Tensor<1, dim>
    total_force() const = 0;

    /** The number of nodes in contact at the last enforce(), summed over ranks (collective). */
    virtual unsigned int
    n_touching_nodes() const = 0;
  };

  /** The registry of contact models. */
  template <int dim>
  using ContactRegistry = PluginRegistry<Contact<dim>>;

  extern template class PluginRegistry<Contact<2>>;
  extern template class PluginRegistry<Contact<3>>;

  /**
   * Frictionless unilateral contact with a fixed rigid plane, enforced kinematically as
   * explicit codes do (a forward-increment Lagrange multiplier): with lumped masses each node
   * is its own constraint, and the contact force of step n+1 is the smallest push along the
   * plane's normal n that keeps the node's next position x_{n+2} = X + u_{n+1} +
   * dt v_{n+1/2} + dt^2 a_{n+1} on the allowed side: a += max(0, -g) / dt^2 n, with
   * g = (x_{n+2} - P) . n. It only pushes, so the body separates when it pulls away. A node
   * that arrives stops in the plane within a step: its normal kinetic energy is dissipated,
   * m v^2 / 2 per node and impact, which vanishes with the mesh size against the body's
   * energy. Momentum goes to the wall through the contact force.
   */
  template <int dim>
  class RigidWallContact : public Contact<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm) override;
    void
    initialize(const FEZone<dim> &zone) override;
    void
    enforce(const double                         time_step,
            const typename Contact<dim>::VectorType &mass,
            const typename Contact<dim>::VectorType &displacement,
            const typename Contact<dim>::VectorType &velocity,
            typename Contact<dim>::VectorType       &acceleration,
            typename Contact<dim>::VectorType       &applied_force) override;
    Tensor<1, dim>
    total_force() const override;
    unsigned int
    n_touching_nodes() const override;

  private:
    /** A boundary node that may touch: its DoFs (owned, local indices) and position. */
    struct Node
    {
      std::array<unsigned int, dim> dofs;
      Point<dim>                    position;
    };

    std::string             point_text;
    Point<dim>              wall_point;
    Tensor<1, dim>          normal;
    std::set<unsigned int>  boundary_ids;
    std::vector<Node>       nodes;
    MPI_Comm                communicator;
    /** This rank's contact force and touching nodes at the last enforce(). */
    Tensor<1, dim>          local_force;
    unsigned int            local_touching = 0;
  };
} // namespace PeriArlequin

/**
 * Register a contact model class template (instantiated for dim = 2 and 3, default
 * constructed; with its static declare_parameters(ParameterHandler &) if it has one) under
 * @p name.
 */
#define PERIARLEQUIN_REGISTER_CONTACT(classname, name, description)                          \
  namespace                                                                                  \
  {                                                                                          \
    const bool periarlequin_registered_contact_##classname =                                 \
      PeriArlequin::register_plugin_template<PeriArlequin::Contact, classname>(name,         \
                                                                               description); \
  }

#endif
