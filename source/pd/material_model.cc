#include <periarlequin/base/parallel_loops.h>
#include <periarlequin/pd/breakable_bonds.h>
#include <periarlequin/pd/material_model.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <cmath>

namespace PeriArlequin
{
  template <int dim>
  void
  PDMaterialModel<dim>::parse_parameters(ParameterHandler &)
  {}

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::initialize(const Parameters::Material &material,
                                          const BondFamilies<dim> &)
  {
    const double nu = material.poissons_ratio, mu = material.shear_modulus();
    youngs_modulus = material.youngs_modulus;
    bulk_modulus   = material.bulk_modulus();
    if (dim == 3)
      {
        c = 3.;
        k = bulk_modulus;
        b = 15. * mu;
      }
    else if (material.planar_model == Parameters::PlanarModel::plane_stress)
      {
        c = 2. * (2. * nu - 1.) / (nu - 1.);
        k = bulk_modulus + mu * (nu + 1.) * (nu + 1.) / (9. * (2. * nu - 1.) * (2. * nu - 1.));
        b = 8. * mu;
      }
    else
      {
        c = 2.;
        k = bulk_modulus + mu / 9.;
        b = 8. * mu;
      }
    plane_strain = dim == 2 && material.planar_model == Parameters::PlanarModel::plane_strain;
  }

  template <int dim>
  bool
  PDMaterialModel<dim>::supports_stencil() const
  {
    return false;
  }

  template <int dim>
  bool
  LinearPeridynamicSolid<dim>::supports_stencil() const
  {
    return true;
  }

  template <int dim>
  unsigned int
  LinearPeridynamicSolid<dim>::n_particle_scalars() const
  {
    return 2;
  }

  template <int dim>
  std::vector<std::string>
  LinearPeridynamicSolid<dim>::particle_scalar_names() const
  {
    return {"dilatation", "deviatoric_moment"};
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::compute_particle_scalars(const BondFamilies<dim>        &bonds,
                                                        ArrayView<const Tensor<1, dim>> u,
                                                        std::vector<double> &scalars) const
  {
    if (bonds.uses_stencil())
      {
        compute_moments_on_stencil(bonds, u, 0., nullptr);
        scalars_from_moments_on_stencil(bonds, scalars);
        return;
      }
    // Per owned particle: the extension moment sum x e V v and the intact weighted volume
    // sum x^2 V v, gathered bond by bond into both owned ends.
    moments.assign(2 * bonds.n_owned, 0.);
    for (unsigned int i = 0; i < bonds.n_owned; ++i)
      for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
        {
          if (bonds.state[n] == BondFamilies<dim>::broken)
            continue;
          const unsigned int j    = bonds.neighbor(i, n);
          const auto        &bond = bonds.stencil[bonds.stencil_index[n]];
          const double       e    = BondFamilies<dim>::extension(bond, u[j] - u[i]).first;
          const double       extension_moment = bond.length * e * bond.volume;
          const double       weighted_volume  = bond.length * bond.length * bond.volume;
          moments[2 * i] += extension_moment;
          moments[2 * i + 1] += weighted_volume;
          if (j < bonds.n_owned)
            {
              moments[2 * j] += extension_moment;
              moments[2 * j + 1] += weighted_volume;
            }
        }
    for (unsigned int i = 0; i < bonds.n_owned; ++i)
      {
        const double theta = c * moments[2 * i] / bonds.weighted_volume[i];
        scalars[2 * i]     = theta;
        scalars[2 * i + 1] = moments[2 * i] - theta * moments[2 * i + 1] / 3.;
      }
  }

  template <int dim>
  std::vector<StoredBond>
  PDMaterialModel<dim>::compute_particle_scalars_breaking(BondFamilies<dim>              &bonds,
                                                          ArrayView<const Tensor<1, dim>> u,
                                                          const double         critical_stretch,
                                                          std::vector<double> &scalars) const
  {
    BreakableBonds<dim> breakable(bonds, u);
    breakable.break_above_stretch(critical_stretch);
    if (breakable.n_broken() > 0)
      bonds.bonds_broke(breakable.broken_bonds());
    compute_particle_scalars(bonds, u, scalars);
    return breakable.broken_bonds();
  }

  template <int dim>
  std::vector<StoredBond>
  LinearPeridynamicSolid<dim>::compute_particle_scalars_breaking(BondFamilies<dim> &bonds,
                                                                 ArrayView<const Tensor<1, dim>> u,
                                                                 const double critical_stretch,
                                                                 std::vector<double> &scalars) const
  {
    if (!bonds.uses_stencil())
      return PDMaterialModel<dim>::compute_particle_scalars_breaking(bonds,
                                                                     u,
                                                                     critical_stretch,
                                                                     scalars);
    const unsigned int    version_before = bonds.stencil_layout().mask_version();
    std::vector<SlotBond> breaking;
    compute_moments_on_stencil(bonds, u, critical_stretch, &breaking);
    std::vector<StoredBond> broken = bonds.break_stencil_bonds(breaking);
    if (!broken.empty())
      update_intact_volumes(bonds, breaking, version_before);
    scalars_from_moments_on_stencil(bonds, scalars);
    return broken;
  }

  template <int dim>
  void
  PDMaterialModel<dim>::compute_pair_energies(const BondFamilies<dim> &,
                                              ArrayView<const Tensor<1, dim>>,
                                              ArrayView<const double>,
                                              std::vector<double> &) const
  {
    AssertThrow(false,
                ExcMessage("Peridynamics/Fracture criterion: this material model does not "
                           "split its energy into bonds; choose a criterion that does not "
                           "need bond energies (e.g. critical stretch)."));
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::compute_coefficients(const BondFamilies<dim>   &bonds,
                                                    ArrayView<const double>    scalars,
                                                    const std::vector<double> &state_weight) const
  {
    // With t = alpha x + beta e_d, alpha = c (k theta - beta S / 3) / q, beta = b / q:
    // t = beta e + (alpha - beta theta / 3) x. So a bond's pair force is t_ij + t_ji =
    // (beta_i + beta_j) e + (a_i + a_j) x with a = alpha - beta theta / 3; theta / 3 is kept
    // for the deviatoric energy.
    coefficients.resize(3 * bonds.n_total);
    // Under a window of the stencil, only the particles its force pass reads.
    bonds.stencil_layout().for_each_read_particle(bonds.n_total, [&](const unsigned int j) {
      const double weight     = state_weight.empty() ? 1. : state_weight[j];
      const double q          = bonds.weighted_volume[j];
      const double beta       = b / q;
      const double theta      = scalars[2 * j];
      const double alpha      = c * (k * theta - beta * scalars[2 * j + 1] / 3.) / q;
      coefficients[3 * j]     = weight * beta;
      coefficients[3 * j + 1] = weight * (alpha - beta * theta / 3.);
      coefficients[3 * j + 2] = theta / 3.;
    });
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::compute_pair_energies(const BondFamilies<dim>        &bonds,
                                                     ArrayView<const Tensor<1, dim>> u,
                                                     ArrayView<const double>         scalars,
                                                     std::vector<double> &pair_energy) const
  {
    compute_coefficients(bonds, scalars, {});
    pair_energy.assign(bonds.n_bonds(), 0.);
    for (unsigned int i = 0; i < bonds.n_owned; ++i)
      for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
        if (bonds.state[n] != BondFamilies<dim>::broken)
          {
            const unsigned int j    = bonds.neighbor(i, n);
            const auto        &bond = bonds.stencil[bonds.stencil_index[n]];
            const double       e    = BondFamilies<dim>::extension(bond, u[j] - u[i]).first;
            const double       t    = (coefficients[3 * i] + coefficients[3 * j]) * e +
                             (coefficients[3 * i + 1] + coefficients[3 * j + 1]) * bond.length;
            pair_energy[n] = 0.5 * t * e;
          }
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::compute_forces(const BondFamilies<dim>        &bonds,
                                              ArrayView<const Tensor<1, dim>> u,
                                              const std::vector<double>      &scalars,
                                              const std::vector<double>      &state_weight,
                                              std::vector<Tensor<1, dim>>    &force_density,
                                              std::vector<double>            &energy_density) const
  {
    if (bonds.uses_stencil())
      return compute_forces_on_stencil(bonds,
                                       u,
                                       scalars,
                                       state_weight,
                                       force_density,
                                       energy_density);
    // The state weights scale each particle's force state, as they scale its energy.
    compute_coefficients(bonds, make_array_view(scalars), state_weight);
    std::fill(force_density.begin(), force_density.begin() + bonds.n_owned, Tensor<1, dim>());
    // Sum of omega e_d^2 V v per owned particle.
    std::fill(energy_density.begin(), energy_density.begin() + bonds.n_owned, 0.);
    for (unsigned int i = 0; i < bonds.n_owned; ++i)
      {
        const double *const ci = &coefficients[3 * i];
        Tensor<1, dim>      force_i;
        double              deviatoric_i = 0;
        for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
          {
            if (bonds.state[n] == BondFamilies<dim>::broken)
              continue;
            const unsigned int   j    = bonds.neighbor(i, n);
            const double *const  cj   = &coefficients[3 * j];
            const auto          &bond = bonds.stencil[bonds.stencil_index[n]];
            const Tensor<1, dim> eta  = u[j] - u[i];
            const auto [e, length]    = BondFamilies<dim>::extension(bond, eta);
            const double         t    = (ci[0] + cj[0]) * e + (ci[1] + cj[1]) * bond.length;
            const Tensor<1, dim> pair = (t * bond.volume / length) * (bond.xi + eta);
            const double         ed_i = e - ci[2] * bond.length;
            force_i += pair;
            deviatoric_i += ed_i * ed_i * bond.volume;
            if (j < bonds.n_owned)
              {
                const double ed_j = e - cj[2] * bond.length;
                force_density[j] -= pair;
                energy_density[j] += ed_j * ed_j * bond.volume;
              }
          }
        force_density[i] += force_i;
        energy_density[i] += deviatoric_i;
      }
    for (unsigned int i = 0; i < bonds.n_owned; ++i)
      {
        const double theta = scalars[2 * i];
        energy_density[i] =
          0.5 * state_weight[i] * k * theta * theta + 0.5 * coefficients[3 * i] * energy_density[i];
      }
  }

  template <int dim>
  double
  LinearPeridynamicSolid<dim>::critical_stretch(const double energy_release_rate,
                                                const double horizon) const
  {
    if (dim == 3)
      return std::sqrt(5. * energy_release_rate / (9. * bulk_modulus * horizon));
    if (plane_strain)
      return std::sqrt(5. * numbers::PI * energy_release_rate / (12. * youngs_modulus * horizon));
    return std::sqrt(4. * numbers::PI * energy_release_rate / (9. * youngs_modulus * horizon));
  }

  template class PDMaterialModel<2>;
  template class PDMaterialModel<3>;
  template class PluginRegistry<PDMaterialModel<2>>;
  template class PluginRegistry<PDMaterialModel<3>>;
  template class LinearPeridynamicSolid<2>;
  template class LinearPeridynamicSolid<3>;

  PERIARLEQUIN_REGISTER_PD_MATERIAL(
    LinearPeridynamicSolid,
    "LPS",
    "state-based linear peridynamic solid (3D, 2D plane stress and plane strain)")
} // namespace PeriArlequin
