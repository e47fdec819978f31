#ifndef periarlequin_fe_particle_face_contact_h
#define periarlequin_fe_particle_face_contact_h

#include <periarlequin/fe/contact.h>
#include <periarlequin/fe/contact_checks.h>

#include <array>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace PeriArlequin
{
  /**
   * Frictionless unilateral contact between the particles of the PD zone and boundary faces
   * of the FE cells of the same mesh (an FE striker against a PD target, PD fragments against
   * an FE support), enforced kinematically as between the two bodies of the elastic-target
   * contact, with a particle in place of a striker vertex. Every step each particle of the
   * pure PD part (alpha = 0, not a slave, not prescribed) near a selected face is paired with
   * the face it lies in front of at the next positions x = X + u_{n+1} + dt v_{n+1/2} + dt^2
   * a_{n+1} (the nearest if several), at the foot with face shape values N_j and along the
   * face's outward unit normal n there. The particle stands for its lattice cell: the gap
   * g = n . (x_p - sum_j N_j x_j) - dx/2 must not be negative. The pair takes the smallest
   * lambda >= 0 that closes it, on the particle along n and on the face's nodes along -n with
   * the weights N_j, lambda = -g / (dt^2 (1/m_p + sum_j N_j^2 / m_j)); pairs that share nodes
   * are solved together by Gauss-Seidel sweeps. A prescribed FE component does not move (its
   * support takes the force, which enters its reaction). The forces cancel in pairs
   * (momentum is exchanged exactly) and are internal: the relative normal kinetic energy of
   * each meeting pair leaves the total energy, which vanishes with the lattice and the mesh.
   *
   * The FE zone steps before the PD zone: enforce() notes the FE zone's vectors, and
   * push_particles(), which the PD zone calls once the FE accelerations are complete, moves
   * both sides. The faces' nodes and the pairs are few: gathered on every rank, which all
   * solve the same pairs in the same order (by position), so the forces do not depend on the
   * partition.
   */
  template <int dim>
  class ParticleFaceContact
    : public Contact<dim>
    , private GatheredBoundaryNodes<dim>
  {
  public:
    /** The entries of subsection "Contact/PD against FE", declared and parsed. */
    void
    entries(ParameterEntries &entries);
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm) override;

    /** Find the faces that particles may touch, and their nodes. */
    void
    initialize(const FEZone<dim> &zone) override;
    /** Note the FE zone's vectors; the contact itself is resolved in push_particles(). */
    void
    enforce(const double                             time_step,
            const typename Contact<dim>::VectorType &mass,
            const typename Contact<dim>::VectorType &displacement,
            const typename Contact<dim>::VectorType &velocity,
            typename Contact<dim>::VectorType       &acceleration,
            typename Contact<dim>::VectorType       &applied_force) override;

    bool
    acts_on_particles() const override;
    bool
    needs_particles() const override;
    /** Refuse particles that start within their radius of a face (or behind it). */
    void
    check_particles(const MPI_Comm                 communicator,
                    const double                   radius,
                    const std::vector<Point<dim>> &positions) override;
    /**
     * Pair the particles with the faces, solve the pairs, and move the particles (@p push) and
     * the FE nodes (the accelerations noted by enforce()). Collective.
     */
    void
    push_particles(const double                   time_step,
                   const double                   radius,
                   const std::vector<Point<dim>> &next_position,
                   const std::vector<double>     &mass,
                   std::vector<Tensor<1, dim>>   &push) override;
    /** The faces' box at the last step, widened by two radii and the nodes' travel. */
    BoundingBox<dim>
    reach(const double time_step, const double radius) const override;

  private:
    /** A face: its nodes (indices into nodes) and the direction out of its cell. */
    struct Face
    {
      std::array<unsigned int, GeometryInfo<dim>::vertices_per_face> nodes;
      Tensor<1, dim>                                                 outward;
    };

    /** A particle in front of a face: the face, and the foot on it. */
    struct NearestFace : internal::FaceFoot<dim>
    {
      unsigned int face = numbers::invalid_unsigned_int;
    };

    /**
     * The face that @p x lies in front of, of those binned near it, at the node positions @p
     * x_nodes: the nearest whose distance lies in (-half the smallest face, @p within];
     * face = invalid if none.
     */
    NearestFace
    nearest_face(const Point<dim>              &x,
                 const std::vector<Point<dim>> &x_nodes,
                 const double                   within) const;

    /**
     * Bin the faces at the node positions @p x_nodes, each where it lies within @p within and
     * a skin, unless the bins of an earlier call still hold them.
     */
    void
    bin_faces(const std::vector<Point<dim>> &x_nodes, const double within);

    /** The bin of @p x. */
    std::array<long long, dim>
    bin_of(const Point<dim> &x) const;

    /**
     * Gather u, v, a and the inverse mass of each component (0 where prescribed) of every
     * node (4 dim numbers a node, in node order) from the owned entries of every rank.
     */
    std::vector<double>
    gather_state(const typename Contact<dim>::VectorType &mass,
                 const typename Contact<dim>::VectorType &displacement,
                 const typename Contact<dim>::VectorType &velocity,
                 const typename Contact<dim>::VectorType &acceleration) const;

    std::vector<unsigned int> boundary_id_list;
    std::set<unsigned int>    boundary_ids;

    /** The faces' vertices, and the faces. */
    using GatheredBoundaryNodes<dim>::nodes;
    using GatheredBoundaryNodes<dim>::owned_nodes;
    using GatheredBoundaryNodes<dim>::owned_dofs;
    std::vector<Face> faces;
    /** Per owned node and component: prescribed? */
    std::vector<std::array<bool, dim>> owned_prescribed;
    /** The smallest and the largest face size (an edge; its diameter) [m]. */
    double smallest_face = 0, largest_face = 0;
    /** The nodes' positions X + u at set-up or the last step (the broad phase's box). */
    std::vector<Point<dim>> node_position;
    /** The largest distance of a node's next position from its position at the last step [m]. */
    double node_travel = 0;

    /** The faces in bins of edge bin_size (those within reach of the bin's points). */
    double                                                          bin_size = 0;
    std::map<std::array<long long, dim>, std::vector<unsigned int>> bins;
    /** The node positions and the reach the bins were made for. */
    std::vector<Point<dim>> binned_position;
    double                  binned_within = 0;

    /** The FE zone's vectors of the step, noted by enforce(). */
    const typename Contact<dim>::VectorType *fe_mass         = nullptr;
    const typename Contact<dim>::VectorType *fe_displacement = nullptr;
    const typename Contact<dim>::VectorType *fe_velocity     = nullptr;
    typename Contact<dim>::VectorType       *fe_acceleration = nullptr;
    typename Contact<dim>::VectorType       *fe_applied      = nullptr;
  };
} // namespace PeriArlequin

#endif
