// The energy jump of a conversion in 3D under a uniform strain, against the 3D lattice factor.
// A block [-0.2, 0.2]^3 m, FE cells 40 mm, lattice 10 mm (m = 3.015, aluminium), pure PD
// [-0.08, 0.08]^2 x [-0.04, 0.04], overlap band w = 0.04 m (one cell), energy blending, weak
// coupling. A criterion registered here flags the cells whose centre lies in [0.08, 0.12] x
// [-0.08, 0.08] x [-0.04, 0.04] (8 cells); one conversion at t = 0.
// The FE energy is W_c int alpha (Gauss quadrature) and the PD energy f W_c sum (1 - alpha_I) V
// (slaves included), f the lattice factor of the strain from the independent lattice sum of
// tests/pd/affine_deformation (3D, m = 3.015: uniaxial strain 1.00691, shear 0.98791). So the
// jump is W_c (dV_FE + f dV_PD), dV_FE < 0 and dV_PD > 0 the changes of the two blended
// volumes. Unlike 2D, where the band's rounded corners only move and their quadrature errors
// cancel, the band's four edges along x grow by the layer here, and alpha is not polynomial
// across an edge (alpha = r / w): the two quadratures differ there by more than (f - 1) of
// the jump. So the volumes are measured, from the masses (a separate conversion under the
// uniform velocity (1, 0, 0) m/s: the FE lumped masses from the FE momentum, less the slaves'
// mass lumped onto the FE nodes; the PD masses from the particles), and checked against the
// exact change of the blending volume of a box, dV = d|B| + dS w / 2 + dL pi w^2 / 12
// (|B| volume, S surface, L edge length: the band's faces, edges and corners; the corners
// only move) = 5.12e-4 + 3.84e-4 + 6.702e-5 m^3, within 1 % (the quadratures of the edges).
// Tolerances: jump / predicted to 5e-6 / |f - 1| (the rounding of f's fifth decimal; the
// geometric nonlinearity at eps = 1e-7 is 1e-7); the new particles take the linear field to
// 1e-12 of eps (Q1 holds it).
// Run on 1 and 2 ranks: the same verdicts.

#include <periarlequin/adaptivity/conversion_criterion.h>

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  constexpr double density = 2700;

  /** Flags the cells whose centre lies in [0.08, 0.12] x [-0.08, 0.08] x [-0.04, 0.04]. */
  template <int dim>
  class SlabConversion : public PeriArlequin::CellCentreCriterion<dim>
  {
  protected:
    bool
    converts(const Point<dim> &c) const override
    {
      return c[0] > 0.08 && c[0] < 0.12 && std::abs(c[1]) < 0.08 && std::abs(c[dim - 1]) < 0.04;
    }
  };

  std::string
  case_text(const std::string &displacement, const std::string &velocity)
  {
    return "set Dimension = 3\n"
           "subsection Geometry\n  set Lower corner = -0.2, -0.2, -0.2\n"
           "  set Upper corner = 0.2, 0.2, 0.2\n  set Subdivisions = 10, 10, 10\nend\n"
           "subsection Material\n  set Young's modulus = 69e9\n  set Poisson's ratio = 0.3\n"
           "  set Density = 2700\nend\n"
           "subsection Peridynamics\n  set Region = -0.08, -0.08, -0.04 : 0.08, 0.08, 0.04\n"
           "  set Lattice spacing = 0.01\n  set Horizon factor = 3.015\nend\n"
           "subsection Coupling\n  set Method = weak\n  set Blending = energy\n"
           "  set Overlap width = 0.04\n  set Multiplier solver = cg\nend\n"
           "subsection Adaptive PD zone\n  set Conversion criterion = test slab\n"
           "  set Check interval = 1000\nend\n"
           "subsection Time\n  set Time step = 2e-7\n  set End time = 1e-6\nend\n"
           "subsection Initial conditions\nsubsection function\n"
           "  subsection Displacement\n    set Function expression = " +
           displacement +
           "\n  end\n  subsection Velocity\n    set Function expression = " + velocity +
           "\n  end\nend\nend\n" + quiet_output();
  }

  double
  total_energy(const PeriArlequin::Simulator<3> &simulator)
  {
    return simulator.get_fe_zone().kinetic_energy() + simulator.get_fe_zone().strain_energy() +
           simulator.get_pd_zone()->kinetic_energy() + simulator.get_pd_zone()->strain_energy();
  }

  /** The blended volumes int alpha (FE) and sum (1 - alpha_I) V (PD), under v = (1, 0, 0). */
  std::pair<double, double>
  blended_volumes(const PeriArlequin::Simulator<3> &simulator)
  {
    const auto *pd         = simulator.get_pd_zone();
    double      pd_mass    = 0;
    double      slave_mass = 0;
    for (unsigned int i = 0; i < pd->n_owned_particles(); ++i)
      {
        pd_mass += pd->particle_mass(i);
        if (pd->is_slave(i))
          slave_mass += pd->particle_mass(i);
      }
    pd_mass              = Utilities::MPI::sum(pd_mass, MPI_COMM_WORLD);
    slave_mass           = Utilities::MPI::sum(slave_mass, MPI_COMM_WORLD);
    const double fe_mass = simulator.get_fe_zone().linear_momentum()[0] - slave_mass;
    return {fe_mass / density, pd_mass / density};
  }
} // namespace

PERIARLEQUIN_REGISTER_CONVERSION_CRITERION(SlabConversion, "test slab", "cells in a slab (test)")

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    // The blended volumes before and after the conversion.
    auto moving = make_simulator<3>(case_text("0; 0; 0", "1; 0; 0"));
    moving->setup();
    const auto before = blended_volumes(*moving);
    check("cells converted", moving->grow_pd_zone(), 8, 0);
    const auto   after = blended_volumes(*moving);
    const double dV_fe = after.first - before.first, dV_pd = after.second - before.second;
    const double w = 0.04, exact = 0.04 * 0.16 * 0.08 + (0.1216 - 0.1024) * w / 2 +
                                   0.16 * numbers::PI * w * w / 12;
    report("exact change of the blending volume [m^3]", exact);
    report("FE volume change [m^3]", dV_fe);
    report("PD volume change [m^3]", dV_pd);
    check("-(FE volume change) / exact", -dV_fe / exact, 1., 0.01);
    check("PD volume change / exact", dV_pd / exact, 1., 0.01);

    const double E = 69e9, nu = 0.3, eps = 1e-7;
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    struct Strain
    {
      std::string name, displacement;
      double      classical_density, lattice_factor;
    };
    const std::vector<Strain> strains = {
      {"uniaxial strain", "1e-7*x; 0; 0", 0.5 * (lambda + 2 * mu) * eps * eps, 1.00691},
      {"shear strain", "1e-7*y; 0; 0", 0.5 * mu * eps * eps, 0.98791}};
    for (const auto &strain : strains)
      {
        auto simulator = make_simulator<3>(case_text(strain.displacement, "0; 0; 0"));
        simulator->setup();
        const double energy_before = total_energy(*simulator);
        simulator->grow_pd_zone();
        const double f         = strain.lattice_factor;
        const double predicted = strain.classical_density * (dV_fe + f * dV_pd);
        const double jump      = total_energy(*simulator) - energy_before;
        report(strain.name + ": jump [J]", jump);
        report(strain.name + ": (f - 1) W_c dV, exact dV [J]",
               (f - 1) * strain.classical_density * exact);
        check(strain.name + ": energy jump / predicted W_c (dV_FE + f dV_PD)",
              jump / predicted,
              1.,
              5e-6 / std::abs(f - 1));
        const auto *pd    = simulator->get_pd_zone();
        const auto  x     = pd->reference_positions();
        const auto  u     = pd->get_state().displacements();
        double      worst = 0;
        for (unsigned int i = 0; i < pd->n_owned_particles(); ++i)
          {
            const Tensor<1, 3> exact_u(
              {1e-7 * (strain.name[0] == 'u' ? x[i][0] : x[i][1]), 0., 0.});
            worst = std::max(worst, (u[i] - exact_u).norm());
          }
        check_below(strain.name + ": max |u_I - u(x_I)| / eps",
                    Utilities::MPI::max(worst, MPI_COMM_WORLD) / eps,
                    1e-12);
      }
  });
}
