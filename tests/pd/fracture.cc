// Fracture.
// 1. A single bond between two particles, one held and one pulled then released
//    (u = U sin(pi t / T)), breaks at the first step whose stretch exceeds the critical
//    stretch, which is s_c = sqrt(4 pi G0 / (9 E delta)) in plane stress,
//    sqrt(5 pi G0 / (12 E delta)) in plane strain and sqrt(5 G0 / (9 K delta)) in 3D
//    (written out here), and stays broken when the stretch falls back below it.
// 2. A plate with an edge pre-crack pulled apart slowly (top and bottom layers displaced by
//    +-U (1 - cos(pi t / T)) / 2, far-field strain 0.5 s_c at the end) grows damage from the
//    crack tip: new broken bonds appear, all of them ahead of the tip and near the crack
//    line; the same plate without the pre-crack breaks no bond.
// 3. The weighted volume q of a particle whose bonds the pre-crack cuts is that of its full
//    initial family, sum over the lattice offsets of |xi|^2 V v with the partial volumes v of
//    eq. 22 (computed here): a pre-cut bond counts like a bond broken during the run, whose
//    breaking leaves q unchanged, so a given crack and a grown one act alike (exact to
//    round-off, 1e-12).

#include "plate.h"
#include "single_bond.h"

using namespace PeriArlequinTests;

template <int dim>
void
single_bond(const std::string &model = "plane stress")
{
  const double dx = 1e-3, G0 = 100., E = 69e9, nu = 0.3, delta = 3.015 * dx;
  const double s_c = dim == 3 ? std::sqrt(5 * G0 / (9 * (E / (3 * (1 - 2 * nu))) * delta)) :
                     model == "plane stress" ? std::sqrt(4 * numbers::PI * G0 / (9 * E * delta)) :
                                               std::sqrt(5 * numbers::PI * G0 / (12 * E * delta));
  const double U = 2 * s_c * dx, T = 1e-4;
  auto         simulator = make_simulator<dim>(single_bond_case<dim>(model, "", G0, U, T));
  simulator->setup();
  auto             &pd = *simulator->get_pd_zone();
  const std::string title =
    std::to_string(dim) + "D " + (dim == 2 ? model + " " : "") + "single bond";
  check(title + ": critical stretch / formula", pd.get_critical_stretch() / s_c, 1., 1e-12);
  const auto run = run_single_bond(*simulator, U, T, [&](const double e) { return e / dx > s_c; });
  report(title + ": expected breaking step", run.expected_step);
  report(title + ": breaking step", run.breaking_step);
  check(title + ": breaking step - first step with stretch > s_c",
        run.breaking_step - run.expected_step,
        0,
        0);
  check(title + ": bond stays broken after the stretch falls (1 = yes)", run.stays_broken, 1, 0);
}

/** sum over the lattice offsets of |xi|^2 dx^2 v(|xi|) with eq. 22's partial volume, 2D. */
double
full_family_weighted_volume(const double dx, const double delta)
{
  double     q     = 0;
  const auto reach = static_cast<int>(std::ceil(delta / dx + 0.5));
  for (int a = -reach; a <= reach; ++a)
    for (int b = -reach; b <= reach; ++b)
      {
        const double x = dx * std::sqrt(a * a + b * b);
        if ((a == 0 && b == 0) || x >= delta + dx / 2)
          continue;
        const double v = x <= delta - dx / 2 ? 1. : (delta - x) / dx + 0.5;
        q += x * x * dx * dx * v;
      }
  return q;
}

void
precracked_plate()
{
  auto cracked = make_simulator<2>(plate_parameters(4e-4, true, 500));
  cracked->run();
  auto        &pd     = *cracked->get_pd_zone();
  const auto   broken = cracked->get_energy_history().column("broken_bonds");
  const double dx = 4e-4, delta = 3.015 * dx;
  report("pre-cracked plate: bonds cut by the pre-crack", broken.front());
  report("pre-cracked plate: broken bonds at the end", broken.back());
  check_above("pre-cracked plate: new broken bonds", broken.back() - broken.front(), 20);
  // Every bond broken after the start lies ahead of the tip (x > 0.02 - delta), within a few
  // horizons of the crack line y = 0.02.
  double                    farthest_from_line = 0, tip = 0;
  const std::vector<double> damage = pd.get_bonds().damage();
  for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
    if (damage[i] > 0 && pd.reference_positions()[i][0] > 0.02 - delta)
      {
        farthest_from_line =
          std::max(farthest_from_line, std::abs(pd.reference_positions()[i][1] - 0.02));
        tip = std::max(tip, pd.reference_positions()[i][0]);
      }
  report("pre-cracked plate: damaged particles' largest distance from the crack line / delta",
         farthest_from_line / delta);
  check_above("pre-cracked plate: crack advance beyond the pre-crack tip / delta",
              (tip - 0.02) / delta,
              2.);
  check_below("pre-cracked plate: damage ahead of the tip within 3 horizons of the crack line",
              farthest_from_line / delta,
              3.);

  // The particle just above the crack line at x = 10 mm: far from every boundary, with the
  // bonds across the line cut.
  const double q_full  = full_family_weighted_volume(dx, delta);
  double       q_error = -1;
  for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
    if (std::abs(pd.reference_positions()[i][0] - (0.01 + dx / 2)) < dx / 4 &&
        std::abs(pd.reference_positions()[i][1] - (0.02 + dx / 2)) < dx / 4)
      q_error = std::abs(pd.get_bonds().weighted_volume[i] / q_full - 1);
  q_error = Utilities::MPI::max(q_error, MPI_COMM_WORLD);
  check_above("pre-cracked plate: particle next to the crack line found", q_error, -0.5);
  check_below("pre-cracked plate: |q / q of the full family - 1| next to the crack line",
              q_error,
              1e-12);

  auto intact = make_simulator<2>(plate_parameters(4e-4, false, 500));
  intact->run();
  check("plate without pre-crack: broken bonds at the end",
        intact->get_energy_history().column("broken_bonds").back(),
        0,
        0);
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    single_bond<2>();
    single_bond<2>("plane strain");
    single_bond<3>();
    precracked_plate();
  });
}
