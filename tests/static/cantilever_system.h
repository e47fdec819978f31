#ifndef periarlequin_tests_static_cantilever_system_h
#define periarlequin_tests_static_cantilever_system_h

// The cantilever of static/direct_solve, assembled independently of the library (step-8
// style): a plane-stress plate clamped on x = 0 (boundary 0) and loaded by a shear traction
// on x = length (boundary 1), Q1 on a uniform mesh. Shared by that test (its reference
// solution) and benchmarks/static_solve_cost.cc (direct and Krylov solves of the same mesh).

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
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <tuple>

namespace PeriArlequinTests
{
  using namespace dealii;

  /** The linear system K u = f of the cantilever and what it was built on. */
  struct CantileverSystem
  {
    static constexpr double E = 200e9, nu = 0.3, length = 0.1, height = 0.02, shear = 1e6;

    CantileverSystem(const unsigned int cells_x, const unsigned int cells_y)
      : fe(FE_Q<2>(1), 2)
      , dofs(triangulation)
    {
      GridGenerator::subdivided_hyper_rectangle(triangulation,
                                                {cells_x, cells_y},
                                                Point<2>(0, 0),
                                                Point<2>(length, height),
                                                true);
      dofs.distribute_dofs(fe);
      VectorTools::interpolate_boundary_values(dofs, 0, Functions::ZeroFunction<2>(2), constraints);
      constraints.close();
      DynamicSparsityPattern pattern(dofs.n_dofs());
      DoFTools::make_sparsity_pattern(dofs, pattern, constraints, false);
      sparsity.copy_from(pattern);
      stiffness.reinit(sparsity);
      load.reinit(dofs.n_dofs());
      assemble();
    }

    /** Nodal values by support point (rounded to 1 nm) and component. */
    using NodalValues = std::map<std::tuple<long, long, unsigned int>, double>;

    static std::tuple<long, long, unsigned int>
    key(const Point<2> &p, const unsigned int component)
    {
      return {std::lround(p[0] * 1e9), std::lround(p[1] * 1e9), component};
    }

    /** The nodal values of a solution @p u of this system (constraints distributed). */
    NodalValues
    nodal_values(const Vector<double> &u) const
    {
      std::vector<Point<2>> points(dofs.n_dofs());
      DoFTools::map_dofs_to_support_points(MappingQ1<2>(), dofs, points);
      NodalValues                          nodal;
      const unsigned int                   n = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> indices(n);
      for (const auto &cell : dofs.active_cell_iterators())
        {
          cell->get_dof_indices(indices);
          for (unsigned int i = 0; i < n; ++i)
            nodal[key(points[indices[i]], fe.system_to_component_index(i).first)] = u(indices[i]);
        }
      return nodal;
    }

    /** Parameter text of the same case for the library (without Output and Static solve). */
    static std::string
    case_text(const unsigned int cells_x, const unsigned int cells_y, const double time_step)
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
           << "subsection Time\n  set Integration = static then explicit\n  set Time step = "
           << time_step << "\n  set End time = " << time_step << "\nend\n";
      return text.str();
    }

    Triangulation<2>          triangulation;
    const FESystem<2>         fe;
    DoFHandler<2>             dofs;
    AffineConstraints<double> constraints;
    SparsityPattern           sparsity;
    SparseMatrix<double>      stiffness;
    Vector<double>            load;

  private:
    void
    assemble()
    {
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
                    cell_matrix(i, j) += (lambda * trace(eps_i) * trace(eps_j) +
                                          2 * mu * scalar_product(eps_i, eps_j)) *
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
    }
  };
} // namespace PeriArlequinTests

#endif
