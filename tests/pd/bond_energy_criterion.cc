// The "critical bond energy" fracture criterion.
// 1. Its bond energies split the LPS strain energy exactly: sum over bonds of
//    (t_ij + t_ji) e / 2 V v = sum_I W_I V on a random displacement field of strain about
//    1e-2 with a pre-crack (broken bonds, surfaces, the deviatoric-moment term), in 2D plane
//    stress, plane strain and 3D. The model's energy is a homogeneous quadratic form of the
//    bond extensions, so this holds to round-off if t = dW/de / (V v): tolerance 1e-12
//    relative (sums of 1e4-1e5 terms of one sign-varying kind).
// 2. Two particles 1 mm apart, one held, one pulled along the bond with u = U sin(pi t / T):
//    the single bond's energy is w = e^2 (k c^2 + b (1 - c/3)^2) / (dx^2 V v) (theta = c e /
//    dx, e_d = e (1 - c/3), written out from the model's definition: 4 K + 4 mu / 3 in plane
//    strain, 9 K in 3D), and w_c = G0 / sum over the lattice offsets xi with xi_0 > 0 of
//    xi_0 V v (eq. 22's partial volumes, computed here): the cut of a lattice plane costs G0.
//    The bond must break at the first step with w >= w_c, exactly, and stay broken; pushed
//    instead (u < 0, the same energy) it must not break.

#include "single_bond.h"

using namespace PeriArlequinTests;

template <int dim>
void
energy_split(const std::string &model)
{
  auto simulator = make_simulator<dim>(cracked_random_block<dim>(model));
  simulator->setup();
  auto &pd = *simulator->get_pd_zone();
  pd.compute_internal_forces();
  const double strain_energy = pd.strain_energy();

  const auto         &bonds = pd.get_bonds();
  std::vector<double> pair_energy;
  pd.get_material_model().compute_pair_energies(bonds,
                                                pd.get_state().displacements(),
                                                pd.particle_scalars(),
                                                pair_energy);
  double sum = 0;
  for (unsigned int i = 0; i < bonds.n_owned; ++i)
    for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
      sum += pair_energy[n] * pd.particle_volume() * bonds.stencil[bonds.stencil_index[n]].volume;
  const std::string title = std::to_string(dim) + "D " + (dim == 2 ? model + " " : "");
  report(title + "broken bonds", pd.n_global_broken_bonds());
  check(title + "sum of bond energies / strain energy", sum / strain_energy, 1., 1e-12);
}

/** sum over the lattice offsets xi with xi_0 > 0 of xi_0 dx^dim v(|xi|) (eq. 22). */
template <int dim>
double
cut_per_unit_area(const double dx, const double delta)
{
  const int reach = static_cast<int>(std::ceil(delta / dx + 0.5));
  double    sum   = 0;
  for (int i = 1; i <= reach; ++i)
    for (int j = -reach; j <= reach; ++j)
      for (int k = (dim == 3 ? -reach : 0); k <= (dim == 3 ? reach : 0); ++k)
        {
          const double x = dx * std::sqrt(double(i * i + j * j + k * k));
          const double v = x <= delta - dx / 2 ? 1. : (delta - x) / dx + 0.5;
          if (v > 0)
            sum += i * dx * std::pow(dx, dim) * v;
        }
  return sum;
}

template <int dim>
void
single_bond(const double sign)
{
  // The case of single_bond.h: dx = 1 mm, E = 69 GPa, nu = 0.3, m = 3.015.
  const double dx = 1e-3, G0 = 100., E = 69e9, nu = 0.3, delta = 3.015 * dx;
  const double K = E / (3 * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double bond_volume = std::pow(dx, dim);
  const double stiffness   = dim == 3 ? 9 * K : 4 * K + 4 * mu / 3;
  const double w_c         = G0 / cut_per_unit_area<dim>(dx, delta);
  const double e_c         = std::sqrt(w_c * dx * dx * bond_volume / stiffness);
  const double U = 2 * e_c, T = 1e-4;
  auto         simulator =
    make_simulator<dim>(single_bond_case<dim>("plane strain",
                                              "  set Fracture criterion = critical bond energy\n",
                                              G0,
                                              sign * U,
                                              T));
  simulator->setup();
  const auto        run = run_single_bond(*simulator, sign * U, T, [&](const double e) {
    return e > 0 && stiffness * e * e / (dx * dx * bond_volume) >= w_c;
  });
  const std::string title =
    std::to_string(dim) + "D single bond " + (sign > 0 ? "pulled" : "pushed");
  if (sign > 0)
    {
      report(title + ": expected breaking step", run.expected_step);
      check(title + ": breaking step - first step with w >= w_c",
            run.breaking_step - run.expected_step,
            0,
            0);
      check(title + ": bond stays broken after the stretch falls (1 = yes)",
            run.stays_broken,
            1,
            0);
    }
  else
    check(title + ": breaking step (-1: never)", run.breaking_step, -1, 0);
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    energy_split<2>("plane stress");
    energy_split<2>("plane strain");
    energy_split<3>("");
    for (const double sign : {1., -1.})
      {
        single_bond<2>(sign);
        single_bond<3>(sign);
      }
  });
}
