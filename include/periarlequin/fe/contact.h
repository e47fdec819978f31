#ifndef periarlequin_fe_contact_h
#define periarlequin_fe_contact_h

#include <periarlequin/base/parameters.h>
#include <periarlequin/base/plugin_registry.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <array>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  template <int dim>
  class FEZone;

  /**
   * Contact of the FE zone's boundary (and, for models that say so, of PD particles) with an
   * obstacle, inside the explicit step: selected by name in "Contact/Model" (none by
   * default); a model's own parameters live in "Contact/<name>". The FE zone calls enforce()
   * once its trial accelerations of a step are known, the PD zone push_particles(). A fixed
   * obstacle's contact force counts as an applied force, so its work enters the energy
   * balance; a moving obstacle is part of the system (its kinetic energy counts instead).
   * The nodes that touch must not lie in an Arlequin overlap (the multiplier correction that
   * follows would move them again); particles in an overlap are not pushed.
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
     * Does the model act on PD particles too (push_particles())? The models of FE boundary
     * nodes only do not, and need an FE zone.
     */
    virtual bool
    acts_on_particles() const;

    /** Does the model need PD particles (contact between particles and FE faces)? No by default. */
    virtual bool
    needs_particles() const;

    /**
     * Before the first step: refuse particles that start inside the obstacle, given the
     * current positions of the owned particles that may touch it and their contact radius
     * @p radius [m] (collective over @p communicator; the PD zone's). Only for models that
     * act on particles.
     */
    virtual void
    check_particles(const MPI_Comm                 communicator,
                    const double                   radius,
                    const std::vector<Point<dim>> &positions);

    /**
     * Kinematic contact of PD particles, called by the PD zone once their trial accelerations
     * are known: given the particles' positions @p next_position if nothing pushed them,
     * X + u_{n+1} + dt v_{n+1/2} + dt^2 a_{n+1}, their masses and contact radius @p radius,
     * set @p push to the acceleration each needs to end the next step outside the obstacle
     * (zero where it does not touch). Only for models that act on particles.
     */
    virtual void
    push_particles(const double                   time_step,
                   const double                   radius,
                   const std::vector<Point<dim>> &next_position,
                   const std::vector<double>     &mass,
                   std::vector<Tensor<1, dim>>   &push);

    /**
     * A box outside which no particle of contact radius @p radius can touch the obstacle at
     * the end of the next step of @p time_step (the PD zone's broad phase); by default everything.
     */
    virtual BoundingBox<dim>
    reach(const double time_step, const double radius) const;

    /** Refuse a time step the model cannot work with (at set-up); by default any. */
    virtual void
    check_time_step(const double time_step) const;

    /** The obstacle's own kinetic energy [J; J/m in 2D], the same on every rank (0: fixed). */
    virtual double
    obstacle_kinetic_energy() const;

    /**
     * Columns the model adds to the history besides force and touching count (a moving
     * obstacle's position and velocity), the same on every rank; none by default.
     */
    virtual std::vector<std::pair<std::string, double>>
    history_columns() const;

    /** The model's own state for a checkpoint (a moving obstacle's motion); none by default. */
    virtual std::string
    save_state() const;
    /** Restore what save_state() wrote. */
    virtual void
    load_state(const std::string &state);

    /**
     * The total contact force on the body at the last enforce() [N], summed over ranks
     * (collective: call it on every rank; the time loop itself needs no sum). By default the
     * sum of local_force.
     */
    virtual Tensor<1, dim>
    total_force() const;

    /**
     * The number of nodes in contact at the last enforce(), summed over ranks (collective).
     * By default the sum of local_touching.
     */
    virtual unsigned int
    n_touching_nodes() const;

  protected:
    /** The FE zone's communicator, set by initialize(). */
    MPI_Comm communicator = MPI_COMM_SELF;
    /** This rank's share of the contact force and of the touching nodes at the last enforce(). */
    Tensor<1, dim> local_force;
    unsigned int   local_touching = 0;
  };

  /** The registry of contact models. */
  template <int dim>
  using ContactRegistry = PluginRegistry<Contact<dim>>;

  extern template class PluginRegistry<Contact<2>>;
  extern template class PluginRegistry<Contact<3>>;

  /** A vertex of the FE boundary: its DoFs (global indices, one per component) and position. */
  template <int dim>
  struct BoundaryVertex
  {
    std::array<types::global_dof_index, dim> dofs;
    Point<dim>                               position;
  };

  /**
   * The vertices of the faces with boundary id in @p boundary_ids (all if empty) of the
   * locally owned cells that carry FE DoFs, by their first DoF; refuses ids the mesh does not
   * have, naming @p parameter, and elements other than FE_Q(1)^dim (contact needs lumped
   * vertex masses). A vertex on a face between two ranks' cells is found on both.
   */
  template <int dim>
  std::map<types::global_dof_index, BoundaryVertex<dim>>
  boundary_vertices(const FEZone<dim>            &zone,
                    const std::set<unsigned int> &boundary_ids,
                    const std::string            &parameter);

  /** A face of the FE boundary: its vertices, in deal.II's order, and a direction out of its cell.
   */
  template <int dim>
  struct BoundaryFace
  {
    std::vector<BoundaryVertex<dim>> vertices;
    Tensor<1, dim>                   outward;
  };

  /**
   * The faces with boundary id in @p boundary_ids (all if empty) of the FE cells of every
   * rank, gathered on all ranks in rank order; refuses ids the mesh does not have and
   * elements other than FE_Q(1)^dim as boundary_vertices() does.
   */
  template <int dim>
  std::vector<BoundaryFace<dim>>
  all_boundary_faces(const FEZone<dim>            &zone,
                     const std::set<unsigned int> &boundary_ids,
                     const std::string            &parameter);

  /**
   * Boundary vertices whose values a contact model gathers on every rank each step (the
   * models that solve their pairs on every rank alike): sorted by position, the same list
   * on every rank whatever the partition, with the local DoFs of those this rank owns and
   * every rank's owned list, in the order of the gathered values.
   */
  template <int dim>
  class GatheredBoundaryNodes
  {
  protected:
    /**
     * Take @p vertices (each once) as the nodes, sorted, and find which this rank owns in
     * @p zone (collective).
     */
    void
    set_nodes(std::vector<BoundaryVertex<dim>> vertices, const FEZone<dim> &zone);

    /** The index of the node whose first DoF is @p first_dof. */
    unsigned int
    node_index(const types::global_dof_index first_dof) const;

    /**
     * The values of the owned nodes, @p width a node in the order of owned_nodes (@p mine),
     * gathered on all ranks into node order (collective; plain MPI).
     */
    std::vector<double>
    gather_node_values(const std::vector<double> &mine, const unsigned int width) const;

    std::vector<BoundaryVertex<dim>> nodes;
    /** The nodes whose DoFs this rank owns, with their local indices; every rank's list. */
    std::vector<unsigned int>                  owned_nodes;
    std::vector<std::array<unsigned int, dim>> owned_dofs;
    std::vector<std::vector<unsigned int>>     nodes_of_rank;

  private:
    std::map<types::global_dof_index, unsigned int> node_of;
    MPI_Comm                                        node_communicator = MPI_COMM_SELF;
  };

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
    /** The entries of subsection "Contact/<name>", declared and parsed. */
    void
    entries(ParameterEntries &entries);
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm) override;
    void
    initialize(const FEZone<dim> &zone) override;
    void
    enforce(const double                             time_step,
            const typename Contact<dim>::VectorType &mass,
            const typename Contact<dim>::VectorType &displacement,
            const typename Contact<dim>::VectorType &velocity,
            typename Contact<dim>::VectorType       &acceleration,
            typename Contact<dim>::VectorType       &applied_force) override;

  private:
    /** A boundary node that may touch: its DoFs (owned, local indices) and position. */
    struct Node
    {
      std::array<unsigned int, dim> dofs;
      Point<dim>                    position;
    };

    /** The entries as given (Point and Normal kept as text for messages). */
    std::string               point_text  = dim == 2 ? "0, 0" : "0, 0, 0";
    std::string               normal_text = dim == 2 ? "-1, 0" : "-1, 0, 0";
    std::vector<unsigned int> boundary_id_list;
    Point<dim>                wall_point;
    Tensor<1, dim>            normal;
    std::set<unsigned int>    boundary_ids;
    std::vector<Node>         nodes;
  };

  /**
   * Frictionless unilateral contact between two FE bodies of the same mesh, a striker and a
   * target (boundary ids of each), enforced kinematically like the rigid wall but between
   * nodes and faces: each vertex s of the striker's contact boundary is paired, once, with
   * the target face that it projects onto in the reference configuration (small sliding, as
   * the linear elastic bodies of the FE zone are), at the point with face shape values N_j,
   * along that face's outward normal n. The gap of the next positions, g = n . (x_s -
   * sum_j N_j x_j) with x = X + u_{n+1} + dt v_{n+1/2} + dt^2 a_{n+1}, must not be negative:
   * pair k gets the force lambda_k >= 0, on s along n and on the face's nodes along -n with
   * the weights N_j, the smallest that closes the gap, lambda_k = -g / (dt^2 (1/m_s + sum_j
   * N_j^2 / m_j)). Pairs that share target nodes are solved together by Gauss-Seidel sweeps
   * (one sweep where the meshes match node to node). Momentum is conserved exactly (the
   * forces on the two bodies cancel, sum_j N_j = 1); energy is lost only as the relative
   * normal kinetic energy of the nodes that meet (m_s m_j / (m_s + m_j) per pair and impact),
   * which the contact work records. The bodies separate when they pull apart.
   *
   * The nodes and faces involved are few (a contact surface): their state is gathered on
   * every rank each step and every rank solves the same pairs in the same order (sorted by
   * position), so the contact forces do not depend on the partition.
   */
  template <int dim>
  class ElasticTargetContact
    : public Contact<dim>
    , private GatheredBoundaryNodes<dim>
  {
  public:
    /** The entries of subsection "Contact/<name>", declared and parsed. */
    void
    entries(ParameterEntries &entries);
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm) override;
    void
    initialize(const FEZone<dim> &zone) override;
    void
    enforce(const double                             time_step,
            const typename Contact<dim>::VectorType &mass,
            const typename Contact<dim>::VectorType &displacement,
            const typename Contact<dim>::VectorType &velocity,
            typename Contact<dim>::VectorType       &acceleration,
            typename Contact<dim>::VectorType       &applied_force) override;

  private:
    /** A striker vertex and the target face it projects onto. */
    struct Pair
    {
      unsigned int              striker;
      std::vector<unsigned int> face_nodes;
      std::vector<double>       weights;
      Tensor<1, dim>            normal;
    };

    /**
     * Fill @p state with u, v, a and the mass of every involved node (3 dim + 1 numbers a
     * node, in node order) from the owned entries of every rank.
     */
    void
    gather_state(const typename Contact<dim>::VectorType &mass,
                 const typename Contact<dim>::VectorType &displacement,
                 const typename Contact<dim>::VectorType &velocity,
                 const typename Contact<dim>::VectorType &acceleration,
                 std::vector<double>                     &state) const;

    /**
     * The nodes' positions X + u + dt v + dt^2 a from the gathered @p state (dt = 0: the
     * current ones).
     */
    std::vector<Point<dim>>
    positions(const std::vector<double> &state, const double dt) const;

    /** The gap n . (x_s - sum_j N_j x_j) of @p pair at the node positions @p x [m]. */
    double
    pair_gap(const Pair &pair, const std::vector<Point<dim>> &x) const;

    /** The entries as given, and as sets. */
    std::vector<unsigned int> striker_id_list, target_id_list;
    std::set<unsigned int>    striker_ids, target_ids;
    /** The involved vertices: striker and target. */
    using GatheredBoundaryNodes<dim>::nodes;
    using GatheredBoundaryNodes<dim>::owned_nodes;
    using GatheredBoundaryNodes<dim>::owned_dofs;
    std::vector<Pair> pairs;
    /** Striker nodes this rank owns (a pair's force counts where its striker node lives). */
    std::vector<bool> striker_owned_here;
    /** The smallest target face diameter [m]: the scale of the gap tolerances. */
    double face_size = 0;
  };
} // namespace PeriArlequin

/**
 * Register a contact model class template (instantiated for dim = 2 and 3, default
 * constructed; with its static declare_parameters(ParameterHandler &) if it has one) under
 * @p name.
 */
#define PERIARLEQUIN_REGISTER_CONTACT(classname, name, description)                                \
  namespace                                                                                        \
  {                                                                                                \
    const bool periarlequin_registered_contact_##classname =                                       \
      PeriArlequin::register_plugin_template<PeriArlequin::Contact, classname>(name, description); \
  }

#endif
