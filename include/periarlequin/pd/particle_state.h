#ifndef periarlequin_pd_particle_state_h
#define periarlequin_pd_particle_state_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The kinematic state of the particles of one rank, indexed by the local particle number
   * of GhostExchange: displacements of owned and ghost particles (a bond needs both ends),
   * velocities and accelerations of owned particles. The sizes are fixed by reinit() when
   * the particle set changes; everyone else gets views, so no caller can resize a field out
   * of step with the local numbering.
   */
  template <int dim>
  class ParticleState
  {
  public:
    /** Zero state for @p n_owned owned particles and @p n_total owned plus ghost ones. */
    void
    reinit(const unsigned int n_owned, const unsigned int n_total);

    unsigned int
    n_owned() const;

    /** Owned particles, then ghosts [m]. */
    ArrayView<Tensor<1, dim>>
    displacements();
    ArrayView<const Tensor<1, dim>>
    displacements() const;
    /** Owned particles [m/s]. */
    ArrayView<Tensor<1, dim>>
    velocities();
    ArrayView<const Tensor<1, dim>>
    velocities() const;
    /** Owned particles [m/s^2]. */
    ArrayView<Tensor<1, dim>>
    accelerations();
    ArrayView<const Tensor<1, dim>>
    accelerations() const;

  private:
    std::vector<Tensor<1, dim>> displacement, velocity, acceleration;
  };
} // namespace PeriArlequin

#endif
