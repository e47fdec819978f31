/**
 * The static solve of a pure-FE case, by dynamic relaxation and by conjugate gradients,
 * against a direct solve of K u = f assembled here, independently of the library: a
 * cantilever plate 100 x 20 mm (plane stress, E = 200 GPa, nu = 0.3, Q1 on 40 x 8 cells),
 * clamped on x = 0 and loaded by a shear traction of 1 MPa on x = 100 mm: bending, whose
 * slow modes are the hard case for an iterative solve. The library's solves stop at
 * |M a| <= 1e-10 |F|; the displacement error is at most that residual times the condition
 * of K (about the squared ratio of the highest to the lowest frequency, 1e5 here):
 * tolerance 1e-5 of the largest displacement. Measured: relaxation 5e-9 in 5,355
 * iterations (the residual left is mostly in fast modes, which the stiffness does not
 * amplify), conjugate gradients 1e-12 (5e-12 on 2 ranks) in 148.
 * The same mesh on 1 and 2 ranks; the direct solve (UMFPACK) runs on every rank, whole.
 */
#include <periarlequin/simulator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/sparse_direct.h>

#include "../tests.h"
#include "cantilever_system.h"

using namespace PeriArlequinTests;

namespace
{
  constexpr unsigned int cells_x = 40, cells_y = 8;

  /** Solve K u = f of the cantilever, assembled apart from the library, with UMFPACK. */
  CantileverSystem::NodalValues
  direct_solution()
  {
    CantileverSystem    system(cells_x, cells_y);
    Vector<double>      u(system.dofs.n_dofs());
    SparseDirectUMFPACK solver;
    solver.initialize(system.stiffness);
    solver.vmult(u, system.load);
    system.constraints.distribute(u);
    return system.nodal_values(u);
  }

  /** The cantilever solved by Static solve/Method = @p method against @p exact. */
  void
  cantilever(const std::string &method, const CantileverSystem::NodalValues &exact)
  {
    auto plate = make_simulator<2>(CantileverSystem::case_text(cells_x, cells_y, 1e-7) +
                                   "subsection Static solve\n  set Tolerance = 1e-10\n"
                                   "  set Method = " +
                                   method + "\nend\n" + quiet_output());
    plate->setup();
    const auto result = plate->solve_static();
    report(method + " iterations", result.iterations);
    double largest = 0;
    for (const auto &[where, value] : exact)
      largest = std::max(largest, std::abs(value));
    double      error = 0;
    const auto &u     = plate->get_fe_zone().get_state().displacement;
    for_each_fe_dof(*plate,
                    [&](const unsigned int dof,
                        const Point<2>    &point,
                        const unsigned int component) {
                      error = std::max(error,
                                       std::abs(u.local_element(dof) -
                                                exact.at(CantileverSystem::key(point, component))));
                    });
    check_below(method + ": largest |u - u_direct| over the largest displacement",
                Utilities::MPI::max(error, MPI_COMM_WORLD) / largest,
                1e-5);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const auto exact = direct_solution();
    for (const std::string method : {"relaxation", "conjugate gradients"})
      cantilever(method, exact);
  });
}
