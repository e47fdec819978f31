// The coupling's interpolation N (FE shape functions at the PD particles) against deal.II's
// own point evaluation, VectorTools::point_value (it locates each point's cell and evaluates
// the finite element field there by itself), on the strip case with a rough FE field: every
// DoF gets a pseudo-random value in [-1, 1] mm, so each row of N is tested on its own.
//  - slaves: after set_slave_displacements, d_i = (N u)_i must equal point_value(u, X_i);
//  - overlap particles (strict lambda-mesh, H = I): with d_i = point_value(u, X_i) the
//    constraint residual |g| = |N u - d| must vanish.
// Both are the same linear interpolation computed twice in round-off: tolerance 1e-12 of the
// field scale (1 mm; times sqrt(rows) for the residual norm).

#include <deal.II/fe/mapping_q.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/numerics/vector_tools_point_value.h>

#include "coupled_cases.h"

using namespace PeriArlequinTests;

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    auto simulator = make_simulator<2>(
      strip_case("strict", "energy", "cg", false, false, "0; 0", "0; 0", 1e-7, 1e-7, 1));
    simulator->setup();
    const auto &dof_handler = simulator->get_fe_zone().get_dof_handler();
    auto       &fe          = simulator->get_fe_zone();
    const auto &u           = fe.get_state().displacement;
    // A rough field: pseudo-random per DoF, from the DoF's global index.
    unsigned int local = 0;
    for (const auto i : u.locally_owned_elements())
      fe.set_displacement(local++, 1e-3 * std::sin(12.9898 * i + 78.233 * std::sin(4.1414 * i)));
    u.update_ghost_values();

    auto &pd       = *simulator->get_pd_zone();
    auto &coupling = *simulator->get_coupling();
    coupling.set_slave_displacements();

    const hp::MappingCollection<2> mapping(MappingQ<2>(1));
    Vector<double>                 value(2);
    const auto                     interpolated = [&](const unsigned int i) {
      VectorTools::point_value(mapping, dof_handler, u, pd.reference_positions()[i], value);
      return Tensor<1, 2>({value[0], value[1]});
    };
    double       slave_error = 0;
    unsigned int n_slaves = 0, n_overlap = 0;
    for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
      if (pd.is_slave(i))
        {
          slave_error =
            std::max(slave_error, (pd.get_state().displacements()[i] - interpolated(i)).norm());
          ++n_slaves;
        }
      else if (pd.blending_weights()[i] > 0)
        {
          pd.set_displacement(i, interpolated(i));
          ++n_overlap;
        }
    report("slave particles checked", n_slaves);
    report("overlap particles checked", n_overlap);
    check_above("slave and overlap particles checked", std::min(n_slaves, n_overlap), 0);
    check_below("slaves: max |N u - point_value(u)| / 1 mm", slave_error / 1e-3, 1e-12);
    const double rows = std::sqrt(coupling.n_multipliers());
    check_below("overlap: |N u - point_value(u)| / (1 mm sqrt(rows))",
                coupling.constraint_residuals().first / (1e-3 * rows),
                1e-12);
  });
}
