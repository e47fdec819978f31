// The "strain" conversion criterion flags the FE cells whose largest principal strain at a
// Gauss point reaches the threshold, plus the cells within "Buffer" of them. Plate [-0.2, 0.2]^2,
// 20 x 20 FE cells (h = 20 mm), PD centre [-0.06, 0.06]^2, overlap band 0.04 m; displaced by
// u = (a x^2, 0), a = 1e-3 1/m, so that the strain at a cell centre is eps_xx = 2 a x_c
// exactly at every Gauss point (the Q1 interpolant of the quadratic is linear in x between
// nodes, its gradient the difference quotient), and
// the largest principal strain is max(2 a x_c, 0). The criterion is created from its
// parameters through the registry, as the simulator does.
//  - Strain = 2e-4: the columns x_c >= 0.1 (centres 0.11 ... 0.19), 5 x 20 = 100 cells.
//  - with Buffer = 0.015 m: the cells whose box lies within 0.015 + h/2 of a flagged centre
//    add the column x_c = 0.09 (0.01 away) but not x_c = 0.07 (0.03 away): 120 cells.
//  - Buffer = 0 takes the growth's trigger distance: given as 0.015 m, the 120 cells again;
//    without one (0), no buffer: 100.
//  - Strain = 1e-3 (above 2 a x_c = 3.8e-4 everywhere): none.
//  - Strain 2e-4 with boundary 1 (x = 0.2) loaded: its column of 20 cells stays FE, 80; with
//    Buffer = 0.015 m, 100.
// Counts over all ranks, exact; the same on 1 and 2 ranks.

#include <periarlequin/adaptivity/conversion_criterion.h>

#include "../tests.h"

using namespace PeriArlequinTests;

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    auto simulator = make_simulator<2>(
      "set Dimension = 2\n"
      "subsection Geometry\n  set Lower corner = -0.2, -0.2\n"
      "  set Upper corner = 0.2, 0.2\n  set Subdivisions = 20, 20\nend\n"
      "subsection Peridynamics\n  set Region = -0.06, -0.06 : 0.06, 0.06\n"
      "  set Lattice spacing = 0.005\nend\n"
      "subsection Coupling\n  set Method = weak\n  set Overlap width = 0.04\nend\n"
      "subsection Time\n  set Time step = 2e-7\n  set End time = 2e-7\nend\n"
      "subsection Initial conditions\nsubsection function\n  subsection Displacement\n"
      "    set Function expression = 1e-3*x^2; 0\n  end\nend\nend\n" +
      quiet_output());
    simulator->setup();
    const auto &fe    = simulator->get_fe_zone();
    const auto &pd    = *simulator->get_pd_zone();
    const auto  count = [&](const std::string                  &strain,
                           const std::string                  &buffer,
                           const double                        trigger_distance  = 0,
                           const std::set<types::boundary_id> &loaded_boundaries = {}) {
      ParameterHandler prm;
      PeriArlequin::ConversionCriterionRegistry<2>::declare_parameters(prm);
      prm.parse_input_from_string("subsection strain\n  set Strain = " + strain +
                                  "\n  set Buffer = " + buffer + "\nend\n");
      auto criterion = PeriArlequin::ConversionCriterionRegistry<2>::create("strain", prm);
      PeriArlequin::GrowthContext context;
      context.trigger_distance  = trigger_distance;
      context.loaded_boundaries = loaded_boundaries;
      criterion->initialize(fe, pd, context);
      std::vector<bool> convert(fe.get_dof_handler().get_triangulation().n_active_cells(), false);
      criterion->mark_cells(fe, pd, convert);
      return Utilities::MPI::sum(std::count(convert.begin(), convert.end(), true), MPI_COMM_WORLD);
    };
    check("Strain 2e-4: cells flagged", count("2e-4", "0"), 100, 0);
    check("Strain 2e-4, Buffer 0.015 m: cells flagged", count("2e-4", "0.015"), 120, 0);
    check("Strain 2e-4, Buffer 0 (the trigger distance, 0.015 m): cells flagged",
          count("2e-4", "0", 0.015),
          120,
          0);
    check("Strain 1e-3: cells flagged", count("1e-3", "0"), 0, 0);
    check("Strain 2e-4, boundary 1 loaded: cells flagged", count("2e-4", "0", 0, {1}), 80, 0);
    check("Strain 2e-4, Buffer 0.015 m, boundary 1 loaded: cells flagged",
          count("2e-4", "0.015", 0, {1}),
          100,
          0);
  });
}
