#ifndef periarlequin_coupling_master_slave_coupling_h
#define periarlequin_coupling_master_slave_coupling_h

#include <periarlequin/coupling/coupling.h>
#include <periarlequin/coupling/slave_layer.h>

#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The paper's "bad" coupling (fig. 8), registered as "bad": the overlap is split in two
   * halves (a step profile of alpha) and there are no multipliers. PD particles of the FE-side
   * half (and the layer past it) are slaves of the FE field, d = N u; FE DoFs of the PD-side
   * half are slaves of the PD field, interpolated multilinearly on the lattice. It is the
   * baseline that reflects waves.
   */
  template <int dim>
  class MasterSlaveCoupling : public Coupling<dim>
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    explicit MasterSlaveCoupling(const Parameters::Coupling &parameters);

    BlendingProfile
    blending_profile() const override;
    void
    initialize(const BlendingField<dim> &blending,
               FEZone<dim>              &fe_zone,
               PDZone<dim>              &pd_zone,
               const double              time_step) override;
    /** FE slaves from the PD lattice first, then PD slaves from the FE field. */
    void
    set_slave_displacements() override;
    void
    add_interface_forces(const double time) override;
    /** No damping: does nothing. */
    void
    apply_damping() override;
    /** No multipliers: does nothing. */
    void
    enforce_constraint() override;
    void
    set_slave_velocities() override;
    /** No constraint: zeros. */
    std::pair<double, double>
    constraint_residuals() const override;
    types::global_dof_index
    n_multipliers() const override;
    std::pair<types::global_dof_index, types::global_dof_index>
    n_coupled_particles() const override;
    unsigned int
    last_solver_iterations() const override;

  private:
    /** An FE DoF that follows the PD field, with its lattice weights (local PD indices). */
    struct FESlave
    {
      unsigned int                                 dof;
      unsigned int                                 component;
      std::vector<std::pair<unsigned int, double>> weights;
    };

    const Parameters::Coupling parameters;
    FEZone<dim>               *fe_zone = nullptr;
    PDZone<dim>               *pd_zone = nullptr;
    SlaveLayer<dim>            slaves;
    std::vector<FESlave>       fe_slaves;
    /** PD velocities and accelerations of owned and ghost particles. */
    std::vector<double> pd_motion;
  };
} // namespace PeriArlequin

#endif
