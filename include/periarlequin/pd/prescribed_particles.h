#ifndef periarlequin_pd_prescribed_particles_h
#define periarlequin_pd_prescribed_particles_h

#include <periarlequin/base/separable_field.h>
#include <periarlequin/pd/particle_state.h>
#include <periarlequin/pd/pd_parameters.h>

#include <deal.II/base/function.h>

#include <array>
#include <cstdint>
#include <vector>

namespace PeriArlequin
{
  /**
   * The owned particles whose prescribed components follow a function of position and time
   * (displacement or velocity) instead of the equation of motion: those in the regions of
   * Peridynamics/Prescribed region N, and those in the boundary layer of a face with a
   * displacement condition (add()). The velocity and acceleration of a
   * prescribed component come from central differences of the function over one time step,
   * so that Verlet reproduces the motion.
   */
  template <int dim>
  class PrescribedParticles
  {
  public:
    explicit PrescribedParticles(const Parameters::Peridynamics<dim> &parameters);

    /** Collect the owned particles (the first @p n_owned of @p positions) in the regions. */
    void
    reinit(ArrayView<const Point<dim>> positions, const unsigned int n_owned);

    /**
     * Prescribe the displacement @p function on the @p components of owned particle @p i
     * (a particle of the boundary layer of face @p boundary_id), unless a region already
     * prescribes it.
     */
    void
    add(const unsigned int           i,
        const Point<dim>            &position,
        Function<dim>               &function,
        const std::array<bool, dim> &components,
        const unsigned int           boundary_id);

    /** Does a prescribed region or boundary layer hold owned particle @p i? */
    bool
    contains(const unsigned int i) const;
    /** Is component @p d of owned particle @p i prescribed? */
    bool
    prescribes(const unsigned int i, const unsigned int d) const
    {
      return (held_components[i] >> d) & 1u;
    }

    /** Does no rank hold a prescribed particle? (collective) */
    bool
    empty(const MPI_Comm communicator) const;

    /**
     * Evaluate the motion at @p time: a prescribed displacement is set in @p state; the
     * velocity and acceleration of every prescribed component are stored and written.
     */
    void
    impose(const double time, const double dt, ParticleState<dim> &state);

    /** Write the stored velocities of the prescribed components again. */
    void
    restore_velocities(ParticleState<dim> &state) const;
    /** Write the stored accelerations of the prescribed components again. */
    void
    restore_accelerations(ParticleState<dim> &state) const;

    /** Call @p visit(i, d) for every prescribed component d of owned particle i. */
    template <typename Visitor>
    void
    for_each_component(const Visitor &visit) const
    {
      for_each_support_component(
        [&](const unsigned int i, const unsigned int d, const unsigned int) { visit(i, d); });
    }

    /**
     * Call @p visit(i, d, support) for every prescribed component d of owned particle i,
     * with the support that prescribes it: a boundary layer's boundary id, or 2 dim + r for
     * Peridynamics/Prescribed region r (after the boundary ids of the box).
     */
    template <typename Visitor>
    void
    for_each_support_component(const Visitor &visit) const
    {
      for (const auto &p : particles)
        for (unsigned int d = 0; d < dim; ++d)
          if (p.components[d])
            visit(p.local_index, d, p.support);
    }

  private:
    struct Particle
    {
      unsigned int          local_index;
      Function<dim>        *function;
      std::array<bool, dim> components;
      bool                  prescribes_velocity;
      Point<dim>            position;
      /** Prescribed velocity and acceleration at the current time (prescribed components). */
      Tensor<1, dim> velocity, acceleration;
      /** See for_each_support_component(). */
      unsigned int support;
      /** The function as a SeparableField (or nullptr), and its spatial field here. */
      const SeparableField<dim> *separable;
      Tensor<1, dim>             spatial_field;
    };

    /** A prescribed particle, with the spatial field of a separable function. */
    static Particle
    make_particle(const unsigned int           local_index,
                  Function<dim>               *function,
                  const std::array<bool, dim> &components,
                  const bool                   prescribes_velocity,
                  const Point<dim>            &position,
                  const unsigned int           support);

    const Parameters::Peridynamics<dim> &parameters;
    std::vector<Particle>                particles;
    /**
     * Per owned particle: bit d set if component d is prescribed, bit 7 if a region or a
     * boundary layer holds it (0: free).
     */
    std::vector<std::uint8_t> held_components;
  };
} // namespace PeriArlequin

#endif
