// A Gmsh mesh of hexahedra (gmsh_block_3d.geo: a 40 x 20 x 10 mm steel block, the x-y face
// meshed with unstructured quadrilaterals and extruded along z; 102 cells), PD in the box
// [12, 28] x [5, 15] x [0, 10] mm coupled by the weak coupling across an 8 mm band, lattice
// 0.5 mm, m = 3; a smooth velocity pulse along x starting in the FE part:
//  - every lattice site of the PD zone's extent (within band + 2 (delta + dx/2) of the PD box)
//    holds exactly one particle: the count equals the count of those sites in the block,
//    made here from the lattice, exactly (sites on the faces between distorted hexahedra go
//    to one cell only);
//  - N reproduces a linear field (mapped Q1 holds it) at every particle in an FE cell to
//    1e-10 of its magnitude: deal.II inverts the trilinear map by Newton iterations that stop
//    at a residual near 1e-11 of the cell (the bilinear inverse of 2D is explicit, and
//    coupling/gmsh_plate_with_hole holds 1e-12);
//  - on 2 ranks the energy history of 40 steps equals 1 rank to 1e-10 of each column's
//    magnitude (sums in another order).

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  std::string
  case_text()
  {
    return std::string("set Dimension = 3\n"
                       "subsection Geometry\n  set Mesh file = ") +
           PERIARLEQUIN_SOURCE_DIR
           "/tests/coupling/gmsh_block_3d.msh\nend\n"
           "subsection Material\n  set Young's modulus = 200e9\n  set Poisson's ratio = 0.3\n"
           "  set Density = 7800\nend\n"
           "subsection Peridynamics\n  set Region = 0.012, 0.005, 0 : 0.028, 0.015, 0.01\n"
           "  set Lattice spacing = 5e-4\n  set Horizon factor = 3\nend\n"
           "subsection Coupling\n  set Method = weak\n  set Blending = force\n"
           "  set Overlap width = 0.008\nend\n"
           "subsection Initial conditions\n  set Model = function\n  subsection function\n"
           "    subsection Velocity\n"
           "      set Function expression = exp(-((x-0.006)^2)/2e-5); 0; 0\n"
           "    end\n  end\nend\n"
           "subsection Time\n  set Time step = 5e-8\n  set End time = 2e-6\n"
           // dt is a third of the stable step: a short estimate decides as well.
           "  set Stability estimate iterations = 20\nend\n" +
           quiet_output() + "subsection Output\n  set Energy interval = 5\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const double   dx = 5e-4, delta = 3 * dx, band = 0.008;
    const Point<3> pd_lower(0.012, 0.005, 0), pd_upper(0.028, 0.015, 0.01);

    auto simulator = make_simulator<3>(case_text());
    simulator->setup();
    const auto &pd = *simulator->get_pd_zone();

    const double       reach    = (band + 2 * (delta + 0.5 * dx)) * (1 + 1e-10);
    unsigned long long expected = 0;
    for (unsigned int i = 0; (i + 0.5) * dx < 0.04; ++i)
      for (unsigned int j = 0; (j + 0.5) * dx < 0.02; ++j)
        for (unsigned int k = 0; (k + 0.5) * dx < 0.01; ++k)
          if (distance_to_box(Point<3>((i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx),
                              pd_lower,
                              pd_upper) <= reach)
            ++expected;
    report("sites expected", expected);
    check("particles against the sites of the extent",
          static_cast<double>(pd.n_global_particles()),
          static_cast<double>(expected),
          0);

    class Linear : public Function<3>
    {
    public:
      Linear()
        : Function<3>(3)
      {}
      double
      value(const Point<3> &p, const unsigned int c) const override
      {
        const double a[3][3] = {{2, -3, 1}, {0.5, 1, -2}, {-1, 0.25, 3}};
        return 1e-3 * (a[c][0] * p[0] + a[c][1] * p[1] + a[c][2] * p[2]) + 1e-5 * (c + 1);
      }
    };
    check_below("linear field through N, error / magnitude",
                interpolation_error_at_particles(*simulator, Linear()),
                1e-10);

    if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      check_below("2 ranks vs 1 rank, largest history difference",
                  parallel_vs_serial_history_difference<3>(case_text(), "block"),
                  1e-10);
  });
}
