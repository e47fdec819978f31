// Displacement conditions on PD particles: the particles within two bond reaches
// (2 delta + dx) of a displacement face follow it, so that every free particle and each of
// its neighbours (whose dilatation enters its force) has a complete family. A 2D aluminium plate
// (lattice 1 mm, horizon 3.015 mm) starts in the affine state u = E x that its four faces
// prescribe. Peridynamic forces vanish exactly for an affine field at particles with
// complete families, so the free particles must stay where they are: after 50 steps (the
// waves of any surface force would have crossed 12 mm of the 40 mm plate) the largest
// deviation from E x, relative to the largest |E x|, must stay at round-off, below 1e-12
// (forces are sums of ~30 bond terms that cancel; relative round-off ~1e-16 per term). The
// same plate with free faces is the control: its surface particles, with cut families,
// deviate by far more (at least 1e-4), which shows the check can see a layer that is too
// thin. Also counted: the layer holds the sites within 7.03 mm of a face, the outer seven
// rings of the 40 x 40 lattice, 40^2 - 26^2 = 924 particles. Then coupled (PD strip in the
// middle, overlaps and FE on both sides, weak coupling, force blending, which reproduces
// affine fields exactly): the layer particles of the overlap carry zero inverse mass in the
// constraint, as the FE nodes of the faces do, and multipliers whose support is all
// prescribed drop out; the whole state still stays at E x below 1e-12 (measured 3e-16;
// leaving the layer particles out of the constraint instead left the FE nodes next to the
// faces unconstrained, a 16 % drift; energy blending's ghost forces give 0.7 %). Run on 2
// ranks too: the same verdicts.

#include "../tests.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

namespace
{
  const std::string affine_field = "1e-3*x + 2e-4*y; 3e-4*x - 5e-4*y";

  std::string
  plate(const bool coupled, const bool prescribed_faces)
  {
    std::string text =
      "set Dimension = 2\n"
      "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = " +
      std::string(coupled ? "0.06" : "0.04") +
      ", 0.04\n  set Subdivisions = " + std::string(coupled ? "12" : "8") +
      ", 8\nend\n"
      "subsection Material\n  set Young's modulus = 69e9\n  set Poisson's ratio = 0.3\n"
      "  set Density = 2700\nend\n"
      "subsection Peridynamics\n  set Lattice spacing = 1e-3\n  set Horizon factor = 3.015\n"
      "  set Region = " +
      std::string(coupled ? "0.02, 0 : 0.04, 0.04" : "0, 0 : 0.04, 0.04") +
      "\nend\n"
      "subsection Initial conditions\n  subsection function\n"
      "    subsection Displacement\n      set Function expression = " +
      affine_field + "\n    end\n  end\nend\n";
    if (prescribed_faces)
      {
        text += "subsection Boundary conditions\n";
        for (unsigned int b = 0; b < 4; ++b)
          text += "  subsection Boundary " + std::to_string(b) +
                  "\n    set Type = displacement\n    subsection Function\n"
                  "      set Function expression = " +
                  affine_field + "\n    end\n  end\n";
        text += "end\n";
      }
    text +=
      "subsection Time\n  set Time step = 5e-8\n  set End time = 2.5e-6\nend\n" + quiet_output();
    if (coupled)
      text += "subsection Coupling\n  set Method = weak\n  set Blending = force\n"
              "  set Overlap region = 0.01, 0 : 0.02, 0.04 ; 0.04, 0 : 0.05, 0.04\n"
              "  set Finite element region = 0, 0 : 0.01, 0.04 ; 0.05, 0 : 0.06, 0.04\nend\n";
    return text;
  }

  Tensor<1, 2>
  affine(const Point<2> &x)
  {
    return Tensor<1, 2>({1e-3 * x[0] + 2e-4 * x[1], 3e-4 * x[0] - 5e-4 * x[1]});
  }

  /** Largest |u - E x| over particles and FE nodes, relative to the largest |E x|. */
  double
  deviation(const Simulator<2> &simulator)
  {
    double worst = 0, scale = 0;
    if (const PDZone<2> *pd = simulator.get_pd_zone())
      for (unsigned int i = 0; i < pd->n_owned_particles(); ++i)
        {
          const Point<2> &x = pd->reference_positions()[i];
          worst = std::max(worst, (pd->get_state().displacements()[i] - affine(x)).norm());
          scale = std::max(scale, affine(x).norm());
        }
    for_each_fe_dof(simulator,
                    [&](const unsigned int dof, const Point<2> &x, const unsigned int component) {
                      worst = std::max(worst,
                                       std::abs(simulator.get_displacement().local_element(dof) -
                                                affine(x)[component]));
                    });
    return Utilities::MPI::max(worst, MPI_COMM_WORLD) / Utilities::MPI::max(scale, MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    {
      auto simulator = make_simulator<2>(plate(false, true));
      simulator->setup();
      unsigned int     n_prescribed = 0;
      const PDZone<2> &pd           = *simulator->get_pd_zone();
      for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
        n_prescribed += pd.is_prescribed(i);
      check("pure PD: particles in the displacement layers",
            Utilities::MPI::sum(n_prescribed, MPI_COMM_WORLD),
            924,
            0);
      simulator->run();
      check_below("pure PD, faces prescribed: max |u - E x| / max |E x|",
                  deviation(*simulator),
                  1e-12);
    }
    {
      auto simulator = make_simulator<2>(plate(false, false));
      simulator->run();
      check_above("control, free faces: max |u - E x| / max |E x|", deviation(*simulator), 1e-4);
    }
    {
      auto simulator = make_simulator<2>(plate(true, true));
      simulator->run();
      check_below("coupled, faces prescribed: max |u - E x| / max |E x|",
                  deviation(*simulator),
                  1e-12);
    }
  });
}
