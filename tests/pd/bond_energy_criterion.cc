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

#include "../tests.h"

using namespace PeriArlequinTests;

template <int dim>
void
energy_split(const std::string &model)
{
  const double dx = 1e-3;
  std::ostringstream prm;
  prm << "set Dimension = " << dim << "\n"
      << "subsection Geometry\n  set Lower corner = " << (dim == 2 ? "0, 0" : "0, 0, 0")
      << "\n  set Upper corner = " << (dim == 2 ? "0.02, 0.02" : "0.01, 0.01, 0.01")
      << "\n  set Subdivisions = " << (dim == 2 ? "5, 5" : "2, 2, 2") << "\nend\n"
      << (dim == 2 ? "subsection Material\n  set Two-dimensional model = " + model + "\nend\n" : "")
      << "subsection Peridynamics\n  set Region = "
      << (dim == 2 ? "0, 0 : 0.02, 0.02" : "0, 0, 0 : 0.01, 0.01, 0.01")
      << "\n  set Lattice spacing = " << dx << "\n"
      << "  set Pre-cracks = "
      << (dim == 2 ? "0, 0.0101 : 0.01, 0.0101" : "0, 0.0051, 0 : 0.005, 0, 0 : 0, 0, 0.01")
      << "\nend\n"
      << "subsection Time\n  set Time step = 1e-9\n  set Stability estimate iterations = 5\nend\n"
      << "subsection Initial conditions\nsubsection function\n  subsection Displacement\n"
      << "    set Function expression = 1e-5*sin(7e3*x*y+3e2*y+1); 1e-5*cos(5e3*x+4e5*x*y)"
      << (dim == 3 ? "; 1e-5*sin(3e3*z+2e5*x*y+9e2*x)" : "") << "\n  end\nend\nend\n"
      << quiet_output();
  auto simulator = make_simulator<dim>(prm.str());
  simulator->setup();
  auto &pd = *simulator->get_pd_zone();
  pd.compute_internal_forces();
  const double strain_energy = pd.strain_energy();

  const auto         &bonds = pd.get_bonds();
  std::vector<double> pair_energy;
  pd.get_material_model().compute_pair_energies(
    bonds, pd.get_state().displacements(), pd.particle_scalars(), pair_energy);
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
  const double dx = 1e-3, G0 = 100., E = 69e9, nu = 0.3, delta = 3.015 * dx;
  const double K = E / (3 * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double bond_volume = std::pow(dx, dim);
  const double stiffness   = dim == 3 ? 9 * K : 4 * K + 4 * mu / 3;
  const double w_c         = G0 / cut_per_unit_area<dim>(dx, delta);
  const double e_c         = std::sqrt(w_c * dx * dx * bond_volume / stiffness);
  const double U = 2 * e_c, T = 1e-4;
  std::ostringstream prm;
  prm << std::setprecision(17) << "set Dimension = " << dim << "\n"
      << "subsection Geometry\n  set Lower corner = " << (dim == 2 ? "0, 0" : "0, 0, 0")
      << "\n  set Upper corner = " << (dim == 2 ? "0.01, 0.01" : "0.01, 0.01, 0.01")
      << "\n  set Subdivisions = " << (dim == 2 ? "2, 2" : "2, 2, 2") << "\nend\n"
      << "subsection Material\n  set Young's modulus = " << E << "\n  set Poisson's ratio = "
      << nu << "\n  set Two-dimensional model = plane strain\nend\n"
      << "subsection Peridynamics\n  set Region = "
      << (dim == 2 ? "0, 0 : 0.002, 0.001" : "0, 0, 0 : 0.002, 0.001, 0.001")
      << "\n  set Lattice spacing = " << dx << "\n  set Fracture = true\n"
      << "  set Fracture criterion = critical bond energy\n"
      << "  set Critical energy release rate = " << G0 << "\n"
      << "  subsection Prescribed region 0\n    set Region = "
      << (dim == 2 ? "0, 0 : 0.001, 0.001" : "0, 0, 0 : 0.001, 0.001, 0.001") << "\n  end\n"
      << "  subsection Prescribed region 1\n    set Region = "
      << (dim == 2 ? "0.001, 0 : 0.002, 0.001" : "0.001, 0, 0 : 0.002, 0.001, 0.001")
      << "\n    subsection Function\n      set Function constants = U=" << sign * U
      << ", T=" << T << "\n      set Function expression = U*sin(pi*t/T); 0"
      << (dim == 3 ? "; 0" : "") << "\n    end\n  end\nend\n"
      << "subsection Time\n  set Time step = 2e-8\n  set End time = " << T << "\nend\n"
      << quiet_output();
  auto simulator = make_simulator<dim>(prm.str());
  simulator->setup();
  auto &pd = *simulator->get_pd_zone();
  AssertThrow(pd.n_global_particles() == 2 && pd.n_global_bonds() == 2,
              ExcMessage("expected two particles and one bond (stored at both ends)"));

  int  first_broken_step = -1, expected_step = -1;
  bool broken_after_release = true;
  for (int step = 1; simulator->get_time() < T * (1 - 1e-12); ++step)
    {
      simulator->advance();
      const double e = sign * U * std::sin(numbers::PI * simulator->get_time() / T);
      if (expected_step < 0 && e > 0 && stiffness * e * e / (dx * dx * bond_volume) >= w_c)
        expected_step = step;
      const auto broken = pd.n_global_broken_bonds();
      if (first_broken_step < 0 && broken == 2)
        first_broken_step = step;
      if (first_broken_step > 0 && broken != 2)
        broken_after_release = false;
    }
  const std::string title = std::to_string(dim) + "D single bond " + (sign > 0 ? "pulled" : "pushed");
  if (sign > 0)
    {
      report(title + ": expected breaking step", expected_step);
      check(title + ": breaking step - first step with w >= w_c", first_broken_step - expected_step, 0, 0);
      check(title + ": bond stays broken after the stretch falls (1 = yes)", broken_after_release, 1, 0);
    }
  else
    check(title + ": breaking step (-1: never)", first_broken_step, -1, 0);
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
