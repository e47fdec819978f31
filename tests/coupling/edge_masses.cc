// How the masses at the overlap edges are handled (strip case, weak coupling, energy
// blending; overlap 0.4 <= |x| <= 0.5, alpha = (|x| - 0.4) / 0.1, FE cells h = 20 mm):
//  - FE: the lumped mass of a node is int alpha rho N_I. Nodes at the alpha = 0 edge keep a
//    finite mass from the overlap cell beside them: written out, int_0^h (s / 0.1)(1 - s / h)
//    ds / h = h / (6 * 0.1) = 1/30 of a pure-FE node's mass (same row of the mesh). Nodes
//    inside the pure PD zone carry no DoFs at all (FE_Nothing cells). Checked for every node:
//    mass / (that of a pure-FE node of the same row) = int alpha N_I / int N_I, written out
//    for Q1 with alpha linear (tolerance 1e-12: exact integrals of polynomials).
//  - PD: the mass of a non-slave particle is max(1 - alpha_I, 0.1) rho V (the floor, the
//    `Minimum PD mass weight`, keeps finite masses next to the alpha = 1 edge). Checked
//    against a pure-PD particle's mass (tolerance 1e-12), with the floor active on some.
//  - The coupled stable step is not below the pure-PD strip's: no vanishing mass lowers it
//    (bound 0.95 of the pure-PD step; measured ratio reported).

#include "coupled_cases.h"

using namespace PeriArlequinTests;

namespace
{
  /** int alpha N dx over the 1D cell [a, a + h] for the hat N of the node at @p x_node. */
  double
  weighted_share(const double a, const double h, const double x_node)
  {
    const auto alpha = [](const double x) {
      return std::min(1., std::max(0., (std::abs(x) - 0.4) / 0.1));
    };
    // Simpson's rule is exact for the quadratic alpha * N on a cell where alpha is linear.
    const auto hat = [&](const double x) { return 1. - std::abs(x - x_node) / h; };
    const double m = a + h / 2;
    return h / 6 * (alpha(a) * hat(a) + 4 * alpha(m) * hat(m) + alpha(a + h) * hat(a + h));
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const auto text = [](const std::string &method, const bool all_pd) {
      return strip_case(method, "energy", "cg", false, all_pd, "0; 0", "0; 0", 1e-7, 1e-7, 1);
    };
    auto simulator = make_simulator<2>(text("weak", false));
    simulator->setup();

    // FE
    const auto               &fe = simulator->get_fe_zone();
    std::vector<unsigned int> dofs, components;
    std::vector<Point<2>>     points;
    fe.support_points(dofs, points, components);
    const double h = 0.02, full_row_mass = 2700 * h * h; // interior node of a pure-FE row
    double       fe_error = 0, smallest_share = 1;
    for (unsigned int k = 0; k < dofs.size(); ++k)
      {
        const double x = points[k][0], y = points[k][1];
        // 1D shares along x (the cells on both sides of the node inside the strip
        // [-1.2, 1.2]), times the y-row factor
        const double share_x = ((x > -1.2 + 1e-12 ? weighted_share(x - h, h, x) : 0.) +
                                (x < 1.2 - 1e-12 ? weighted_share(x, h, x) : 0.)) /
                               h;
        const double row = (std::abs(std::abs(y) - 0.04) < 1e-12) ? 0.5 : 1.;
        const double expected = share_x * row * full_row_mass;
        fe_error = std::max(fe_error,
                            std::abs(fe.lumped_mass().local_element(dofs[k]) - expected) /
                              full_row_mass);
        if (std::abs(x) < 0.5)
          smallest_share = std::min(smallest_share, share_x);
      }
    fe_error = Utilities::MPI::max(fe_error, MPI_COMM_WORLD);
    report("smallest FE mass share of an overlap node (1/30 at the alpha = 0 edge)",
           smallest_share);
    check_below("FE lumped masses vs int alpha rho N_I, relative to a pure-FE node",
                fe_error,
                1e-12);

    // PD
    auto        &pd        = *simulator->get_pd_zone();
    const double full_mass = 2700 * 0.005 * 0.005;
    double       pd_error  = 0;
    unsigned int floored   = 0;
    for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
      if (!pd.is_slave(i))
        {
          const double weight = std::max(1. - pd.blending_weights()[i], 0.1);
          pd_error = std::max(pd_error, std::abs(pd.particle_mass(i) / full_mass - weight));
          floored += (1. - pd.blending_weights()[i] < 0.1);
        }
    report("PD particles on the mass floor", Utilities::MPI::sum(floored, MPI_COMM_WORLD));
    check_above("PD particles on the mass floor", Utilities::MPI::sum(floored, MPI_COMM_WORLD), 0);
    check_below("PD masses vs max(1 - alpha, 0.1) rho V, relative",
                Utilities::MPI::max(pd_error, MPI_COMM_WORLD),
                1e-12);

    auto reference = make_simulator<2>(text("none", true));
    reference->setup();
    const double ratio = simulator->get_stable_time_step() / reference->get_stable_time_step();
    report("stable step, coupled / pure PD", ratio);
    check_above("stable step, coupled / pure PD", ratio, 0.95);
  });
}
