#include <periarlequin/pd/material_model.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <cmath>

namespace PeriArlequin
{
  namespace
  {
    /**
     * Extension e = |xi + eta| - |xi| and deformed length of a bond, with e computed as
     * (2 xi.eta + eta.eta) / (|xi + eta| + |xi|): no cancellation of nearly equal lengths,
     * so small strains keep full relative precision.
     */
    template <typename Bond, int dim>
    inline std::pair<double, double>
    extension(const Bond &bond, const Tensor<1, dim> &eta)
    {
      const double length = (bond.xi + eta).norm();
      return {(2. * (bond.xi * eta) + eta * eta) / (length + bond.length), length};
    }
  } // namespace

  template <int dim>
  std::map<std::string, typename PDMaterialRegistry<dim>::Entry> &
  PDMaterialRegistry<dim>::models()
  {
    static std::map<std::string, Entry> registered;
    return registered;
  }

  template <int dim>
  bool
  PDMaterialRegistry<dim>::register_model(const std::string &name,
                                          const std::string &description,
                                          Creator            creator)
  {
    AssertThrow(models().count(name) == 0,
                ExcMessage("A PD material model named '" + name + "' is already registered."));
    models()[name] = {description, std::move(creator)};
    return true;
  }

  template <int dim>
  std::unique_ptr<PDMaterialModel<dim>>
  PDMaterialRegistry<dim>::create(const std::string &name)
  {
    const auto entry = models().find(name);
    AssertThrow(entry != models().end(),
                ExcMessage("Invalid input: parameter 'Peridynamics/Material model' = '" + name +
                           "'; allowed: one of " + names() + "."));
    return entry->second.creator();
  }

  template <int dim>
  std::string
  PDMaterialRegistry<dim>::names()
  {
    std::string list;
    for (const auto &entry : models())
      list += (list.empty() ? "" : "|") + entry.first;
    return list;
  }

  template <int dim>
  std::string
  PDMaterialRegistry<dim>::documentation()
  {
    std::string text;
    for (const auto &entry : models())
      text += " '" + entry.first + "': " + entry.second.description + ".";
    return text;
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::initialize(const Parameters::Material &material,
                                          const BondFamilies<dim> &)
  {
    const double nu = material.poissons_ratio, mu = material.shear_modulus();
    youngs_modulus  = material.youngs_modulus;
    bulk_modulus    = material.bulk_modulus();
    if (dim == 3)
      {
        c = 3.;
        k = bulk_modulus;
        b = 15. * mu;
      }
    else
      {
        AssertThrow(material.planar_model == Parameters::PlanarModel::plane_stress,
                    ExcMessage("Invalid input: parameter 'Material/Two-dimensional model' = "
                               "'plane strain'; allowed with the PD material model 'LPS': "
                               "plane stress."));
        c = 2. * (2. * nu - 1.) / (nu - 1.);
        k = bulk_modulus + mu * (nu + 1.) * (nu + 1.) / (9. * (2. * nu - 1.) * (2. * nu - 1.));
        b = 8. * mu;
      }
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
  LinearPeridynamicSolid<dim>::compute_particle_scalars(
    const BondFamilies<dim>          &bonds,
    const std::vector<Tensor<1, dim>> &u,
    std::vector<double>               &scalars) const
  {
    for (unsigned int i = 0; i < bonds.n_owned; ++i)
      {
        double extension_moment = 0, intact_weighted_volume = 0;
        for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
          {
            if (bonds.state[n] == BondFamilies<dim>::broken)
              continue;
            const auto          &bond = bonds.stencil[bonds.stencil_index[n]];
            const double         e    = extension(bond, u[bonds.neighbor[n]] - u[i]).first;
            extension_moment += bond.length * e * bond.volume;
            intact_weighted_volume += bond.length * bond.length * bond.volume;
          }
        const double theta     = c * extension_moment / bonds.weighted_volume[i];
        scalars[2 * i]         = theta;
        scalars[2 * i + 1]     = extension_moment - theta * intact_weighted_volume / 3.;
      }
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::compute_forces(const BondFamilies<dim>          &bonds,
                                              const std::vector<Tensor<1, dim>> &u,
                                              const std::vector<double>         &scalars,
                                              std::vector<Tensor<1, dim>>       &force_density,
                                              std::vector<double> &energy_density) const
  {
    // Per particle (owned and ghost): t = alpha x + beta e_d with alpha = c (k theta -
    // beta S / 3) / q and beta = b / q.
    coefficients.resize(2 * bonds.n_total);
    for (unsigned int j = 0; j < bonds.n_total; ++j)
      {
        const double q           = bonds.weighted_volume[j];
        const double beta        = b / q;
        coefficients[2 * j]      = c * (k * scalars[2 * j] - beta * scalars[2 * j + 1] / 3.) / q;
        coefficients[2 * j + 1]  = beta;
      }
    for (unsigned int i = 0; i < bonds.n_owned; ++i)
      {
        const double   theta_i = scalars[2 * i];
        const double   alpha_i = coefficients[2 * i], beta_i = coefficients[2 * i + 1];
        Tensor<1, dim> force;
        double         deviatoric = 0;
        for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
          {
            if (bonds.state[n] == BondFamilies<dim>::broken)
              continue;
            const unsigned int   j      = bonds.neighbor[n];
            const auto          &bond   = bonds.stencil[bonds.stencil_index[n]];
            const Tensor<1, dim> eta    = u[j] - u[i];
            const auto [e, length]      = extension(bond, eta);
            const Tensor<1, dim> y      = bond.xi + eta;
            const double         ed_i   = e - theta_i * bond.length / 3.;
            const double         ed_j   = e - scalars[2 * j] * bond.length / 3.;
            const double t_ij = alpha_i * bond.length + beta_i * ed_i;
            const double t_ji = coefficients[2 * j] * bond.length + coefficients[2 * j + 1] * ed_j;
            force += ((t_ij + t_ji) * bond.volume / length) * y;
            deviatoric += ed_i * ed_i * bond.volume;
          }
        force_density[i]  = force;
        energy_density[i] = 0.5 * k * theta_i * theta_i + 0.5 * beta_i * deviatoric;
      }
  }

  template <int dim>
  double
  LinearPeridynamicSolid<dim>::critical_stretch(const double energy_release_rate,
                                                const double horizon) const
  {
    if (dim == 3)
      return std::sqrt(5. * energy_release_rate / (9. * bulk_modulus * horizon));
    return std::sqrt(4. * numbers::PI * energy_release_rate / (9. * youngs_modulus * horizon));
  }

  template class PDMaterialRegistry<2>;
  template class PDMaterialRegistry<3>;
  template class LinearPeridynamicSolid<2>;
  template class LinearPeridynamicSolid<3>;

  PERIARLEQUIN_REGISTER_PD_MATERIAL(LinearPeridynamicSolid,
                                    "LPS",
                                    "state-based linear peridynamic solid (3D, 2D plane stress)")
} // namespace PeriArlequin
