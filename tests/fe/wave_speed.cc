// A smooth longitudinal pulse released at rest splits into two halves that travel at the
// plane longitudinal wave speed: sqrt(E / (rho (1 - nu^2))) in a 2D plane-stress strip and
// sqrt((K + 4 mu / 3) / rho) in 3D (P-wave), the lateral faces on rollers so that the strain is
// uniaxial. The speed is measured from the run: the centroid of u_x of the right-moving half
// at two times after the halves have separated.
//
// Tolerance 1 %: the pulse spans 40 (2D) and 30 (3D) cells, where the group-velocity error
// of lumped-mass Q1 with central differences at half the stable step is below 0.3 %; the
// centroid of the smooth pulse moves at that group velocity.

#include "../tests.h"

using namespace PeriArlequinTests;

template <int dim>
double
centroid_right_of(const PeriArlequin::Simulator<dim>               &simulator,
                  const LinearAlgebra::distributed::Vector<double> &coordinate,
                  const LinearAlgebra::distributed::Vector<double> &is_x,
                  const double                                      x0)
{
  const auto &u          = simulator.get_displacement();
  double      moments[2] = {0, 0};
  for (unsigned int i = 0; i < u.locally_owned_size(); ++i)
    if (is_x.local_element(i) > 0.5 && coordinate.local_element(i) > x0)
      {
        moments[0] += u.local_element(i) * coordinate.local_element(i);
        moments[1] += u.local_element(i);
      }
  Utilities::MPI::sum(ArrayView<const double>(moments, 2),
                      MPI_COMM_WORLD,
                      ArrayView<double>(moments, 2));
  return moments[0] / moments[1];
}

template <int dim>
void
measure_wave_speed()
{
  const double       x0 = dim == 2 ? 2.25 : 2.5;
  std::ostringstream prm;
  prm << "set Dimension = " << dim << "\n"
      << "subsection Geometry\n"
      << (dim == 2 ? "  set Lower corner = 0, 0\n  set Upper corner = 4.5, 0.02\n"
                     "  set Subdivisions = 450, 2\n" :
                     "  set Lower corner = 0, 0, 0\n  set Upper corner = 5, 0.04, 0.04\n"
                     "  set Subdivisions = 250, 2, 2\n")
      << "end\n"
      << "subsection Material\n  set Young's modulus = 69e9\n  set Poisson's ratio = 0.3\n"
      << "  set Density = 2700\n  set Two-dimensional model = plane stress\nend\n"
      << "subsection Time\n  set Time step = " << (dim == 2 ? 9e-7 : 1.7e-6)
      << "\n  set End time = 1\nend\n"
      << "subsection Initial conditions\nsubsection function\n  subsection Displacement\n"
      << "    set Function constants = x0=" << x0 << ", w=" << (dim == 2 ? 0.4 : 0.6) << "\n"
      << "    set Function expression = if(abs(x-x0) < w/2, 1e-5*(1+cos(2*pi*(x-x0)/w)), 0)"
      << (dim == 2 ? "; 0" : "; 0; 0") << "\n  end\nend\nend\n"
      << "subsection Boundary conditions\n";
  for (unsigned int b = 2; b < 2 * dim; ++b)
    prm << "  subsection Boundary " << b << "\n    set Type = displacement\n"
        << "    set Components = " << (b < 4 ? "y" : "z") << "\n  end\n";
  prm << "end\n" << quiet_output();

  auto simulator = make_simulator<dim>(prm.str());
  simulator->setup();
  LinearAlgebra::distributed::Vector<double> coordinate, is_x;
  dof_coordinates(simulator->get_fe_zone(), coordinate, is_x);

  const auto  &material = simulator->get_fe_zone().get_material();
  const double E = material.youngs_modulus, nu = material.poissons_ratio, rho = material.density;
  const double expected =
    dim == 2 ? std::sqrt(E / (rho * (1 - nu * nu))) :
               std::sqrt((material.bulk_modulus() + 4. / 3. * material.shear_modulus()) / rho);
  // Sample once the halves are apart (each has moved more than the pulse width), and again
  // 1 m further on, before either half reaches an end of the bar.
  const double t1 = 1.5 * (dim == 2 ? 0.4 : 0.6) / expected, t2 = t1 + 1.0 / expected;
  double       c1 = 0, c2 = 0, s1 = 0, s2 = 0;
  while (simulator->get_time() < t2)
    {
      simulator->advance();
      const double t = simulator->get_time();
      if (c1 == 0 && t >= t1)
        c1 = centroid_right_of(*simulator, coordinate, is_x, x0), s1 = t;
      if (t >= t2)
        c2 = centroid_right_of(*simulator, coordinate, is_x, x0), s2 = t;
    }
  const double measured = (c2 - c1) / (s2 - s1);
  check(std::to_string(dim) + "D longitudinal wave speed / analytic",
        measured / expected,
        1.,
        0.01);
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    measure_wave_speed<2>();
    measure_wave_speed<3>();
  });
}
