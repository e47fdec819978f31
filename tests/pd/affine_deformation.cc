// LPS under an affine displacement d = G x, particles with a full horizon:
//  - zero net force on particles more than two horizons inside (relative to the largest force on
//  the free surface, 1e-10: round-off);
//  - under a pure dilatation (equi-biaxial in plane stress, equi-triaxial in 3D) the strain
//    energy density equals the classical 1/2 sigma:eps to 1e-10 (it is exact: e = eps x);
//  - under uniaxial strain and shear it equals 1/2 sigma:eps times the lattice quadrature
//    factor of the partial-volume sums, which an independent lattice-sum computation gives
//    (omega = 1, eq. 22 partial volumes, small strain) as: 3D m = 3.015: uniaxial 1.00691,
//    shear e_xy 0.98791; m = 4.015: 1.00012, 0.99978; 2D plane stress m = 3.015: 1.01349,
//    0.96145; m = 4.015: 1.00142, 0.99593. Reproduced to 1e-4 (the figures' last digit;
//    the geometric nonlinearity at strain 1e-7 is 1e-7).
// Plane strain LPS is checked the same way: exact under dilatation, and under shear the
// plane-stress factors (theta = 0 there and the deviatoric modulus is the same).
// The classical energies are written out here from E and nu.

#include "../tests.h"

using namespace PeriArlequinTests;

template <int dim>
void
check_affine(const double          m,
             const std::string    &model,
             const std::string    &name,
             const Tensor<2, dim> &G,
             const double          expected_ratio,
             const double          tolerance)
{
  const double dx = 1e-3, E = 69e9, nu = 0.3, mu = E / (2 * (1 + nu));
  const double lambda = dim == 2 && model == "plane stress" ? E * nu / (1 - nu * nu) :
                                                              E * nu / ((1 + nu) * (1 - 2 * nu));
  const SymmetricTensor<2, dim> strain = symmetrize(G);
  const double                  classical =
    0.5 * (lambda * trace(strain) * trace(strain) + 2 * mu * strain * strain);

  // A block of 25 (2D) or 20 (3D) lattice spacings; cells 5 dx wide hold the horizon.
  const unsigned int n = dim == 2 ? 25 : 20;
  Point<dim>         upper;
  for (unsigned int d = 0; d < dim; ++d)
    upper[d] = n * dx;
  std::ostringstream prm, expression;
  expression << std::setprecision(17);
  const char *axis[] = {"x", "y", "z"};
  for (unsigned int i = 0; i < dim; ++i)
    {
      expression << (i ? "; " : "");
      for (unsigned int j = 0; j < dim; ++j)
        expression << (j ? " + " : "") << G[i][j] << "*" << axis[j];
    }
  prm << "set Dimension = " << dim << "\n"
      << "subsection Geometry\n  set Lower corner = " << (dim == 2 ? "0, 0" : "0, 0, 0")
      << "\n  set Upper corner = "
      << box_text<dim>(upper, upper).substr(box_text<dim>(upper, upper).find(':') + 2)
      << "\n  set Subdivisions = " << (dim == 2 ? "5, 5" : "4, 4, 4") << "\nend\n"
      << "subsection Material\n  set Young's modulus = 69e9\n  set Poisson's ratio = 0.3\n"
      << "  set Two-dimensional model = " << model << "\nend\n"
      << "subsection Peridynamics\n  set Region = " << box_text<dim>(Point<dim>(), upper)
      << "\n  set Lattice spacing = " << dx << "\n  set Horizon factor = " << m << "\nend\n"
      << "subsection Time\n  set Time step = 1e-9\n  set Stability estimate iterations = 5\nend\n"
      << "subsection Initial conditions\nsubsection function\n  subsection Displacement\n"
      << "    set Function expression = " << expression.str() << "\n  end\nend\nend\n"
      << quiet_output();
  auto simulator = make_simulator<dim>(prm.str());
  simulator->setup();
  auto &pd = *simulator->get_pd_zone();

  // The force on a particle involves the dilatations of its neighbours: it sees no surface
  // if both its family and its neighbours' families are full.
  const double reach          = 2 * (m * dx + 0.5 * dx);
  double       interior_force = 0, largest_force = 0, energy = 0;
  unsigned int n_interior = 0;
  for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
    {
      largest_force = std::max(largest_force, pd.force_densities()[i].norm());
      bool interior = true;
      for (unsigned int d = 0; d < dim; ++d)
        interior = interior && pd.reference_positions()[i][d] > reach &&
                   pd.reference_positions()[i][d] < n * dx - reach;
      if (!interior)
        continue;
      ++n_interior;
      interior_force = std::max(interior_force, pd.force_densities()[i].norm());
      energy         = pd.energy_densities()[i]; // the same for every interior particle
    }
  AssertThrow(n_interior > 0, ExcMessage("no interior particle"));
  const std::string title = std::to_string(dim) + "D " + (dim == 2 ? model + " " : "") +
                            "m = " + std::to_string(m).substr(0, 5) + " " + name;
  report(title + ": interior particles", n_interior);
  check_below(title + ": max interior |force| / max surface |force|",
              interior_force / largest_force,
              1e-10);
  check(title + ": W_PD / W_classical", energy / classical, expected_ratio, tolerance);
}

template <int dim>
void
check_model(const double       m,
            const double       uniaxial,
            const double       shear,
            const std::string &model = "plane stress")
{
  const double   eps = 1e-7;
  Tensor<2, dim> dilatation, uniaxial_strain, shear_strain;
  for (unsigned int d = 0; d < dim; ++d)
    dilatation[d][d] = eps;
  uniaxial_strain[0][0] = eps;
  shear_strain[0][1] = shear_strain[1][0] = eps;
  check_affine<dim>(m, model, "pure dilatation", dilatation, 1., 1e-10);
  if (uniaxial > 0)
    check_affine<dim>(m, model, "uniaxial strain", uniaxial_strain, uniaxial, 1e-4);
  check_affine<dim>(m, model, "shear strain", shear_strain, shear, 1e-4);
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    check_model<2>(3.015, 1.01349, 0.96145);
    check_model<2>(4.015, 1.00142, 0.99593);
    // Plane strain: no tabulated uniaxial factor; under shear theta = 0 and the deviatoric
    // modulus 8 mu / q is that of plane stress, so the shear factors are the same.
    check_model<2>(3.015, 0, 0.96145, "plane strain");
    check_model<2>(4.015, 0, 0.99593, "plane strain");
    check_model<3>(3.015, 1.00691, 0.98791);
    check_model<3>(4.015, 1.00012, 0.99978);
  });
}
