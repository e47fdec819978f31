/**
 * The static solve (dynamic relaxation) of a pure-FE case against a direct solve of K u = f
 * assembled here, independently of the library: a cantilever plate 100 x 20 mm (plane
 * stress, E = 200 GPa, nu = 0.3, Q1 on 40 x 8 cells), clamped on x = 0 and loaded by a
 * shear traction of 1 MPa on x = 100 mm: bending, whose slow modes are the hard case for a
 * relaxation. The library's solve stops at |M a| <= 1e-10 |F|; the displacement error is
 * at most that residual times the condition of K (about the squared ratio of the highest to
 * the lowest frequency, 1e5 here): tolerance 1e-5 of the largest displacement; measured
 * 5e-9 in 5,355 iterations (the residual left is mostly in fast modes, which the stiffness
 * does not amplify).
 * The same mesh on 1 and 2 ranks; the direct solve (UMFPACK) runs on every rank, whole.
 */
#include <periarlequin/simulator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <map>
#include <sstream>

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  constexpr double       E = 200e9, nu = 0.3, length = 0.1, height = 0.02, shear = 1e6;
  constexpr unsigned int cells_x = 40, cells_y = 8;

  /** Nodal displacements of the direct solve, by support point (rounded to 1 nm) and component. */
  using NodalValues = std::map<std::tuple<long, long, unsigned int>, double>;

  std::tuple<long, long, unsigned int>
  key(const Point<2> &p, const unsigned int component)
  {
    return {std::lround(p[0] * 1e9), std::lround(p[1] * 1e9), component};
  }

  /** Assemble and solve K u = f for the cantilever (step-8 style, plane stress). */
  NodalValues
  direct_solution()
  {
    Triangulation<2> triangulation;
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              {cells_x, cells_y},
                                              Point<2>(0, 0),
                                              Point<2>(length, height),
                                              true);
    const FESystem<2> fe(FE_Q<2>(1), 2);
    DoFHandler<2>     dofs(triangulation);
    dofs.distribute_dofs(fe);

    AffineConstraints<double> constraints;
    VectorTools::interpolate_boundary_values(dofs, 0, Functions::ZeroFunction<2>(2), constraints);
    constraints.close();
    DynamicSparsityPattern pattern(dofs.n_dofs());
    DoFTools::make_sparsity_pattern(dofs, pattern, constraints, false);
    SparsityPattern sparsity;
    sparsity.copy_from(pattern);
    SparseMatrix<double> stiffness(sparsity);
    Vector<double>       load(dofs.n_dofs()), u(dofs.n_dofs());

    // Plane stress: sigma = lambda* tr(eps) I + 2 mu eps, lambda* = E nu / (1 - nu^2).
    const double       lambda = E * nu / (1 - nu * nu), mu = E / (2 * (1 + nu));
    const QGauss<2>    quadrature(2);
    const QGauss<1>    face_quadrature(2);
    FEValues<2>        values(fe, quadrature, update_gradients | update_JxW_values);
    FEFaceValues<2>    face_values(fe, face_quadrature, update_values | update_JxW_values);
    const unsigned int n = fe.n_dofs_per_cell();
    FullMatrix<double> cell_matrix(n, n);
    Vector<double>     cell_load(n);
    std::vector<types::global_dof_index> indices(n);
    const FEValuesExtractors::Vector     displacement(0);
    for (const auto &cell : dofs.active_cell_iterators())
      {
        values.reinit(cell);
        cell_matrix = 0;
        cell_load   = 0;
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          for (unsigned int i = 0; i < n; ++i)
            {
              const auto eps_i = values[displacement].symmetric_gradient(i, q);
              for (unsigned int j = 0; j < n; ++j)
                {
                  const auto eps_j = values[displacement].symmetric_gradient(j, q);
                  cell_matrix(i, j) +=
                    (lambda * trace(eps_i) * trace(eps_j) + 2 * mu * scalar_product(eps_i, eps_j)) *
                    values.JxW(q);
                }
            }
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == 1)
            {
              face_values.reinit(cell, f);
              for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                for (unsigned int i = 0; i < n; ++i)
                  cell_load(i) -=
                    shear * face_values[displacement].value(i, q)[1] * face_values.JxW(q);
            }
        cell->get_dof_indices(indices);
        constraints.distribute_local_to_global(cell_matrix, cell_load, indices, stiffness, load);
      }
    SparseDirectUMFPACK solver;
    solver.initialize(stiffness);
    solver.vmult(u, load);
    constraints.distribute(u);

    std::vector<Point<2>> points(dofs.n_dofs());
    DoFTools::map_dofs_to_support_points(MappingQ1<2>(), dofs, points);
    NodalValues nodal;
    for (const auto &cell : dofs.active_cell_iterators())
      {
        cell->get_dof_indices(indices);
        for (unsigned int i = 0; i < n; ++i)
          nodal[key(points[indices[i]], fe.system_to_component_index(i).first)] = u(indices[i]);
      }
    return nodal;
  }

  std::string
  cantilever_text()
  {
    std::ostringstream text;
    text << "set Dimension = 2\n"
         << "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = " << length
         << ", " << height << "\n  set Subdivisions = " << cells_x << ", " << cells_y << "\nend\n"
         << "subsection Material\n  set Young's modulus = " << E
         << "\n  set Poisson's ratio = " << nu
         << "\n  set Density = 7800\n  set Two-dimensional model = plane stress\nend\n"
         << "subsection Boundary conditions\n"
         << "  subsection Boundary 0\n    set Type = displacement\n    subsection Function\n"
         << "      set Function expression = 0; 0\n    end\n  end\n"
         << "  subsection Boundary 1\n    set Type = traction\n    subsection Function\n"
         << "      set Function expression = 0; " << -shear << "\n    end\n  end\nend\n"
         << "subsection Time\n  set Integration = static then explicit\n  set Time step = 1e-7\n"
         << "  set End time = 1e-7\nend\n"
         << "subsection Static solve\n  set Tolerance = 1e-10\nend\n"
         << quiet_output();
    return text.str();
  }

  void
  cantilever()
  {
    auto plate = make_simulator<2>(cantilever_text());
    plate->setup();
    const auto result = plate->solve_static();
    report("relaxation iterations", result.iterations);
    const NodalValues exact   = direct_solution();
    double            largest = 0;
    for (const auto &[where, value] : exact)
      largest = std::max(largest, std::abs(value));
    double      error = 0;
    const auto &u     = plate->get_fe_zone().get_state().displacement;
    for_each_fe_dof(
      *plate,
      [&](const unsigned int dof, const Point<2> &point, const unsigned int component) {
        error = std::max(error, std::abs(u.local_element(dof) - exact.at(key(point, component))));
      });
    check_below("largest |u_relaxation - u_direct| over the largest displacement",
                Utilities::MPI::max(error, MPI_COMM_WORLD) / largest,
                1e-5);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] { cantilever(); });
}
