/**
 * The static solve against the problem size (benchmarks/static_solve_cost.sh runs it).
 *
 *   periarlequin-static-solve-cost CELLS_X [LATTICE_SPACING]
 *
 * The cantilever of tests/static/direct_solve (a plane-stress plate 100 x 20 mm clamped at
 * x = 0, an end shear; bending, the slow case for a relaxation) on CELLS_X x CELLS_X/5 Q1
 * cells. Without LATTICE_SPACING, pure FE, three ways to the same K u = f: the library's
 * dynamic relaxation (Static solve/Tolerance 1e-8), a sparse direct solve (UMFPACK) and
 * conjugate gradients with SSOR (relative residual 1e-10), each with its wall time and the
 * largest difference from the direct solution. With LATTICE_SPACING [m], the coupled model:
 * PD on [40, 60] mm over the full height, strict force-blended coupling in a band of two
 * cells, relaxed by the library (its iterations and wall time).
 */
#include <periarlequin/simulator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>

#include <iomanip>
#include <iostream>
#include <sstream>

#include "../tests/static/cantilever_system.h"

namespace
{
  using namespace dealii;
  using PeriArlequinTests::CantileverSystem;

  const std::string quiet = "subsection Output\n  set Output interval = 0\n"
                            "  set Energy interval = 0\n  set Progress interval = 0\n"
                            "  set Print timing summary = false\nend\n"
                            "subsection Static solve\n  set Tolerance = 1e-8\nend\n";

  /**
   * Solve the case @p text statically with the library's @p method: iterations, wall time
   * and the simulator.
   */
  std::unique_ptr<PeriArlequin::Simulator<2>>
  relax(const std::string &text, const std::string &method, unsigned int &iterations, double &wall)
  {
    ParameterHandler prm;
    PeriArlequin::Simulator<2>::declare_parameters(prm);
    prm.parse_input_from_string(text + "subsection Static solve\n  set Method = " + method +
                                "\nend\n");
    auto simulator = std::make_unique<PeriArlequin::Simulator<2>>(prm, MPI_COMM_WORLD);
    simulator->setup();
    Timer clock;
    iterations = simulator->solve_static().iterations;
    wall       = clock.wall_time();
    return simulator;
  }

  /** The largest difference of the FE displacements of @p simulator from @p exact. */
  double
  largest_error(
    const PeriArlequin::Simulator<2>                                                &simulator,
    const decltype(std::declval<CantileverSystem>().nodal_values(Vector<double>())) &exact)
  {
    std::vector<unsigned int> local_dofs, components;
    std::vector<Point<2>>     points;
    simulator.get_fe_zone().support_points(local_dofs, points, components);
    const auto &u     = simulator.get_fe_zone().get_state().displacement;
    double      error = 0;
    for (unsigned int k = 0; k < local_dofs.size(); ++k)
      error = std::max(error,
                       std::abs(u.local_element(local_dofs[k]) -
                                exact.at(CantileverSystem::key(points[k], components[k]))));
    return error;
  }

  void
  pure_fe(const unsigned int cells_x)
  {
    const unsigned int cells_y = cells_x / 5;
    Timer              clock;
    CantileverSystem   system(cells_x, cells_y);
    const double       assembly_wall = clock.wall_time();

    clock.restart();
    Vector<double>      direct(system.dofs.n_dofs());
    SparseDirectUMFPACK umfpack;
    umfpack.initialize(system.stiffness);
    umfpack.vmult(direct, system.load);
    const double direct_wall = clock.wall_time();

    clock.restart();
    Vector<double>           krylov(system.dofs.n_dofs());
    SolverControl            control(100000, 1e-10 * system.load.l2_norm());
    SolverCG<Vector<double>> cg(control);
    PreconditionSSOR<>       ssor;
    ssor.initialize(system.stiffness, 1.2);
    cg.solve(system.stiffness, krylov, system.load, ssor);
    const double krylov_wall = clock.wall_time();
    system.constraints.distribute(direct);
    system.constraints.distribute(krylov);
    const auto     exact      = system.nodal_values(direct);
    Vector<double> difference = krylov;
    difference -= direct;
    const double scale = direct.linfty_norm();

    // One line, printed at the end: the library's runs print their own lines.
    std::ostringstream line;
    line << std::setprecision(3) << "FE " << cells_x << " x " << cells_y << " cells, "
         << system.dofs.n_dofs() << " DoFs:";
    // The case's step matters for nothing here: the relaxation steps at 0.9 of the stable one.
    for (const std::string method : {"relaxation", "conjugate gradients"})
      {
        unsigned int iterations;
        double       wall;
        const auto   simulator = relax(CantileverSystem::case_text(cells_x, cells_y, 1e-9) + quiet,
                                     method,
                                     iterations,
                                     wall);
        line << " library " << method << " " << iterations << " iterations " << wall << " s (error "
             << largest_error(*simulator, exact) / scale << ");";
      }
    line << " assembly " << assembly_wall << " s; UMFPACK " << direct_wall << " s; CG-SSOR "
         << control.last_step() << " iterations " << krylov_wall << " s (error "
         << difference.linfty_norm() / scale << ")";
    std::cout << line.str() << std::endl;
  }

  /**
   * The coupled cantilever (PD on [40, 60] mm, lattice @p spacing) by force blending and
   * relaxation, and by energy blending and conjugate gradients: iterations, wall time, and
   * the largest FE displacement over that of the pure FE cantilever on the same mesh.
   */
  void
  coupled(const unsigned int cells_x, const double spacing)
  {
    const unsigned int cells_y   = cells_x / 5;
    const double       cell_size = CantileverSystem::length / cells_x;
    // The coupled solves step with the case's step: 0.8 of the lattice's stable step.
    const double time_step            = 0.8 * 0.4 * spacing / std::sqrt(CantileverSystem::E / 7800);
    const auto   largest_displacement = [](const PeriArlequin::Simulator<2> &simulator) {
      return simulator.get_fe_zone().get_state().displacement.linfty_norm();
    };
    unsigned int iterations;
    double       wall;
    const double pure_fe =
      largest_displacement(*relax(CantileverSystem::case_text(cells_x, cells_y, time_step) + quiet,
                                  "conjugate gradients",
                                  iterations,
                                  wall));
    std::ostringstream line;
    line << std::setprecision(3) << "coupled " << cells_x << " x " << cells_y << " cells, dx "
         << spacing << " m:";
    for (const auto &[blending, method] :
         {std::pair<std::string, std::string>{"force", "relaxation"},
          std::pair<std::string, std::string>{"energy", "conjugate gradients"}})
      {
        std::ostringstream pd;
        pd << "subsection Peridynamics\n  set Region = 0.04, 0 : 0.06, " << CantileverSystem::height
           << "\n  set Lattice spacing = " << spacing << "\n  set Horizon factor = 3\nend\n"
           << "subsection Coupling\n  set Method = strict\n  set Blending = " << blending
           << "\n  set Overlap width = " << 2 * cell_size << "\nend\n";
        const auto simulator =
          relax(CantileverSystem::case_text(cells_x, cells_y, time_step) + pd.str() + quiet,
                method,
                iterations,
                wall);
        line << " " << blending << " blending, " << method << ": "
             << simulator->get_pd_zone()->n_owned_particles() << " particles, " << iterations
             << " iterations " << wall << " s, largest FE displacement over pure FE's "
             << largest_displacement(*simulator) / pure_fe << ";";
      }
    std::cout << line.str() << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc < 2)
    {
      std::cerr << "usage: " << argv[0] << " CELLS_X [LATTICE_SPACING]\n";
      return 1;
    }
  try
    {
      const unsigned int cells_x = std::stoi(argv[1]);
      if (argc > 2)
        coupled(cells_x, std::stod(argv[2]));
      else
        pure_fe(cells_x);
    }
  catch (const std::exception &error)
    {
      std::cerr << error.what() << std::endl;
      return 1;
    }
  return 0;
}
