// Patch test: an affine displacement u = G x (a uniform strain plus a rigid rotation) with the
// tractions sigma n that match it on every face, or with its own values prescribed on every
// face, is an equilibrium of the discrete model: F_ext - K u vanishes at every free DoF.
// Checked for Q1 and Q2 in 2D (plane stress and plane strain) and Q1 in 3D, on cells of
// aspect ratio 2. The strain energy u.K u / 2 equals V (lambda/2 tr(e)^2 + mu e:e) of the
// uniform strain (the rotation stores none). K u runs on the test's 2 threads (more rows than
// one thread's share) and on 1 thread, which must give the same bits; the test also runs on
// 2 ranks with the same verdicts.
//
// Tolerance 1e-10 of the force scale max |K u|: the residual is pure round-off (about 1e-15
// times the condition of the assembly sums), so anything above 1e-10 is a real defect. The
// energy to 1e-11 relative: it is the sum over the boundary nodes of u.f (the interior forces
// cancel to round-off); measured 3e-15 (3D Q1) to 5.5e-13 (2D Q2).

#include "../tests.h"

using namespace PeriArlequinTests;

template <int dim>
void
patch_test(const unsigned int degree, const std::string &model, const bool tractions)
{
  // G: strain e_xx = 1e-3, e_yy = -4e-4, e_xy = 3e-4 (e_zz, e_xz, e_yz too in 3D), rotation 2e-4.
  Tensor<2, dim> G;
  G[0][0] = 1e-3, G[1][1] = -4e-4, G[0][1] = 3e-4 + 2e-4, G[1][0] = 3e-4 - 2e-4;
  if (dim == 3)
    G[2][2] = 6e-4, G[0][2] = 1e-4, G[2][0] = 1e-4, G[1][2] = -2e-4, G[2][1] = -2e-4;

  // Hooke's law written out here: plane stress has lambda = E nu / (1 - nu^2).
  const double E = 69e9, nu = 0.3, mu = E / (2 * (1 + nu));
  const double lambda = dim == 2 && model == "plane stress" ? E * nu / (1 - nu * nu) :
                                                              E * nu / ((1 + nu) * (1 - 2 * nu));
  const SymmetricTensor<2, dim> strain = symmetrize(G);
  const SymmetricTensor<2, dim> stress =
    lambda * trace(strain) * unit_symmetric_tensor<dim>() + 2 * mu * strain;

  std::ostringstream prm;
  prm << std::setprecision(17) << "set Dimension = " << dim << "\n"
      << "subsection Geometry\n"
      << (dim == 2 ? "  set Lower corner = -0.1, 0.2\n  set Upper corner = 0.3, 0.4\n"
                     "  set Subdivisions = 32, 32\n" :
                     "  set Lower corner = -0.1, 0.2, 0\n  set Upper corner = 0.3, 0.4, 0.1\n"
                     "  set Subdivisions = 12, 12, 6\n")
      << "end\n"
      << "subsection Material\n  set Young's modulus = 69e9\n  set Poisson's ratio = 0.3\n"
      << "  set Two-dimensional model = " << (dim == 2 ? model : "plane stress") << "\nend\n"
      << "subsection Finite elements\n  set Polynomial degree = " << degree << "\nend\n"
      << "subsection Time\n  set Time step = 1e-9\nend\n";
  const char *axis[] = {"x", "y", "z"};
  std::string affine;
  for (unsigned int i = 0; i < dim; ++i)
    {
      std::ostringstream row;
      row << std::setprecision(17);
      for (unsigned int j = 0; j < dim; ++j)
        row << (j ? " + " : "") << G[i][j] << "*" << axis[j];
      affine += (i ? "; " : "") + row.str();
    }
  prm << "subsection Initial conditions\nsubsection function\n  subsection Displacement\n"
      << "    set Function expression = " << affine << "\n  end\nend\nend\n"
      << "subsection Boundary conditions\n";
  for (unsigned int b = 0; b < 2 * dim; ++b)
    {
      prm << "  subsection Boundary " << b << "\n";
      if (tractions)
        {
          prm << "    set Type = traction\n    subsection Function\n"
              << "      set Function expression = ";
          const double sign = b % 2 ? 1. : -1.;
          for (unsigned int i = 0; i < dim; ++i)
            prm << (i ? "; " : "") << sign * stress[i][b / 2];
          prm << "\n    end\n";
        }
      else
        prm << "    set Type = displacement\n    subsection Function\n"
            << "      set Function expression = " << affine << "\n    end\n";
      prm << "  end\n";
    }
  prm << "end\n" << quiet_output();

  auto simulator = make_simulator<dim>(prm.str());
  simulator->setup();
  const auto                                &fe_zone = simulator->get_fe_zone();
  LinearAlgebra::distributed::Vector<double> internal, external;
  fe_zone.initialize_vector(internal);
  fe_zone.initialize_vector(external);
  on_one_thread([&] { fe_zone.compute_internal_force(simulator->get_displacement(), internal); });
  const LinearAlgebra::distributed::Vector<double> one_thread_force = internal;
  fe_zone.compute_internal_force(simulator->get_displacement(), internal);
  unsigned int differing = 0;
  for (unsigned int i = 0; i < internal.locally_owned_size(); ++i)
    differing += internal.local_element(i) != one_thread_force.local_element(i);
  const double volume = dim == 2 ? 0.4 * 0.2 : 0.4 * 0.2 * 0.1;
  const double energy_density =
    lambda / 2 * trace(strain) * trace(strain) + mu * scalar_product(strain, strain);
  const double strain_energy = 0.5 * (simulator->get_displacement() * internal);
  fe_zone.compute_external_force(simulator->get_problem_data(), 0., external);
  const double scale = internal.linfty_norm();
  external -= internal;
  for (const auto &prescribed : fe_zone.prescribed_dofs(simulator->get_problem_data()))
    external.local_element(prescribed.local_index) = 0;
  const std::string name = std::to_string(dim) + "D Q" + std::to_string(degree) + " " +
                           (dim == 2 ? model + " " : std::string()) +
                           (tractions ? "tractions" : "prescribed displacements");
  report(name + ": force scale", scale);
  check_below(name + ": max |F_ext - K u| / max |K u| at free DoFs",
              external.linfty_norm() / scale,
              1e-10);
  check_below(name + ": |u.K u / 2 - V W(e)| / (V W(e))",
              std::abs(strain_energy - volume * energy_density) / (volume * energy_density),
              1e-11);
  check(name + ": DoFs whose K u differs between 2 threads and 1",
        Utilities::MPI::sum(differing, MPI_COMM_WORLD),
        0,
        0);
}

int
main(int argc, char **argv)
{
  return run_test(
    argc,
    argv,
    [] {
      require_two_threads();
      for (const bool tractions : {true, false})
        {
          patch_test<2>(1, "plane stress", tractions);
          patch_test<2>(2, "plane stress", tractions);
          patch_test<2>(1, "plane strain", tractions);
          patch_test<3>(1, "", tractions);
        }
    },
    2);
}
