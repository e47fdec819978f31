// The stable-step estimate 2 / sqrt(lambda_max(M^-1 K)) from power iterations is checked
// against what it predicts: integrated just below it (0.99 x) the free vibration of a body
// excited in all its modes stays bounded, just above it (1.01 x) it blows up. The integrator
// here is written out in the test (central differences u_{n+1} = 2 u_n - u_{n-1} + dt^2 a_n,
// equivalent to velocity Verlet), so the application's own step refusal is not involved.
//
// Tolerances: bounded = the energy norm after 3000 steps below 10 x its initial value (at
// 0.99 of the limit the scheme is neutrally stable); unstable = above 1e6 x after 500 steps
// (the top mode grows by |q| = 1.33 per step at 1.01 of the limit, and the modes within 0.1 %
// of it by at least 1.03). Both are decisive by many orders.

#include "../tests.h"

using namespace PeriArlequinTests;

template <int dim>
double
growth(const PeriArlequin::FEZone<dim> &fe_zone, const double dt, const unsigned int n_steps)
{
  using Vector = LinearAlgebra::distributed::Vector<double>;
  Vector previous, current, next, force;
  for (Vector *v : {&previous, &current, &next, &force})
    fe_zone.initialize_vector(*v);
  // Pseudo-random initial displacement: every mode, the highest included, is excited.
  for (unsigned int i = 0; i < current.locally_owned_size(); ++i)
    current.local_element(i) = 1e-6 * std::sin(1e3 * (i + 1) * (i + 3.7));
  previous               = current;
  const auto energy_norm = [&](const Vector &u) {
    fe_zone.compute_internal_force(u, force);
    return std::sqrt(u * force);
  };
  const double initial = energy_norm(current);
  const auto  &mass    = fe_zone.lumped_mass();
  for (unsigned int n = 0; n < n_steps; ++n)
    {
      fe_zone.compute_internal_force(current, force);
      for (unsigned int i = 0; i < current.locally_owned_size(); ++i)
        next.local_element(i) = 2 * current.local_element(i) - previous.local_element(i) -
                                dt * dt * force.local_element(i) / mass.local_element(i);
      previous.swap(current);
      current.swap(next);
    }
  return energy_norm(current) / initial;
}

template <int dim>
void
check_estimate()
{
  std::ostringstream prm;
  prm << "set Dimension = " << dim << "\n"
      << "subsection Geometry\n"
      << (dim == 2 ? "  set Lower corner = 0, 0\n  set Upper corner = 0.3, 0.1\n"
                     "  set Subdivisions = 30, 7\n" :
                     "  set Lower corner = 0, 0, 0\n  set Upper corner = 0.2, 0.1, 0.1\n"
                     "  set Subdivisions = 12, 5, 4\n")
      << "end\n"
      << "subsection Time\n  set Time step = 1e-9\nend\n"
      << quiet_output();
  auto simulator = make_simulator<dim>(prm.str());
  simulator->setup();
  const double estimate = simulator->get_stable_time_step();
  report(std::to_string(dim) + "D estimated stable step", estimate);
  check_below(std::to_string(dim) + "D energy growth at 0.99 x estimate",
              growth(simulator->get_fe_zone(), 0.99 * estimate, 3000),
              10);
  check_above(std::to_string(dim) + "D energy growth at 1.01 x estimate",
              growth(simulator->get_fe_zone(), 1.01 * estimate, 500),
              1e6);
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    check_estimate<2>();
    check_estimate<3>();
  });
}
