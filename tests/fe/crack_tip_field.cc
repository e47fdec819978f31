// The crack-tip boundary field (Boundary conditions/Crack tip field, eq. 82) against the
// elasticity it must satisfy, with stresses from central differences of the displacement
// (step 1e-4 r: truncation ~1e-8, round-off ~1e-10 of the stress) and Hooke's law written out
// here (divergence: central differences of those stresses, step 1e-3 r, truncation ~1e-6).
// Plane strain (E = 29 GPa, nu = 0.29, the paper's section 6.4) and plane stress; tip
// at (0.01, -0.02) m, crack direction 30 degrees, phase angle 30 degrees, K_eff = 1e9 t at
// t = 2e-3 s (2 MPa m^1/2), at r = 5 mm:
//  - equilibrium: |div sigma| r / |sigma| below 1e-5 at 12 angles around the tip;
//  - traction-free crack faces: sigma_nn and sigma_nt (crack frame) over the stress ahead
//    of the tip vanish linearly towards the faces: below 2e-3 at 1e-3 rad from them, and
//    more than 5 times smaller there than at 1e-2 rad;
//  - the stress intensity factors: ahead of the tip (theta = 0) sigma_nn sqrt(2 pi r) = K_I
//    and sigma_nt sqrt(2 pi r) = K_II (the definition of K), within 1e-6 relative;
//  - the parameter file parameter_files/fe_crack_tip_kfield_2d.prm (which lists the four
//    sides) against its former boundary expression written out in muparser (the paper's
//    eq. 82 transcribed independently), at points on the sides: 1e-12 relative.

#include <periarlequin/base/crack_tip_field.h>

#include <deal.II/base/function_parser.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "../tests.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

namespace
{
  using Stress = Tensor<2, 2>;

  /** sigma at @p x from central differences of @p field (plane stress or strain). */
  Stress
  stress(const Function<2> &field, const Point<2> &x, const double h, const Parameters::Material &m)
  {
    Tensor<2, 2>   grad;
    Vector<double> plus(2), minus(2);
    for (unsigned int d = 0; d < 2; ++d)
      {
        Point<2> a = x, b = x;
        a[d] += h;
        b[d] -= h;
        field.vector_value(a, plus);
        field.vector_value(b, minus);
        for (unsigned int c = 0; c < 2; ++c)
          grad[c][d] = (plus(c) - minus(c)) / (2 * h);
      }
    const double E = m.youngs_modulus, nu = m.poissons_ratio, mu = E / (2 * (1 + nu));
    const double lambda = m.planar_model == Parameters::PlanarModel::plane_strain ?
                            E * nu / ((1 + nu) * (1 - 2 * nu)) :
                            E * nu / (1 - nu * nu);
    const double trace  = grad[0][0] + grad[1][1];
    Stress       sigma;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        sigma[i][j] = mu * (grad[i][j] + grad[j][i]) + (i == j ? lambda * trace : 0.);
    return sigma;
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const Point<2>     tip(0.01, -0.02);
    const double       beta = M_PI / 6, psi = M_PI / 6, r = 0.005, t = 2e-3, K = 1e9 * t;
    const Tensor<1, 2> n({-std::sin(beta), std::cos(beta)}), e({std::cos(beta), std::sin(beta)});
    for (const auto model :
         {Parameters::PlanarModel::plane_strain, Parameters::PlanarModel::plane_stress})
      {
        Parameters::Material material;
        material.youngs_modulus = 29e9;
        material.poissons_ratio = 0.29;
        material.planar_model   = model;
        const std::string name =
          model == Parameters::PlanarModel::plane_strain ? "plane strain" : "plane stress";
        CrackTipField<2> field(tip, beta, "1e9*t", psi, material);
        field.set_time(t);
        const auto at = [&](const double theta) {
          return tip + r * Tensor<1, 2>({std::cos(beta + theta), std::sin(beta + theta)});
        };
        const double h = 1e-4 * r;

        const Stress ahead = stress(field, at(0), h, material);
        const double scale = ahead.norm();
        double       worst = 0;
        for (unsigned int k = 0; k < 12; ++k)
          {
            const double   theta = -M_PI + (k + 0.5) * 2 * M_PI / 12;
            const Point<2> x     = at(theta);
            Tensor<1, 2>   divergence;
            for (unsigned int d = 0; d < 2; ++d)
              {
                Point<2> a = x, b = x;
                a[d] += 10 * h;
                b[d] -= 10 * h;
                const Stress difference =
                  stress(field, a, h, material) - stress(field, b, h, material);
                for (unsigned int i = 0; i < 2; ++i)
                  divergence[i] += difference[i][d] / (20 * h);
              }
            worst = std::max(worst, divergence.norm() * r / stress(field, x, h, material).norm());
          }
        check_below(name + ": |div sigma| r / |sigma|", worst, 1e-5);

        // The traction on the crack faces vanishes linearly with the angle from them.
        double faces[2] = {0, 0};
        for (unsigned int k = 0; k < 2; ++k)
          for (const double side : {-1., 1.})
            {
              const Stress face =
                stress(field, at(side * (M_PI - (k == 0 ? 1e-2 : 1e-3))), h, material);
              faces[k] = std::max(
                {faces[k], std::abs(n * (face * n)) / scale, std::abs(e * (face * n)) / scale});
            }
        report(name + ": crack-face traction / |sigma ahead|, 1e-2 rad from the faces", faces[0]);
        check_below(name + ": crack-face traction / |sigma ahead|, 1e-3 rad from the faces",
                    faces[1],
                    2e-3);
        check_above(name + ": the same 1e-2 rad / 1e-3 rad from the faces (linear: 10)",
                    faces[0] / faces[1],
                    5);
        const double root = std::sqrt(2 * M_PI * r);
        check_below(name + ": |sigma_nn sqrt(2 pi r) / K_I - 1| ahead",
                    std::abs(n * (ahead * n) * root / (K * std::cos(psi)) - 1.),
                    1e-6);
        check_below(name + ": |sigma_nt sqrt(2 pi r) / K_II - 1| ahead",
                    std::abs(e * (ahead * n) * root / (K * std::sin(psi)) - 1.),
                    1e-6);
      }

    // The shipped file against the muparser transcription it replaced (tip at the origin,
    // crack direction 0, plane strain, psi = 0.5236 rad as written there).
    ParameterHandler prm;
    Simulator<2>::declare_parameters(prm);
    prm.parse_input(PERIARLEQUIN_SOURCE_DIR "/parameter_files/fe_crack_tip_kfield_2d.prm");
    ProblemData<2> data;
    data.parse_parameters(prm);
    const std::string expression =
      "(1+nu)/E*sqrt(sqrt(x^2+y^2)/(2*pi))*rate*t*(cos(psi)*cos(atan2(y,x)/2)*(3-4*nu-1+2*sin("
      "atan2(y,x)/2)^2) + sin(psi)*sin(atan2(y,x)/2)*(3-4*nu+1+2*cos(atan2(y,x)/2)^2)); "
      "(1+nu)/E*sqrt(sqrt(x^2+y^2)/(2*pi))*rate*t*(cos(psi)*sin(atan2(y,x)/2)*(3-4*nu+1-2*cos("
      "atan2(y,x)/2)^2) - sin(psi)*cos(atan2(y,x)/2)*(3-4*nu-1-2*sin(atan2(y,x)/2)^2))";
    FunctionParser<2> written(2);
    written.initialize("x,y,t",
                       expression,
                       {{"E", 29e9}, {"nu", 0.29}, {"rate", 1e9}, {"psi", M_PI / 6}, {"pi", M_PI}},
                       true);
    double worst = 0, largest = 0;
    for (unsigned int b = 0; b < 4; ++b)
      {
        Function<2> &field = *data.boundary_conditions[b].function;
        check("boundary " + std::to_string(b) + " is a displacement condition",
              data.boundary_conditions[b].type == BoundaryType::displacement,
              1,
              0);
        for (unsigned int k = 0; k < 9; ++k)
          {
            const double   s = -0.03125 + k * 0.0078125, a = 0.03125;
            const Point<2> x = b == 0 ? Point<2>(-a, s) :
                               b == 1 ? Point<2>(a, s) :
                               b == 2 ? Point<2>(s, -a) :
                                        Point<2>(s, a);
            for (const double time : {1e-6, 2e-5})
              {
                field.set_time(time);
                written.set_time(time);
                for (unsigned int c = 0; c < 2; ++c)
                  {
                    worst   = std::max(worst, std::abs(field.value(x, c) - written.value(x, c)));
                    largest = std::max(largest, std::abs(written.value(x, c)));
                  }
              }
          }
      }
    check_below("fe_crack_tip_kfield_2d.prm vs the muparser eq. 82, relative",
                worst / largest,
                1e-12);
  });
}
