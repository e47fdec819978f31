// Long-wave speed of the pure-PD LPS plate (plane stress): a smooth pulse u_x(x) released at
// rest splits into halves travelling at the plane longitudinal speed sqrt(E / (rho (1 -
// nu^2))). The lateral edges are on rollers (layers of particles one horizon thick with
// u_y = 0, the usual fictitious boundary layer), so that the strain is uniaxial as in the
// classical plane wave. The speed is measured from the centroid of u_x of the right-moving
// half, over the whole cross-section, at two times after the halves have separated.
//
// Tolerance 2 % (the bound). What the model itself contributes: in the bulk the
// lattice sums make the LPS uniaxial modulus 1.35 % stiffer than classical at m = 3.015 (the
// affine test's figure), +0.67 % in speed; within a horizon of a free surface the truncated
// families are stiffer still (the LPS surface effect, worth about one extra lattice row of
// modulus per edge), which over the 160 rows of this plate adds about 0.35 % in speed. The
// pulse spans 60 spacings (20 horizons), where PD dispersion is below 0.1 %. A narrow strip
// would show the surface effect instead of the long-wave speed.

#include "../tests.h"

using namespace PeriArlequinTests;

double
centroid(const PeriArlequin::PDZone<2> &pd, const double x0)
{
  double moments[2] = {0, 0};
  for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
    if (pd.reference_positions()[i][0] > x0)
      {
        moments[0] += pd.get_state().displacements()[i][0] * pd.reference_positions()[i][0];
        moments[1] += pd.get_state().displacements()[i][0];
      }
  Utilities::MPI::sum(ArrayView<const double>(moments, 2),
                      MPI_COMM_WORLD,
                      ArrayView<double>(moments, 2));
  return moments[0] / moments[1];
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const double       x0 = 0.3, w = 0.15;
    std::ostringstream prm;
    prm << "set Dimension = 2\n"
        << "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = 0.85, 0.4\n"
        << "  set Subdivisions = 85, 40\nend\n"
        << "subsection Peridynamics\n  set Region = 0, 0 : 0.85, 0.4\n"
        << "  set Lattice spacing = 0.0025\n"
        << "  subsection Prescribed region 0\n"
        << "    set Region = 0, 0 : 0.85, 0.0075 ; 0, 0.3925 : 0.85, 0.4\n"
        << "    set Type = velocity\n    set Components = y\n  end\nend\n"
        << "subsection Time\n  set Time step = 4e-7\n  set End time = 1\nend\n"
        << "subsection Initial conditions\nsubsection function\n  subsection Displacement\n"
        << "    set Function constants = x0=" << x0 << ", w=" << w << "\n"
        << "    set Function expression = if(abs(x-x0) < w/2, 1e-6*(1+cos(2*pi*(x-x0)/w)), 0); 0\n"
        << "  end\nend\nend\n"
        << quiet_output();
    auto simulator = make_simulator<2>(prm.str());
    simulator->setup();
    auto        &pd = *simulator->get_pd_zone();
    const double E = 69e9, nu = 0.3, rho = 2700;
    const double expected = std::sqrt(E / (rho * (1 - nu * nu)));
    const double t1 = w / expected, t2 = t1 + 0.225 / expected;
    double       c1 = 0, c2 = 0, s1 = 0, s2 = 0;
    while (simulator->get_time() < t2)
      {
        simulator->advance();
        const double t = simulator->get_time();
        if (c1 == 0 && t >= t1)
          c1 = centroid(pd, x0), s1 = t;
        if (t >= t2)
          c2 = centroid(pd, x0), s2 = t;
      }
    report("centroid at t1", c1);
    report("centroid at t2", c2);
    check("PD long-wave speed / sqrt(E / (rho (1 - nu^2)))",
          (c2 - c1) / (s2 - s1) / expected,
          1.,
          0.02);
  });
}
