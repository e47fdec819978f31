// A user adds a PD material model without editing the library: this file defines a
// bond-based prototype micro-elastic brittle (PMB) model with a parameter of its own
// ("Peridynamics/calibrated PMB/Stiffness factor", scaling the micromodulus), registers it
// under the name "calibrated PMB" with PERIARLEQUIN_REGISTER_PD_MATERIAL, and runs it by
// naming it in the parameter file. Its micromodulus is calibrated on the lattice so that the
// dilatation energy is exactly classical: W = (c / 4) sum s^2 x V v with c = 18 K / sum x V v (3D)
// or 4 E / ((1 - nu) sum x V v) (plane stress). Checked: under a pure dilatation the interior force
// vanishes (1e-10 of the surface force: round-off) and W equals the classical 9 K eps^2 / 2 (3D) or
// E eps^2 / (1 - nu) (plane stress) to 1e-10 (exact by construction); with the stiffness factor set
// to 2.5 in the parameter file, W is 2.5 times that (the parameter reached the model). The strain
// is 1e-4 because this simple model computes the stretch as a difference of lengths, whose
// round-off is 1e-16 / strain relative. The model has no stencil kernel: the automatic force kernel
// gives it the bond lists, and asking for the stencil (Peridynamics/Force kernel = stencil) is
// refused by name.

#include <periarlequin/pd/material_model.h>

#include "../tests.h"

namespace UserModels
{
  using namespace dealii;
  using PeriArlequin::BondFamilies;

  template <int dim>
  class CalibratedPMB : public PeriArlequin::PDMaterialModel<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Stiffness factor",
                        "1",
                        Patterns::Double(0),
                        "Factor on the calibrated micromodulus [-].");
    }
    void
    parse_parameters(ParameterHandler &prm) override
    {
      stiffness_factor = prm.get_double("Stiffness factor");
    }
    void
    initialize(const PeriArlequin::Parameters::Material &material,
               const BondFamilies<dim>                  &bonds) override
    {
      double moment = 0; // sum x V v over a full family
      for (const auto &bond : bonds.stencil)
        moment += bond.length * bond.volume;
      micromodulus   = stiffness_factor * (dim == 3 ? 18 * material.bulk_modulus() / moment :
                                                      4 * material.youngs_modulus /
                                                      ((1 - material.poissons_ratio) * moment));
      youngs_modulus = material.youngs_modulus;
    }
    unsigned int
    n_particle_scalars() const override
    {
      return 0;
    }
    std::vector<std::string>
    particle_scalar_names() const override
    {
      return {};
    }
    void
    compute_particle_scalars(const BondFamilies<dim> &,
                             ArrayView<const Tensor<1, dim>>,
                             std::vector<double> &) const override
    {}
    void
    compute_forces(const BondFamilies<dim>        &bonds,
                   ArrayView<const Tensor<1, dim>> u,
                   const std::vector<double> &,
                   const std::vector<double>   &state_weight,
                   std::vector<Tensor<1, dim>> &force_density,
                   std::vector<double>         &energy_density) const override
    {
      // Each stored bond once, its pair force and energy shared by both owned ends.
      std::fill(force_density.begin(), force_density.end(), Tensor<1, dim>());
      std::fill(energy_density.begin(), energy_density.end(), 0.);
      for (unsigned int i = 0; i < bonds.n_owned; ++i)
        for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
          {
            if (bonds.state[n] == BondFamilies<dim>::broken)
              continue;
            const unsigned int   j    = bonds.neighbor(i, n);
            const auto          &bond = bonds.stencil[bonds.stencil_index[n]];
            const Tensor<1, dim> y    = bond.xi + u[j] - u[i];
            const double         s    = (y.norm() - bond.length) / bond.length;
            // Half the bond energy belongs to each end, weighted by that end's state weight.
            const double         w      = 0.5 * (state_weight[i] + state_weight[j]);
            const Tensor<1, dim> pair   = (w * micromodulus * s * bond.volume / y.norm()) * y;
            const double         energy = 0.25 * micromodulus * s * s * bond.length * bond.volume;
            force_density[i] += pair;
            energy_density[i] += state_weight[i] * energy;
            if (bonds.neighbor_is_owned(i, n))
              {
                force_density[j] -= pair;
                energy_density[j] += state_weight[j] * energy;
              }
          }
    }
    double
    critical_stretch(const double energy_release_rate, const double horizon) const override
    {
      return std::sqrt(5 * energy_release_rate / (9 * youngs_modulus * horizon));
    }

  private:
    double stiffness_factor = 1, micromodulus = 0, youngs_modulus = 0;
  };

  PERIARLEQUIN_REGISTER_PD_MATERIAL(CalibratedPMB,
                                    "calibrated PMB",
                                    "bond-based PMB calibrated on the lattice (a user model)")
} // namespace UserModels

using namespace PeriArlequinTests;

template <int dim>
void
check_user_model(const double stiffness_factor)
{
  const double eps = 1e-4, dx = 1e-3, E = 69e9, nu = 0.3;
  const double classical =
    dim == 3 ? 4.5 * E / (3 * (1 - 2 * nu)) * eps * eps : E * eps * eps / (1 - nu);
  std::ostringstream prm;
  prm << "set Dimension = " << dim << "\n"
      << "subsection Geometry\n  set Lower corner = " << (dim == 2 ? "0, 0" : "0, 0, 0")
      << "\n  set Upper corner = " << (dim == 2 ? "0.02, 0.02" : "0.016, 0.016, 0.016")
      << "\n  set Subdivisions = " << (dim == 2 ? "5, 5" : "4, 4, 4") << "\nend\n"
      << "subsection Peridynamics\n  set Region = "
      << (dim == 2 ? "0, 0 : 0.02, 0.02" : "0, 0, 0 : 0.016, 0.016, 0.016")
      << "\n  set Lattice spacing = " << dx << "\n  set Material model = calibrated PMB\n"
      << "  subsection calibrated PMB\n    set Stiffness factor = " << stiffness_factor
      << "\n  end\nend\n"
      << "subsection Time\n  set Time step = 1e-9\n  set Stability estimate iterations = 5\nend\n"
      << "subsection Initial conditions\nsubsection function\n  subsection Displacement\n"
      << "    set Function expression = " << eps << "*x; " << eps << "*y"
      << (dim == 3 ? std::string("; ") + std::to_string(eps) + "*z" : "") << "\n  end\nend\nend\n"
      << quiet_output();
  auto simulator = make_simulator<dim>(prm.str());
  simulator->setup();
  auto &pd = *simulator->get_pd_zone();
  AssertThrow(!pd.get_bonds().uses_stencil(),
              ExcMessage("a model without a stencil kernel was given the stencil layout"));
  if (stiffness_factor == 1.)
    {
      bool refused = false;
      try
        {
          make_simulator<dim>(prm.str() +
                              "subsection Peridynamics\n  set Force kernel = stencil\nend\n")
            ->setup();
        }
      catch (const std::exception &error)
        {
          refused =
            std::string(error.what()).find("Peridynamics/Force kernel") != std::string::npos;
        }
      AssertThrow(refused,
                  ExcMessage("Force kernel = stencil with a model without a stencil kernel was "
                             "not refused by name"));
      verdicts() << dim << "D calibrated PMB (user model): bond lists under the automatic "
                 << "kernel, the stencil refused by name" << std::endl;
    }
  const double L = dim == 2 ? 0.02 : 0.016, reach = 3.015 * dx + 0.5 * dx;
  double       inner = 0, largest = 0, energy = 0;
  for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
    {
      largest       = std::max(largest, pd.force_densities()[i].norm());
      bool interior = true;
      for (unsigned int d = 0; d < dim; ++d)
        interior = interior && pd.reference_positions()[i][d] > reach &&
                   pd.reference_positions()[i][d] < L - reach;
      if (interior)
        inner = std::max(inner, pd.force_densities()[i].norm()), energy = pd.energy_densities()[i];
    }
  std::ostringstream title;
  title << dim << "D calibrated PMB (user model), stiffness factor " << stiffness_factor;
  check_below(title.str() + ": max interior |force| / max surface |force|", inner / largest, 1e-10);
  check(title.str() + ": W / (factor x classical) under pure dilatation",
        energy / (stiffness_factor * classical),
        1.,
        1e-10);
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    check_user_model<2>(1.);
    check_user_model<2>(2.5);
    check_user_model<3>(1.);
  });
}
