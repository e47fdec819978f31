#ifndef periarlequin_coupling_slave_layer_h
#define periarlequin_coupling_slave_layer_h

#include <periarlequin/coupling/interpolation_operator.h>

#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The PD slaves: owned particles with a weight 1 - alpha below Coupling/Minimum PD weight.
   * They complete the families of the weighted particles and follow the FE field, d = N u
   * (and w = N v, b = N a), so their blended forces act on the FE nodes through N^T (energy
   * blending) and their masses (1 - alpha) rho V join the lumped FE masses (N^T m).
   */
  template <int dim>
  class SlaveLayer
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    /** The interpolation rows of the slaves of @p pd_zone; adds their masses to @p fe_zone. */
    void
    initialize(FEZone<dim> &fe_zone, PDZone<dim> &pd_zone);

    /** d = N u on the slaves. */
    void
    follow_displacements();

    /** w = N v, b = N a on the slaves. */
    void
    follow_velocities();

    /** @p force += N^T f with f the slaves' blended PD forces [N]. */
    void
    add_forces(VectorType &force);

    /**
     * @p force += N^T f with f the slaves' share of the loads at @p time [N]: their masses
     * move with the FE nodes, so do the body forces and tractions on them.
     */
    void
    add_loads(const double time, VectorType &force);

    /** Slaves on all ranks. */
    types::global_dof_index
    n_global_slaves() const;

  private:
    FEZone<dim>                *fe_zone = nullptr;
    PDZone<dim>                *pd_zone = nullptr;
    std::vector<unsigned int>   particles;
    InterpolationOperator<dim>  interpolation;
    VectorType                  scratch;
    std::vector<Tensor<1, dim>> forces;
  };
} // namespace PeriArlequin

#endif
