// The "wave pulse" initial condition (the paper's eq. 81 as a registered model with its own
// parameters) gives the FE nodes and the PD particles of an uncoupled FE + PD plate the same
// initial displacement as the "function" model with the pulse written out as a muparser
// expression (as parameter_files/fe_wave_2d.prm does), for a pulse centred off the origin
// that covers both zones, along x and along y. Velocities are zero.
//
// Tolerance 1e-13 of the largest displacement: the two evaluate the same formula with the
// operations in another order; the cosine arguments reach 2 pi (w1/2)/w2 ~ 50, where one
// rounding of the argument (1e-16 relative) moves the result by about 5e-15.

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  const std::string pulse_constants = "a1=3e-4, a2=0.3, w1=0.48, w2=0.03, x0=0.05";

  std::string
  parameters(const std::string &initial_conditions)
  {
    return "set Dimension = 2\n"
           "subsection Geometry\n  set Lower corner = -0.4, 0\n  set Upper corner = 0.4, 0.04\n"
           "  set Subdivisions = 80, 4\nend\n"
           "subsection Peridynamics\n  set Region = -0.1, 0 : 0.1, 0.04\n"
           "  set Lattice spacing = 0.0025\nend\n"
           "subsection Time\n  set Time step = 1e-7\n  set Stability estimate iterations = 5\n"
           "end\n" +
           initial_conditions + quiet_output();
  }

  std::string
  pulse_model(const std::string &component)
  {
    return "subsection Initial conditions\n  set Model = wave pulse\n  subsection wave pulse\n"
           "    set Amplitude = 3e-4\n    set Modulation = 0.3\n    set Width = 0.48\n"
           "    set Modulation wavelength = 0.03\n    set Centre = 0.05\n"
           "    set Component = " +
           component + "\n  end\nend\n";
  }

  std::string
  pulse_expression(const std::string &component)
  {
    const std::string d = "if(abs(x-x0) <= w1/2, a1*(1+cos(2*pi*(x-x0)/w1))*"
                          "(1+a2*cos(2*pi*(x-x0+w1/2)/w2)), 0)";
    return "subsection Initial conditions\n  set Model = function\n  subsection function\n"
           "    subsection Displacement\n      set Function constants = " +
           pulse_constants +
           "\n      set Function expression = " + (component == "x" ? d + "; 0" : "0; " + d) +
           "\n    end\n  end\nend\n";
  }

  void
  compare(const std::string &component)
  {
    auto pulse    = make_simulator<2>(parameters(pulse_model(component)));
    auto function = make_simulator<2>(parameters(pulse_expression(component)));
    pulse->setup();
    function->setup();

    auto        fe_difference = pulse->get_fe_zone().get_state().displacement;
    const auto &fe_reference  = function->get_fe_zone().get_state().displacement;
    fe_difference -= fe_reference;
    const double fe_scale = fe_reference.linfty_norm();
    AssertThrow(fe_scale > 3e-4, ExcMessage("the pulse does not reach the FE nodes"));
    check_below(component + " pulse: FE max |u - u_function| / max |u_function|",
                fe_difference.linfty_norm() / fe_scale,
                1e-13);

    const auto u         = pulse->get_pd_zone()->get_state().displacements();
    const auto reference = function->get_pd_zone()->get_state().displacements();
    const auto v         = pulse->get_pd_zone()->get_state().velocities();
    double     pd_scale = 0, pd_difference = 0, speed = 0;
    for (unsigned int i = 0; i < pulse->get_pd_zone()->n_owned_particles(); ++i)
      {
        pd_scale      = std::max(pd_scale, reference[i].norm());
        pd_difference = std::max(pd_difference, (u[i] - reference[i]).norm());
        speed         = std::max(speed, v[i].norm());
      }
    pd_scale      = Utilities::MPI::max(pd_scale, MPI_COMM_WORLD);
    pd_difference = Utilities::MPI::max(pd_difference, MPI_COMM_WORLD);
    AssertThrow(pd_scale > 3e-4, ExcMessage("the pulse does not reach the PD particles"));
    check_below(component + " pulse: PD max |u - u_function| / max |u_function|",
                pd_difference / pd_scale,
                1e-13);
    check(component + " pulse: max |v| of nodes and particles [m/s]",
          Utilities::MPI::max(speed, MPI_COMM_WORLD) +
            pulse->get_fe_zone().get_state().velocity.linfty_norm(),
          0,
          0);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    compare("x");
    compare("y");
  });
}
