// The coupling's interpolation N (FE shape functions at the PD particles) against deal.II's
// own point evaluation, VectorTools::point_value (it locates each point's cell and evaluates
// the finite element field there by itself), on the strip case with a rough FE field: every
// DoF gets a pseudo-random value in [-1, 1] mm, so each row of N is tested on its own.
//  - slaves: after set_slave_displacements, d_i = (N u)_i must equal point_value(u, X_i);
//  - overlap particles (strict lambda-mesh, H = I): with d_i = point_value(u, X_i) the
//    constraint residual |g| = |N u - d| must vanish.
// Both are the same linear interpolation computed twice in round-off: tolerance 1e-12 of the
// field scale (1 mm; times sqrt(rows) for the residual norm).
// The transposes are applied by columns (each FE entry or multiplier gathers its terms), the
// operators by rows: each pair must be adjoint, s . (N u) = (N^T s) . u over the slaves and
// overlap nodes, and s . (H lambda) = (H^T s) . lambda for the multiplier grid of spacing 2
// (pseudo-random s and lambda). Sums of about 1e4 products of size 1e-3 in another order:
// tolerance 1e-12 of sum |s| |N u| (resp. |s| |H lambda|).

#include <periarlequin/coupling/multiplier_space.h>

#include <deal.II/fe/mapping_q.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/numerics/vector_tools_point_value.h>

#include "coupled_cases.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

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

    // Adjoints. A pseudo-random vector per row, from the row number.
    const auto rough = [](const unsigned int k) {
      return Tensor<1, 2>({std::sin(3.7 * k + 1.3 * std::sin(2.1 * k)), std::cos(5.3 * k)});
    };
    // The rows' side s.(A x) against the columns' (A^T s).x, relative to the sum of |s| |A x|.
    const auto check_adjoint = [](const std::string                                &name,
                                  const std::string                                &check_name,
                                  const double                                      rows_side,
                                  const double                                      scale,
                                  const LinearAlgebra::distributed::Vector<double> &transposed,
                                  const LinearAlgebra::distributed::Vector<double> &x) {
      double columns_side = 0;
      for (unsigned int i = 0; i < x.locally_owned_size(); ++i)
        columns_side += transposed.local_element(i) * x.local_element(i);
      report(name, rows_side);
      check_below(check_name, std::abs(rows_side - columns_side) / scale, 1e-12);
    };
    std::vector<unsigned int> coupled, overlap_nodes;
    std::vector<Point<2>>     overlap_positions;
    for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
      if (pd.is_slave(i) || pd.blending_weights()[i] > 0)
        {
          coupled.push_back(i);
          if (!pd.is_slave(i))
            {
              overlap_nodes.push_back(i);
              overlap_positions.push_back(pd.reference_positions()[i]);
            }
        }
    InterpolationOperator<2> N;
    N.reinit(fe, pd, coupled);
    InterpolationOperator<2>::Values s(N.n_rows());
    double                           rows_side = 0, scale = 0;
    for (unsigned int r = 0; r < N.n_rows(); ++r)
      {
        s[r]                     = rough(r);
        const Tensor<1, 2> value = N.interpolate(u, r);
        rows_side += s[r] * value;
        scale += s[r].norm() * value.norm();
      }
    LinearAlgebra::distributed::Vector<double> transposed;
    fe.initialize_vector(transposed);
    N.Tvmult(transposed, s);
    check_adjoint("N: s . (N u)",
                  "N: |s . (N u) - (N^T s) . u| / sum |s| |N u|",
                  rows_side,
                  scale,
                  transposed,
                  u);

    InterpolationOperator<2> overlap;
    overlap.reinit(fe, pd, overlap_nodes);
    GridMultiplierSpace<2>                     grid(overlap, fe, overlap_positions, 2., 0.);
    LinearAlgebra::distributed::Vector<double> lambda, grid_transposed;
    grid.initialize_vector(lambda);
    grid.initialize_vector(grid_transposed);
    for (unsigned int m = 0; m < lambda.locally_owned_size(); ++m)
      lambda.local_element(m) = rough(m)[0];
    InterpolationOperator<2>::Values at_nodes, t(overlap.n_rows());
    grid.apply_h(lambda, at_nodes);
    double grid_rows_side = 0, grid_scale = 0;
    for (unsigned int r = 0; r < overlap.n_rows(); ++r)
      {
        t[r] = rough(r + 7);
        grid_rows_side += t[r] * at_nodes[r];
        grid_scale += t[r].norm() * at_nodes[r].norm();
      }
    grid.apply_transpose_h(t, grid_transposed);
    check_adjoint("H: t . (H lambda)",
                  "H: |t . (H lambda) - (H^T t) . lambda| / sum |t| |H lambda|",
                  grid_rows_side,
                  grid_scale,
                  grid_transposed,
                  lambda);
  });
}
