// The PD force is minus the derivative of the total strain energy: f_K V = -dE/du_K with
// E = sum_I W_I V, checked by central finite differences on a random displacement field of
// strain about 1e-2 (geometrically nonlinear), for LPS in 2D plane stress and in 3D, with a
// pre-crack so that broken bonds (and the deviatoric-moment term they activate) are covered.
// Particles are sampled in the bulk, at the surface and beside the crack.
//
// Tolerance 1e-6 relative to the largest sampled force: with steps h = 1e-6 dx the central
// difference has truncation error (h/u)^2 ~ 1e-8 and round-off eps E / h ~ 1e-8.

#include "../tests.h"

using namespace PeriArlequinTests;

template <int dim>
void
check_consistency()
{
  const double dx        = 1e-3;
  auto         simulator = make_simulator<dim>(cracked_random_block<dim>());
  simulator->setup();
  auto        &pd     = *simulator->get_pd_zone();
  const double volume = pd.particle_volume();
  report(std::to_string(dim) + "D broken bonds", pd.n_global_broken_bonds());
  AssertThrow(pd.n_global_broken_bonds() > 0, ExcMessage("the pre-crack cut no bond"));

  pd.compute_internal_forces();
  const auto                        densities = pd.force_densities();
  const std::vector<Tensor<1, dim>> force(densities.begin(), densities.end());
  const double                      h       = 1e-6 * dx;
  double                            largest = 0, worst = 0;
  // Bulk, corner, surface, beside the crack faces and at the crack tip (in units of the
  // block size L: 0.02 m in 2D, 0.01 m in 3D; the crack runs on y = L/2 + 0.1 dx, x < L/2).
  std::vector<Point<dim>> targets;
  const double            L = dim == 2 ? 0.02 : 0.01;
  for (const auto &fraction : std::vector<std::array<double, 3>>{{0.75, 0.25, 0.5},
                                                                 {0, 0, 0},
                                                                 {0.5, 1, 0.5},
                                                                 {0.25, 0.47, 0.5},
                                                                 {0.25, 0.53, 0.5},
                                                                 {0.5, 0.5, 0.5}})
    {
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = fraction[d] * L;
      targets.push_back(p);
    }
  for (const auto &target : targets)
    {
      unsigned int k = 0;
      for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
        if (pd.reference_positions()[i].distance(target) <
            pd.reference_positions()[k].distance(target))
          k = i;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const Tensor<1, dim> saved = pd.get_state().displacements()[k];
          Tensor<1, dim>       moved = saved;
          moved[d]                   = saved[d] + h;
          pd.set_displacement(k, moved);
          pd.compute_internal_forces();
          const double plus = pd.strain_energy();
          moved[d]          = saved[d] - h;
          pd.set_displacement(k, moved);
          pd.compute_internal_forces();
          const double minus = pd.strain_energy();
          pd.set_displacement(k, saved);
          const double derivative = (plus - minus) / (2 * h);
          largest                 = std::max(largest, std::abs(force[k][d] * volume));
          worst                   = std::max(worst, std::abs(force[k][d] * volume + derivative));
        }
    }
  check_below(std::to_string(dim) + "D max |f V + dE/du| / max |f V| over sampled particles",
              worst / largest,
              1e-6);
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    check_consistency<2>();
    check_consistency<3>();
  });
}
