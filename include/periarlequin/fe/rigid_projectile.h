#ifndef periarlequin_fe_rigid_projectile_h
#define periarlequin_fe_rigid_projectile_h

#include <periarlequin/fe/contact.h>
#include <periarlequin/time/integrated_zone.h>

namespace PeriArlequin
{
  /**
   * A rigid projectile that strikes the bodies of a case ("Contact/Model = rigid
   * projectile"): a sphere (a disc in 2D), a cylinder or a flat punch of a given mass,
   * position and velocity, translating (no rotation) under the contact forces. It touches
   * FE boundary nodes and PD particles (those of the pure PD part: in an Arlequin overlap
   * they are not pushed) with the kinematic scheme of the rigid wall: each point gets the
   * smallest push that keeps its next position, X + u_{n+1} + dt v_{n+1/2} + dt^2 a_{n+1},
   * outside the projectile at its own next position; a particle stands for the lattice cell
   * around it, so its centre is kept half a lattice spacing off the surface. The projectile
   * takes the opposite of every push: momentum is exchanged exactly. It is a zone of the
   * integrator (velocity Verlet with the other zones), and part of the system: its kinetic
   * energy counts in the energies, the pushes are not applied forces. Energy is lost only
   * where a point arrives (the normal part of its velocity relative to the projectile, as at
   * the wall), which vanishes with the mesh and the lattice; a body in contact stays in
   * contact without loss. Each rank holds the projectile; its force is summed over the
   * ranks once a step.
   */
  template <int dim>
  class RigidProjectile
    : public Contact<dim>
    , public IntegratedZone
  {
  public:
    enum class Shape
    {
      sphere,
      cylinder,
      flat_punch
    };

    /** The defaults of the entries: a sphere, a cylinder along z, a punch of 10 mm sides. */
    RigidProjectile();

    /** The entries of subsection "Contact/rigid projectile", declared and parsed. */
    void
    entries(ParameterEntries &entries);
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm) override;

    // Contact with FE boundary nodes.
    void
    initialize(const FEZone<dim> &zone) override;
    void
    enforce(const double                             time_step,
            const typename Contact<dim>::VectorType &mass,
            const typename Contact<dim>::VectorType &displacement,
            const typename Contact<dim>::VectorType &velocity,
            typename Contact<dim>::VectorType       &acceleration,
            typename Contact<dim>::VectorType       &applied_force) override;

    /**
     * The force on the bodies and the points (nodes and particles) in contact, over all
     * ranks, as the last compute_accelerations() summed them.
     */
    Tensor<1, dim>
    total_force() const override;
    unsigned int
    n_touching_nodes() const override;

    // Contact with PD particles.
    bool
    acts_on_particles() const override;
    void
    check_particles(const MPI_Comm                 communicator,
                    const double                   radius,
                    const std::vector<Point<dim>> &positions) override;
    void
    push_particles(const double                   time_step,
                   const double                   radius,
                   const std::vector<Point<dim>> &next_position,
                   const std::vector<double>     &mass,
                   std::vector<Tensor<1, dim>>   &push) override;
    BoundingBox<dim>
    reach(const double time_step, const double radius) const override;

    /** Refuse a speed that crosses the projectile's smallest size in a step. */
    void
    check_time_step(const double time_step) const override;

    double
    obstacle_kinetic_energy() const override;
    /**
     * Position and velocity of the centre, the kinetic energy, and the contact radius: the
     * root mean square distance of the contact forces from the line of the total force
     * through the centre, weighted by their magnitudes [m] (for a Hertz contact a / 2 under
     * a cylinder, a sqrt(2/5) under a sphere: a measure of the contact patch that does not
     * depend on which points at its edge touch).
     */
    std::vector<std::pair<std::string, double>>
    history_columns() const override;
    std::string
    save_state() const override;
    void
    load_state(const std::string &state) override;

    // The projectile's motion, as a zone of the integrator.
    std::string
    name() const override;
    void
    predict(const double dt) override;
    void
    impose_prescribed_motion(const double time) override;
    void
    compute_forces(const double time) override;
    /**
     * a = -(force on the bodies, summed over ranks) / mass, and the contact radius
     * (collective).
     */
    void
    compute_accelerations(const double time) override;
    void
    correct(const double dt) override;
    void
    start_work_interval(const bool from_unloaded) override;
    void
    account_work() override;
    double
    kinetic_energy() const override;
    double
    strain_energy() const override;
    double
    external_work() const override;
    void
    scale_velocities(const double factor) override;
    void
    start_relaxation_step() override;
    std::pair<double, double>
    relaxation_step_sums() const override;
    std::pair<double, double>
    squared_force_norms() const override;
    void
    take_projected_residual(const double dt) override;
    double
    squared_residual_norm() const override;
    void
    update_search_direction(const double beta) override;
    void
    move_along_search_direction(const double s) override;
    void
    extrapolate_relaxation_step(const double c) override;

    /** The centre's position [m] and velocity [m/s]. */
    const Point<dim> &
    get_position() const;
    const Tensor<1, dim> &
    get_velocity() const;

    /**
     * Signed distance of the point @p y (relative to the centre) from the surface, positive
     * outside [m], and the surface's outward normal there in @p normal.
     */
    double
    signed_distance(const Tensor<1, dim> &y, Tensor<1, dim> &normal) const;

  private:
    /** The centre at the end of the next step, from the present motion. */
    Point<dim>
    next_centre(const double time_step) const;
    /**
     * The push (acceleration) that moves the point @p y (relative to the next centre) of
     * contact radius @p point_radius out of the projectile in a step of @p dt; false if it
     * is outside already.
     */
    bool
    push_out(const Tensor<1, dim> &y,
             const double          point_radius,
             const double          dt,
             Tensor<1, dim>       &push) const;
    /** Refuse a point of the bodies that starts within @p radius of the surface (inside). */
    void
    check_starts_outside(const std::vector<Point<dim>> &positions, const double radius) const;

    Shape                     shape  = Shape::sphere;
    double                    radius = 0.005, mass = 1.;
    Tensor<1, dim>            axis, half_sizes;
    std::vector<unsigned int> boundary_id_list;
    std::set<unsigned int>    boundary_ids;

    /** The motion of the centre. */
    Point<dim>     position;
    Tensor<1, dim> velocity, acceleration;
    /** Has the run moved the projectile (or resumed it)? Then no start check. */
    bool started = false;

    /** This rank's owned FE boundary nodes that may touch: DoFs (local) and position. */
    std::vector<std::pair<std::array<unsigned int, dim>, Point<dim>>> nodes;
    /**
     * What the contact exerts, for enforce() (nodes) and push_particles() (particles) on this
     * rank: the force on the bodies [N], the sum of the forces' magnitudes and their second
     * moment about the centre, sum |f| r (x) r (r: from the centre to the point) [N, N m^2].
     */
    struct Exerted
    {
      Tensor<1, dim> force;
      double         magnitude = 0;
      Tensor<2, dim> second_moment;
      unsigned int   touching = 0;

      /** Add the force @p f at @p r from the centre. */
      void
      add(const Tensor<1, dim> &f, const Tensor<1, dim> &r);
    };
    Exerted on_nodes, on_particles;
    /**
     * Over all ranks at the last step: the force on the bodies [N], the points in contact and
     * the RMS radius of the contact forces [m].
     */
    Tensor<1, dim> exerted_force;
    unsigned int   touching_points = 0;
    double         contact_radius  = 0;
  };
} // namespace PeriArlequin

#endif
