#ifndef periarlequin_pd_material_model_h
#define periarlequin_pd_material_model_h

#include <periarlequin/base/parameters.h>
#include <periarlequin/base/plugin_registry.h>
#include <periarlequin/pd/bond_families.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * A peridynamic constitutive model acting on the bond families of a lattice. A model may
   * need per-particle scalars (the LPS dilatation) of its neighbours: it computes them for
   * owned particles in compute_particle_scalars(); the PD zone copies them to the ghosts
   * before compute_forces(). Broken bonds (state broken) carry no force. Each stored bond is
   * visited once and its contribution goes to both ends that are owned (see BondFamilies).
   *
   * Users add a model by deriving from this class and registering it with
   * PERIARLEQUIN_REGISTER_PD_MATERIAL in their own source file; the parameter
   * "Peridynamics/Material model" then accepts its name, and the model's own parameters
   * (declared by its static declare_parameters()) live in "Peridynamics/<name>".
   */
  template <int dim>
  class PDMaterialModel
  {
  public:
    virtual ~PDMaterialModel() = default;

    /** Read the parameters declared by the class's static declare_parameters(). */
    virtual void
    parse_parameters(ParameterHandler &prm);

    /** Material constants; called once the bond families and weighted volumes exist. */
    virtual void
    initialize(const Parameters::Material &material, const BondFamilies<dim> &bonds) = 0;

    /**
     * Whether the model has kernels for the stencil layout of the bonds (then it must use
     * them when BondFamilies::uses_stencil()); the default loops over the CSR arrays only.
     * While the layout has a window (StencilLayout::restrict_to_window(), after a growth of
     * the zone) its kernels may compute the scalars and forces of the particles in the
     * window only and leave the others' entries as they are (the zone carried them over).
     */
    virtual bool
    supports_stencil() const;

    /** How many scalars per particle compute_forces() needs on ghost particles too. */
    virtual unsigned int
    n_particle_scalars() const = 0;

    /** Output names of those scalars. */
    virtual std::vector<std::string>
    particle_scalar_names() const = 0;

    /** Fill scalars[n_particle_scalars() * i + k] for every owned particle i. */
    virtual void
    compute_particle_scalars(const BondFamilies<dim>        &bonds,
                             ArrayView<const Tensor<1, dim>> displacement,
                             std::vector<double>            &scalars) const = 0;

    /**
     * compute_particle_scalars() after breaking every intact, breakable bond whose stretch
     * e / |xi| exceeds @p critical_stretch (the critical-stretch fracture criterion): the
     * scalars see those bonds broken. Returns the bonds broken, in storage order, with their
     * states set and the stencil view refreshed (BondFamilies::bonds_broke()). The default
     * breaks them in a loop of its own (BreakableBonds::break_above_stretch()) first; a
     * model that forms the extensions for its scalars anyway can break them there.
     */
    virtual std::vector<StoredBond>
    compute_particle_scalars_breaking(BondFamilies<dim>              &bonds,
                                      ArrayView<const Tensor<1, dim>> displacement,
                                      const double                    critical_stretch,
                                      std::vector<double>            &scalars) const;

    /**
     * Force density [N/m^3] and strain-energy density [J/m^3] of every owned particle, from
     * the displacements and scalars of owned and ghost particles. The energy of particle K
     * enters the Hamiltonian with the weight @p state_weight[K] (owned and ghost; 1 - alpha_K
     * for energy-based Arlequin blending, 1 otherwise): the force density of I must be
     * -d/du_I sum_K state_weight[K] W_K V_K / V_I, and energy_density[I] = state_weight[I] W_I.
     */
    virtual void
    compute_forces(const BondFamilies<dim>        &bonds,
                   ArrayView<const Tensor<1, dim>> displacement,
                   const std::vector<double>      &scalars,
                   const std::vector<double>      &state_weight,
                   std::vector<Tensor<1, dim>>    &force_density,
                   std::vector<double>            &energy_density) const = 0;

    /** Critical bond stretch for the critical energy release rate G0 [J/m^2]. */
    virtual double
    critical_stretch(const double energy_release_rate, const double horizon) const = 0;

    /**
     * The energy of each bond of the owned particles' families [J/m^6]: a split of the
     * strain energy into bonds, sum over bonds (each pair once) of pair_energy V v = the
     * energy of the zone (no state weights), 0 on broken bonds. For the "critical bond
     * energy" fracture criterion; the default throws (a model without such a split cannot be
     * used with it). Both ranks that hold a bond to a ghost must get the same value.
     */
    virtual void
    compute_pair_energies(const BondFamilies<dim>        &bonds,
                          ArrayView<const Tensor<1, dim>> displacement,
                          ArrayView<const double>         scalars,
                          std::vector<double>            &pair_energy) const;
  };

  /** The open registry of PD material models, by name. */
  template <int dim>
  using PDMaterialRegistry = PluginRegistry<PDMaterialModel<dim>>;

  extern template class PluginRegistry<PDMaterialModel<2>>;
  extern template class PluginRegistry<PDMaterialModel<3>>;

  /**
   * The state-based linear peridynamic solid (LPS) in 3D and in 2D plane stress and plane
   * strain, written in one form:
   *   theta = (c / q) sum omega x e V v,  e_d = e - theta x / 3,  beta = b / q,
   *   W = k theta^2 / 2 + beta / 2 sum omega e_d^2 V v,
   *   t = c (k theta - beta / 3 S) omega x / q + beta omega e_d,  S = sum omega e_d x V v,
   * with 3D (eq. 17, 25): c = 3, k = K, b = 15 mu (S vanishes while no bond is broken), and
   * plane stress (eq. 26-28, Le, Silling et al. 2014): c = 2 (2 nu - 1) / (nu - 1),
   * k = K + mu (nu + 1)^2 / (9 (2 nu - 1)^2), b = 8 mu; plane strain (same source): c = 2,
   * k = K + mu / 9, b = 8 mu (these make W classical under any uniform strain for a
   * continuous family). t = dW/de / (V v), so the forces are
   * exactly minus the derivative of the energy. omega = 1 on intact bonds, q is the weighted
   * volume of the full initial family.
   *
   * Critical stretch: 3D s_c = sqrt(5 G0 / (9 K delta)) (Silling & Askari 2005); plane stress
   * s_c = sqrt(4 pi G0 / (9 E delta)) (Ha & Bobaru 2010); plane strain
   * s_c = sqrt(5 pi G0 / (12 E delta)) (the same energy balance with the plane-strain
   * bond-based micromodulus 48 E / (5 pi delta^3)).
   */
  template <int dim>
  class LinearPeridynamicSolid : public PDMaterialModel<dim>
  {
  public:
    void
    initialize(const Parameters::Material &material, const BondFamilies<dim> &bonds) override;
    /** Vectorised dilatation and force passes on the stencil layout (lps_stencil_kernel.cc). */
    bool
    supports_stencil() const override;
    unsigned int
    n_particle_scalars() const override;
    std::vector<std::string>
    particle_scalar_names() const override;
    void
    compute_particle_scalars(const BondFamilies<dim>        &bonds,
                             ArrayView<const Tensor<1, dim>> displacement,
                             std::vector<double>            &scalars) const override;
    /** On the stencil layout, the bonds break in the vectorised dilatation pass. */
    std::vector<StoredBond>
    compute_particle_scalars_breaking(BondFamilies<dim>              &bonds,
                                      ArrayView<const Tensor<1, dim>> displacement,
                                      const double                    critical_stretch,
                                      std::vector<double>            &scalars) const override;
    void
    compute_forces(const BondFamilies<dim>        &bonds,
                   ArrayView<const Tensor<1, dim>> displacement,
                   const std::vector<double>      &scalars,
                   const std::vector<double>      &state_weight,
                   std::vector<Tensor<1, dim>>    &force_density,
                   std::vector<double>            &energy_density) const override;
    double
    critical_stretch(const double energy_release_rate, const double horizon) const override;
    /**
     * The model's energy is quadratic in the bond extensions e with t = dW/de / (V v), so
     * half the pair force times the extension, (t_ij + t_ji) e / 2, splits it exactly.
     */
    void
    compute_pair_energies(const BondFamilies<dim>        &bonds,
                          ArrayView<const Tensor<1, dim>> displacement,
                          ArrayView<const double>         scalars,
                          std::vector<double>            &pair_energy) const override;

  private:
    /**
     * Per particle (owned and ghost) the coefficients of its force state, scaled by its
     * state weight (an empty @p state_weight: 1): coefficients[3 j] = beta,
     * coefficients[3 j + 1] = alpha - beta theta / 3, coefficients[3 j + 2] = theta / 3.
     */
    void
    compute_coefficients(const BondFamilies<dim>   &bonds,
                         ArrayView<const double>    scalars,
                         const std::vector<double> &state_weight) const;

    /**
     * The extension moments sum x e V v of every slot of the stencil layout of @p bonds
     * (box_moment); with @p breaking, the intact, breakable bonds whose stretch exceeds
     * @p critical_stretch are left out and listed there (the dilatation pass of
     * compute_particle_scalars_breaking()).
     */
    void
    compute_moments_on_stencil(const BondFamilies<dim>        &bonds,
                               ArrayView<const Tensor<1, dim>> displacement,
                               const double                    critical_stretch,
                               std::vector<SlotBond>          *breaking) const;
    /**
     * After the bonds @p broken broke: the intact weighted volumes of their ends' slots
     * summed again (in the passes' order, so with the bits of a full pass), if box_volume
     * was that of the mask version @p version_before; else the next scalars sum them all.
     */
    void
    update_intact_volumes(const BondFamilies<dim>     &bonds,
                          const std::vector<SlotBond> &broken,
                          const unsigned int           version_before) const;
    /**
     * The scalars of the owned particles (in the layout's window, if it has one) from
     * box_moment and the bonds' current states.
     */
    void
    scalars_from_moments_on_stencil(const BondFamilies<dim> &bonds,
                                    std::vector<double>     &scalars) const;
    /** compute_forces() on the stencil layout of @p bonds. */
    void
    compute_forces_on_stencil(const BondFamilies<dim>        &bonds,
                              ArrayView<const Tensor<1, dim>> displacement,
                              const std::vector<double>      &scalars,
                              const std::vector<double>      &state_weight,
                              std::vector<Tensor<1, dim>>    &force_density,
                              std::vector<double>            &energy_density) const;
    /** The displacements of the held particles in the box slots, one array per component. */
    void
    gather_displacements(const StencilLayout<dim>       &layout,
                         ArrayView<const Tensor<1, dim>> displacement) const;

    double                      c = 0, k = 0, b = 0;
    double                      youngs_modulus = 0, bulk_modulus = 0;
    bool                        plane_strain = false;
    mutable std::vector<double> coefficients;
    mutable std::vector<double> moments;

    /**
     * Scratch of the stencil kernels, per box slot: displacement components, the three
     * force-state coefficients, extension moment, intact weighted volume (for the layout's
     * mask version box_volume_version), force components, deviatoric sum.
     */
    mutable std::vector<double> box_displacement, box_coefficients, box_moment, box_volume,
      box_force, box_deviatoric;
    mutable unsigned int box_volume_version = 0;
  };
} // namespace PeriArlequin

/**
 * Register a PD material model class template (instantiated for dim = 2 and 3, default
 * constructed; with its static declare_parameters(ParameterHandler &) if it has one) under
 * @p name, e.g.
 * PERIARLEQUIN_REGISTER_PD_MATERIAL(MyBondBasedModel, "PMB", "prototype micro-elastic").
 */
#define PERIARLEQUIN_REGISTER_PD_MATERIAL(classname, name, description)                 \
  namespace                                                                             \
  {                                                                                     \
    const bool periarlequin_registered_material_##classname =                           \
      PeriArlequin::register_plugin_template<PeriArlequin::PDMaterialModel, classname>( \
        name,                                                                           \
        description);                                                                   \
  }

#endif
