#include <periarlequin/pd/particle_state.h>

namespace PeriArlequin
{
  template <int dim>
  void
  ParticleState<dim>::reinit(const unsigned int n_owned, const unsigned int n_total)
  {
    Assert(n_owned <= n_total, ExcInternalError());
    displacement.assign(n_total, Tensor<1, dim>());
    velocity.assign(n_owned, Tensor<1, dim>());
    acceleration.assign(n_owned, Tensor<1, dim>());
  }

  template <int dim>
  unsigned int
  ParticleState<dim>::n_owned() const
  {
    return velocity.size();
  }

  template <int dim>
  ArrayView<Tensor<1, dim>>
  ParticleState<dim>::displacements()
  {
    return make_array_view(displacement);
  }

  template <int dim>
  ArrayView<const Tensor<1, dim>>
  ParticleState<dim>::displacements() const
  {
    return make_array_view(displacement);
  }

  template <int dim>
  ArrayView<Tensor<1, dim>>
  ParticleState<dim>::velocities()
  {
    return make_array_view(velocity);
  }

  template <int dim>
  ArrayView<const Tensor<1, dim>>
  ParticleState<dim>::velocities() const
  {
    return make_array_view(velocity);
  }

  template <int dim>
  ArrayView<Tensor<1, dim>>
  ParticleState<dim>::accelerations()
  {
    return make_array_view(acceleration);
  }

  template <int dim>
  ArrayView<const Tensor<1, dim>>
  ParticleState<dim>::accelerations() const
  {
    return make_array_view(acceleration);
  }

  template class ParticleState<2>;
  template class ParticleState<3>;
} // namespace PeriArlequin
