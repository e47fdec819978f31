// Converting FE cells to PD under a smooth state (adaptive PD zone, Coupling/Overlap width).
// The ring case with a band: plate [-0.2, 0.2]^2, FE cells 20 mm, PD lattice 5 mm (m = 3.015,
// aluminium, plane stress), pure PD [-0.06, 0.06]^2, overlap band w = 0.04 m (two cells),
// energy blending, weak coupling. A criterion registered here, as a user would, flags the two
// columns of cells [0.06, 0.10] x [-0.06, 0.06]; one conversion runs at t = 0.
//
// 1. Uniaxial strain u = (eps x, 0) and shear u = (eps y, 0), eps = 1e-7 (small enough that
//    the PD bond's geometric nonlinearity, O(eps), stays below 1e-6), at rest. The FE energy
//    is int alpha W_c and the PD energy sum (1 - alpha_I) W_PD V, with W_PD = f W_c in the bulk
//    (f = 1.01349 uniaxial, 0.96145 shear: the lattice factors of tests/pd/affine_deformation,
//    from an independent lattice sum). So the jump is (f - 1) W_c dV with
//    dV = int (alpha_old - alpha_new) = d|B| + d(perimeter) w / 2 of the PD box B (the band's
//    rounded corners move by whole cells and lattice spacings, so they cancel in both
//    quadratures): dV = 0.04 * 0.12 + 0.08 * 0.02 = 0.0064 m^2. Tolerance on jump/predicted:
//    5e-6 / |f - 1|, the rounding of f's fifth decimal.
//    The new particles take the linear field exactly (Q1 interpolates it): largest
//    |u_I - u(x_I)| below 1e-12 eps; the constraint residual after the conversion below
//    1e-12 of eps times the plate size.
// 2. Uniform velocity v = (3, -2) m/s, and a smooth non-uniform one, no strain: the
//    conversion conserves momentum to round-off (1e-12 relative). Under the uniform velocity
//    the masses that change sides agree (FE Gauss points and lattice sites integrate the
//    linear alpha exactly); under the other the two quadratures of the momentum that changes
//    sides differ by 5e-5 of the total, which the particles that gained mass take up.
// Run on 1 and 2 ranks: the same verdicts.

#include <periarlequin/adaptivity/conversion_criterion.h>

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  /** Flags the cells whose centre lies in [0.06, 0.10] x [-0.06, 0.06]. */
  template <int dim>
  class BoxConversion : public PeriArlequin::CellCentreCriterion<dim>
  {
  protected:
    bool
    converts(const Point<dim> &c) const override
    {
      return c[0] > 0.06 && c[0] < 0.10 && std::abs(c[1]) < 0.06;
    }
  };
} // namespace

PERIARLEQUIN_REGISTER_CONVERSION_CRITERION(BoxConversion, "test box", "cells in a fixed box (test)")

std::string
case_text(const std::string &displacement, const std::string &velocity)
{
  return "set Dimension = 2\n"
         "subsection Geometry\n  set Lower corner = -0.2, -0.2\n"
         "  set Upper corner = 0.2, 0.2\n  set Subdivisions = 20, 20\nend\n"
         "subsection Material\n  set Young's modulus = 69e9\n  set Poisson's ratio = 0.3\n"
         "  set Density = 2700\n  set Two-dimensional model = plane stress\nend\n"
         "subsection Peridynamics\n  set Region = -0.06, -0.06 : 0.06, 0.06\n"
         "  set Lattice spacing = 0.005\nend\n"
         "subsection Coupling\n  set Method = weak\n  set Blending = energy\n"
         "  set Overlap width = 0.04\n  set Multiplier solver = cg\nend\n"
         "subsection Adaptive PD zone\n  set Conversion criterion = test box\n"
         "  set Check interval = 1000\nend\n"
         "subsection Time\n  set Time step = 2e-7\n  set End time = 1e-6\nend\n"
         "subsection Initial conditions\nsubsection function\n"
         "  subsection Displacement\n    set Function expression = " +
         displacement +
         "\n  end\n  subsection Velocity\n    set Function expression = " + velocity +
         "\n  end\nend\nend\n" + quiet_output();
}

template <int dim>
double
total_energy(const PeriArlequin::Simulator<dim> &simulator)
{
  return simulator.get_fe_zone().kinetic_energy() + simulator.get_fe_zone().strain_energy() +
         simulator.get_pd_zone()->kinetic_energy() + simulator.get_pd_zone()->strain_energy();
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const double E = 69e9, nu = 0.3, mu = E / (2 * (1 + nu)), eps = 1e-7;
    struct Strain
    {
      std::string name, displacement;
      double      classical_density, lattice_factor;
      Tensor<1, 2> (*field)(const Point<2> &);
    };
    const std::vector<Strain> strains = {
      {"uniaxial strain",
       "1e-7*x; 0",
       0.5 * E / (1 - nu * nu) * eps * eps,
       1.01349,
       [](const Point<2> &x) {
         return Tensor<1, 2>({1e-7 * x[0], 0.});
       }},
      {"shear strain", "1e-7*y; 0", 0.5 * mu * eps * eps, 0.96145, [](const Point<2> &x) {
         return Tensor<1, 2>({1e-7 * x[1], 0.});
       }}};
    for (const auto &strain : strains)
      {
        auto simulator = make_simulator<2>(case_text(strain.displacement, "0; 0"));
        simulator->setup();
        const auto  *pd            = simulator->get_pd_zone();
        const double energy_before = total_energy(*simulator);
        report(strain.name + ": particles before", pd->n_global_particles());
        check(strain.name + ": cells converted", simulator->grow_pd_zone(), 12, 0);
        report(strain.name + ": particles after", pd->n_global_particles());
        const double f         = strain.lattice_factor;
        const double dV        = 0.04 * 0.12 + 0.08 * 0.02;
        const double predicted = (f - 1) * strain.classical_density * dV;
        const double jump      = total_energy(*simulator) - energy_before;
        check(strain.name + ": energy jump / predicted (f - 1) W_c dV",
              jump / predicted,
              1.,
              5e-6 / std::abs(f - 1));
        check(strain.name + ": recorded conversion energy / measured jump",
              simulator->conversion_energy_change() / jump,
              1.,
              1e-12);
        double     worst = 0;
        const auto x     = pd->reference_positions();
        const auto u     = pd->get_state().displacements();
        for (unsigned int i = 0; i < pd->n_owned_particles(); ++i)
          worst = std::max(worst, (u[i] - strain.field(x[i])).norm());
        check_below(strain.name + ": max |u_I - u(x_I)| / eps",
                    Utilities::MPI::max(worst, MPI_COMM_WORLD) / eps,
                    1e-12);
        const auto residuals = simulator->get_coupling()->constraint_residuals();
        check_below(strain.name + ": |g| after conversion / (eps 0.4 m)",
                    residuals.first / (eps * 0.4),
                    1e-12);
      }
    for (const std::string velocity : {"3; -2", "3 + sin(20*x); -2 + cos(15*y)"})
      {
        auto simulator = make_simulator<2>(case_text("0; 0", velocity));
        simulator->setup();
        const auto momentum = [&] {
          return simulator->get_fe_zone().linear_momentum() +
                 simulator->get_pd_zone()->linear_momentum();
        };
        const Tensor<1, 2> before = momentum();
        simulator->grow_pd_zone();
        check_below("velocity (" + velocity + "): |momentum change| / |momentum|",
                    (momentum() - before).norm() / before.norm(),
                    1e-12);
      }
  });
}
