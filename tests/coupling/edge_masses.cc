// How the masses at the overlap edges are handled (strip case, weak coupling, energy
// blending; overlap 0.4 <= |x| <= 0.5, alpha = (|x| - 0.4) / 0.1, FE cells h = 20 mm):
//  - FE: the lumped mass of a node is int alpha rho N_I. Nodes at the alpha = 0 edge keep a
//    finite mass from the overlap cell beside them: written out, int_0^h (s / 0.1)(1 - s / h)
//    ds / h = h / (6 * 0.1) = 1/30 of a pure-FE node's mass (same row of the mesh). Nodes
//    inside the pure PD zone carry no DoFs at all (FE_Nothing cells). Checked for every node:
//    mass / (that of a pure-FE node of the same row) = int alpha N_I / int N_I, written out
//    for Q1 with alpha linear (tolerance 1e-12: exact integrals of polynomials).
//    Slaves (particles with 1 - alpha below `Minimum PD weight` = 0.1, here those with
//    0.49 < |x| < 0.5 that carry a mass, and the massless ones beyond) move with the FE field
//    and add their masses to the FE nodes: N_I(x_s) (1 - alpha_s) rho V, with N_I the
//    bilinear hat of node I, written out here from the lattice.
//  - PD: the mass of a non-slave particle is (1 - alpha_I) rho V with 1 - alpha_I >= 0.1
//    (nothing is floored, so a free particle's mass matches its stiffness). Checked against
//    a pure-PD particle's mass (tolerance 1e-12).
//  - Mass is conserved: FE plus PD masses of one component = rho x plate area (the lattice
//    sums of the piecewise linear 1 - alpha are exact, its kinks lie on lattice-cell edges;
//    tolerance 1e-12).
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
    const auto   hat = [&](const double x) { return 1. - std::abs(x - x_node) / h; };
    const double m   = a + h / 2;
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
        const double row      = (std::abs(std::abs(y) - 0.04) < 1e-12) ? 0.5 : 1.;
        double       expected = share_x * row * full_row_mass;
        // The slaves with a mass: lattice sites (5 mm, from the corner (-1.2, -0.04)) with
        // 0.49 < |x| < 0.5.
        for (const double xs : {-0.4975, -0.4925, 0.4925, 0.4975})
          for (unsigned int j = 0; j < 16; ++j)
            {
              const double ys    = -0.04 + 0.0025 + 0.005 * j;
              const double hat_x = std::max(0., 1. - std::abs(xs - x) / h);
              const double hat_y = std::max(0., 1. - std::abs(ys - y) / h);
              expected += hat_x * hat_y * (0.5 - std::abs(xs)) / 0.1 * 2700 * 0.005 * 0.005;
            }
        fe_error =
          std::max(fe_error,
                   std::abs(fe.lumped_mass().local_element(dofs[k]) - expected) / full_row_mass);
        if (std::abs(x) < 0.5)
          smallest_share = std::min(smallest_share, share_x);
      }
    fe_error = Utilities::MPI::max(fe_error, MPI_COMM_WORLD);
    report("smallest FE mass share of an overlap node (1/30 at the alpha = 0 edge)",
           smallest_share);
    check_below("FE lumped masses vs int alpha rho N_I + the slaves' N_I m_s, relative to a "
                "pure-FE node",
                fe_error,
                1e-12);

    // PD
    auto        &pd        = *simulator->get_pd_zone();
    const double full_mass = 2700 * 0.005 * 0.005;
    double       pd_error = 0, smallest_free_weight = 1, pd_total = 0;
    unsigned int slaves_with_mass = 0;
    for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
      {
        const double weight = 1. - pd.blending_weights()[i];
        if (pd.is_slave(i))
          slaves_with_mass += (weight > 0);
        else
          {
            pd_error = std::max(pd_error, std::abs(pd.particle_mass(i) / full_mass - weight));
            smallest_free_weight = std::min(smallest_free_weight, weight);
            pd_total += pd.particle_mass(i);
          }
      }
    check_above("slaves with a mass", Utilities::MPI::sum(slaves_with_mass, MPI_COMM_WORLD), 0);
    check_above("smallest weight 1 - alpha of a free PD particle",
                Utilities::MPI::min(smallest_free_weight, MPI_COMM_WORLD),
                0.1 - 1e-12);
    check_below("PD masses vs (1 - alpha) rho V, relative",
                Utilities::MPI::max(pd_error, MPI_COMM_WORLD),
                1e-12);

    double fe_total = 0;
    for (unsigned int k = 0; k < dofs.size(); ++k)
      if (components[k] == 0)
        fe_total += fe.lumped_mass().local_element(dofs[k]);
    const double total = Utilities::MPI::sum(fe_total + pd_total, MPI_COMM_WORLD);
    check_below("FE + PD mass vs rho x area, relative",
                std::abs(total / (2700 * 2.4 * 0.08) - 1.),
                1e-12);

    auto reference = make_simulator<2>(text("none", true));
    reference->setup();
    const double ratio = simulator->get_stable_time_step() / reference->get_stable_time_step();
    report("stable step, coupled / pure PD", ratio);
    check_above("stable step, coupled / pure PD", ratio, 0.95);
  });
}
