/**
 * The stress concentration at a hole by the static solve, PD around the hole coupled to FE.
 *
 * A plane-stress steel plate 100 x 50 mm with a central hole of radius a = 5 mm (d/W = 0.2),
 * pulled by sigma = 10 MPa on its x faces. The mesh is deal.II's plate_with_a_hole (the hole's
 * vertices on the circle, a 25 x 25 mm square of cells around it), written here as a Gmsh
 * file for Geometry/Mesh file.
 * - Pure FE (Q1, refined until the hole has 128 faces, rank 0 alone): the hoop strain at the
 *   poles (across the load) from a harmonic fit of the displacement of the hole's nodes,
 *   E eps_tt / sigma (= sigma_tt / sigma, sigma_rr = 0 on the free hole), against the
 *   solution for a hole in a strip of finite width (Howland; Kirsch's 3 for d/W -> 0), 3.133
 *   at d/W = 0.2 by the polynomial of Peterson's tables, Kt_net = 3 - 3.14 r + 3.667 r^2 -
 *   1.527 r^3, Kt = Kt_net / (1 - r). Tolerance 2 %: measured +0.45 % (+0.66 % on the mesh
 *   refined once more: the mesh's error is a few tenths of a percent), the polynomial's own
 *   accuracy (about 1 %) and the plate's finite length (4.5 diameters on each side).
 * - Coupled (the mesh refined twice, 1.1-4.8 mm cells): PD on the square around the hole
 *   (dx = 0.25 mm, horizon 3 dx), strict Arlequin coupling in a 5 mm band around it, FE
 *   beyond. The hoop strain of the particles of the hole's surface layer (a <= r < a + dx;
 *   the same harmonic fit) against the pure FE field's at the same points, by the static
 *   solve, twice: force blending by relaxation (1,785 steps of 80 ns, about 7 s), energy
 *   blending by conjugate gradients (561 iterations, about 4 s). The difference is the
 *   lattice's: measured -2.9 % (force) and -2.8 % (energy) at dx = 0.25 mm, -0.8 % (force) at
 *   dx = 0.125 mm (the surface layer's softness vanishes as the lattice is refined); the
 *   tolerance 4 % holds the coarser lattice and fails a coupling that strains the band: energy
 *   blending by relaxation, whose equilibrium is the explicit loop's rest state, not the
 *   constrained one (the constraint's residual drifts), gives -9.6 %.
 *   Rows of lattice sites lie on mesh lines here (y = 9.375 mm): each such site must become
 *   one particle (they were once lost, and the bond build stopped).
 * On 2 ranks: the same checks, and the ratios within 1e-6 of rank 0 alone (the ranks sum in
 * another order; both solves stop at |M a| <= 1e-8 |F|).
 */
#include <periarlequin/simulator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <sstream>

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  constexpr double E = 200e9, nu = 0.3, sigma = 10e6;
  constexpr double length = 0.1, width = 0.05, radius = 5e-3, square_half_side = 12.5e-3;
  const Point<2>   centre(0.5 * length, 0.5 * width);

  /** Harmonics of the fit: u_r = sum A_n cos(2 n theta), u_theta = sum B_n sin(2 n theta). */
  constexpr unsigned int n_harmonics = 5;

  /** Write the plate's mesh, @p refinements times refined on its curved hole (rank 0 writes). */
  void
  write_mesh(const std::string &file_name, const unsigned int refinements)
  {
    Triangulation<2> plate;
    const double     pad_x = 0.5 * length - square_half_side;
    const double     pad_y = 0.5 * width - square_half_side;
    GridGenerator::plate_with_a_hole(plate,
                                     radius,
                                     square_half_side,
                                     pad_y,
                                     pad_y,
                                     pad_x,
                                     pad_x,
                                     centre,
                                     0,
                                     1,
                                     1.,
                                     2,
                                     true);
    plate.refine_global(refinements);
    write_gmsh_on_root(plate, file_name);
  }

  std::string
  case_text(const std::string &mesh_file, const double time_step)
  {
    std::ostringstream text;
    text << "set Dimension = 2\n"
         << "subsection Geometry\n  set Mesh file = " << mesh_file << "\nend\n"
         << "subsection Material\n  set Young's modulus = " << E
         << "\n  set Poisson's ratio = " << nu
         << "\n  set Density = 7850\n  set Two-dimensional model = plane stress\nend\n"
         << opposite_tractions(sigma, 2, 0)
         << "subsection Time\n  set Integration = static then explicit\n  set Time step = "
         << time_step << "\n  set End time = " << 5 * time_step << "\nend\n"
         << "subsection Static solve\n  set Tolerance = 1e-8\nend\n"
         << quiet_output();
    return text.str();
  }

  /**
   * Hoop strain at the poles theta = +-90 deg (across the load) from displacements @p u at
   * points @p x around the hole: least-squares fits of u_r and u_theta by the harmonics of a
   * load symmetric about both axes, then eps_tt = (u_r + d u_theta / d theta) / r at the
   * points' mean radius.
   */
  double
  hoop_strain_at_poles(const std::vector<Point<2>> &x, const std::vector<Tensor<1, 2>> &u)
  {
    FullMatrix<double> normal_r(n_harmonics + 1), normal_t(n_harmonics);
    Vector<double>     rhs_r(n_harmonics + 1), rhs_t(n_harmonics);
    double             mean_radius = 0;
    for (unsigned int i = 0; i < x.size(); ++i)
      {
        const Tensor<1, 2> d     = x[i] - centre;
        const double       theta = std::atan2(d[1], d[0]);
        const Tensor<1, 2> e_r({std::cos(theta), std::sin(theta)});
        const Tensor<1, 2> e_t({-std::sin(theta), std::cos(theta)});
        mean_radius += d.norm() / x.size();
        for (unsigned int m = 0; m <= n_harmonics; ++m)
          {
            for (unsigned int n = 0; n <= n_harmonics; ++n)
              normal_r(m, n) += std::cos(2 * m * theta) * std::cos(2 * n * theta);
            rhs_r(m) += std::cos(2 * m * theta) * (u[i] * e_r);
          }
        for (unsigned int m = 1; m <= n_harmonics; ++m)
          {
            for (unsigned int n = 1; n <= n_harmonics; ++n)
              normal_t(m - 1, n - 1) += std::sin(2 * m * theta) * std::sin(2 * n * theta);
            rhs_t(m - 1) += std::sin(2 * m * theta) * (u[i] * e_t);
          }
      }
    normal_r.gauss_jordan();
    normal_t.gauss_jordan();
    Vector<double> radial(n_harmonics + 1), tangential(n_harmonics);
    normal_r.vmult(radial, rhs_r);
    normal_t.vmult(tangential, rhs_t);
    // At theta = 90 deg: cos(2 n theta) = (-1)^n, d/dtheta sin(2 n theta) = 2 n (-1)^n.
    double sum = 0;
    for (unsigned int n = 0; n <= n_harmonics; ++n)
      sum += (n % 2 ? -1 : 1) * radial(n);
    for (unsigned int n = 1; n <= n_harmonics; ++n)
      sum += (n % 2 ? -1 : 1) * 2. * n * tangential(n - 1);
    return sum / mean_radius;
  }

  /** The FE displacement of @p simulator (one rank) at @p points. */
  std::vector<Tensor<1, 2>>
  fe_displacement_at(const PeriArlequin::Simulator<2> &simulator,
                     const std::vector<Point<2>>      &points)
  {
    const auto &fe = simulator.get_fe_zone();
    auto        u  = fe.get_state().displacement;
    u.update_ghost_values();
    std::vector<Tensor<1, 2>> values;
    for (const auto &p : points)
      {
        const auto location = fe.locate(p);
        AssertThrow(location, ExcMessage("a point of the hole's layer outside the FE mesh"));
        values.push_back(fe.point_value(u, *location));
      }
    return values;
  }

  /** Pure FE on the fine mesh (rank 0 alone): the hoop strain at the poles from the hole's nodes.
   */
  std::unique_ptr<PeriArlequin::Simulator<2>>
  pure_fe_reference()
  {
    auto plate = make_simulator<2>(case_text("plate_fine.msh", 2e-8), MPI_COMM_SELF);
    plate->setup();
    const auto result = plate->solve_static();
    report("pure FE: static solve iterations", result.iterations);

    std::vector<unsigned int> dofs, components;
    std::vector<Point<2>>     points;
    plate->get_fe_zone().support_points(dofs, points, components);
    const auto &u = plate->get_fe_zone().get_state().displacement;
    std::map<std::pair<long, long>, std::pair<Point<2>, Tensor<1, 2>>> hole_nodes;
    for (unsigned int k = 0; k < dofs.size(); ++k)
      if (std::abs(points[k].distance(centre) - radius) < 1e-9)
        {
          auto &node =
            hole_nodes[{std::lround(points[k][0] * 1e9), std::lround(points[k][1] * 1e9)}];
          node.first                 = points[k];
          node.second[components[k]] = u.local_element(dofs[k]);
        }
    std::vector<Point<2>>     x;
    std::vector<Tensor<1, 2>> displacement;
    for (const auto &[key, node] : hole_nodes)
      {
        x.push_back(node.first);
        displacement.push_back(node.second);
      }
    report("pure FE: nodes on the hole", x.size());
    const double r       = 2 * radius / width;
    const double howland = (3 - 3.14 * r + 3.667 * r * r - 1.527 * r * r * r) / (1 - r);
    report("Howland's concentration factor", howland);
    check("pure FE: E eps_tt / sigma at the poles over Howland's",
          E * hoop_strain_at_poles(x, displacement) / sigma / howland,
          1,
          0.02);
    return plate;
  }

  /**
   * Coupled, PD (lattice @p spacing) on the square around the hole: the hoop strain at the
   * poles of the hole's surface layer of particles, over that of @p reference's FE field at
   * the same points. @p blending "force" is solved by relaxation, "energy" by conjugate
   * gradients.
   */
  double
  coupled_over_fe(const PeriArlequin::Simulator<2> *reference,
                  const double                      spacing,
                  const std::string                &blending,
                  const MPI_Comm                    communicator)
  {
    std::ostringstream pd;
    pd << "subsection Peridynamics\n  set Region = " << centre[0] - square_half_side << ", "
       << centre[1] - square_half_side << " : " << centre[0] + square_half_side << ", "
       << centre[1] + square_half_side << "\n  set Lattice spacing = " << spacing
       << "\n  set Horizon factor = 3\nend\n"
       << "subsection Coupling\n  set Method = strict\n  set Blending = " << blending
       << "\n  set Overlap width = 0.005\nend\n"
       << "subsection Static solve\n  set Method = "
       << (blending == "energy" ? "conjugate gradients" : "relaxation") << "\nend\n";
    const double time_step = 8e-8 * spacing / 2.5e-4; // 0.84 of the stable step
    auto         plate =
      make_simulator<2>(case_text("plate_coarse.msh", time_step) + pd.str(), communicator);
    plate->setup();
    const auto result = plate->solve_static();
    report("coupled, " + blending + " blending: iterations", result.iterations);

    const auto         &zone = *plate->get_pd_zone();
    const auto          x    = zone.reference_positions();
    const auto          u    = zone.get_state().displacements();
    std::vector<double> layer;
    for (unsigned int i = 0; i < zone.n_owned_particles(); ++i)
      if (const double r = x[i].distance(centre); r >= radius && r < radius + spacing)
        layer.insert(layer.end(), {x[i][0], x[i][1], u[i][0], u[i][1]});
    const auto gathered = Utilities::MPI::gather(communicator, layer);
    double     ratio    = 0;
    if (is_root())
      {
        std::vector<Point<2>>     points;
        std::vector<Tensor<1, 2>> displacements;
        for (const auto &part : gathered)
          for (unsigned int k = 0; k < part.size(); k += 4)
            {
              points.emplace_back(part[k], part[k + 1]);
              displacements.push_back(Tensor<1, 2>({part[k + 2], part[k + 3]}));
            }
        report("coupled: particles in the hole's surface layer", points.size());
        const double pd_strain = hoop_strain_at_poles(points, displacements);
        const double fe_strain =
          hoop_strain_at_poles(points, fe_displacement_at(*reference, points));
        report("coupled, " + blending + " blending: E eps_tt / sigma of the layer, PD",
               E * pd_strain / sigma);
        report("coupled: E eps_tt / sigma of the layer, pure FE", E * fe_strain / sigma);
        ratio = pd_strain / fe_strain;
      }
    return Utilities::MPI::broadcast(communicator, ratio, 0);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    write_mesh("plate_fine.msh", 4);
    write_mesh("plate_coarse.msh", 2);
    std::unique_ptr<PeriArlequin::Simulator<2>> reference;
    if (is_root())
      reference = pure_fe_reference();
    const double spacing = 2.5e-4;
    for (const std::string blending : {"force", "energy"})
      {
        const double ratio = coupled_over_fe(reference.get(), spacing, blending, MPI_COMM_WORLD);
        check("coupled, " + blending +
                " blending: hoop strain of the hole's surface layer over the pure FE one",
              ratio,
              1,
              0.04);
        if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
          {
            double difference = 0;
            if (is_root())
              difference = std::abs(
                coupled_over_fe(reference.get(), spacing, blending, MPI_COMM_SELF) - ratio);
            check_below("coupled, " + blending + " blending: |ratio - ratio of rank 0 alone|",
                        Utilities::MPI::broadcast(MPI_COMM_WORLD, difference, 0),
                        1e-6);
          }
      }
  });
}
