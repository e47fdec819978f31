#ifndef periarlequin_tests_pd_single_bond_h
#define periarlequin_tests_pd_single_bond_h

// The single-bond fracture case shared by the fracture-criterion tests: two lattice sites
// dx = 1 mm apart (E = 69 GPa, nu = 0.3, m = 3.015, fracture on), the left one held, the
// right one moved along the bond with u = U sin(pi t / T) (U < 0: pushed), dt = 2e-8 s, run
// to T.

#include "../tests.h"

namespace PeriArlequinTests
{
  /**
   * The case's parameter text; @p model is the two-dimensional model, @p peridynamics extra
   * lines of the Peridynamics subsection (a criterion and its parameters).
   */
  template <int dim>
  std::string
  single_bond_case(const std::string &model,
                   const std::string &peridynamics,
                   const double       G0,
                   const double       U,
                   const double       T)
  {
    std::ostringstream prm;
    prm << std::setprecision(17) << "set Dimension = " << dim << "\n"
        << "subsection Geometry\n  set Lower corner = " << (dim == 2 ? "0, 0" : "0, 0, 0")
        << "\n  set Upper corner = " << (dim == 2 ? "0.01, 0.01" : "0.01, 0.01, 0.01")
        << "\n  set Subdivisions = " << (dim == 2 ? "2, 2" : "2, 2, 2") << "\nend\n"
        << "subsection Material\n  set Young's modulus = 69e9\n  set Poisson's ratio = 0.3\n"
        << "  set Two-dimensional model = " << model << "\nend\n"
        << "subsection Peridynamics\n  set Region = "
        << (dim == 2 ? "0, 0 : 0.002, 0.001" : "0, 0, 0 : 0.002, 0.001, 0.001")
        << "\n  set Lattice spacing = 1e-3\n  set Fracture = true\n"
        << "  set Critical energy release rate = " << G0 << "\n"
        << peridynamics << "  subsection Prescribed region 0\n    set Region = "
        << (dim == 2 ? "0, 0 : 0.001, 0.001" : "0, 0, 0 : 0.001, 0.001, 0.001") << "\n  end\n"
        << "  subsection Prescribed region 1\n    set Region = "
        << (dim == 2 ? "0.001, 0 : 0.002, 0.001" : "0.001, 0, 0 : 0.002, 0.001, 0.001")
        << "\n    subsection Function\n      set Function constants = U=" << U << ", T=" << T
        << "\n      set Function expression = U*sin(pi*t/T); 0" << (dim == 3 ? "; 0" : "")
        << "\n    end\n  end\nend\n"
        << "subsection Time\n  set Time step = 2e-8\n  set End time = " << T << "\nend\n"
        << quiet_output();
    return prm.str();
  }

  /** What a run of the case showed. */
  struct SingleBondRun
  {
    /** The first step at which @p breaks held, and at which the bond was broken (-1: none). */
    int expected_step = -1, breaking_step = -1;
    /** Did the bond stay broken once broken? */
    bool stays_broken = true;
  };

  /**
   * Set up and run the case to its end time @p T; @p breaks(e) says whether the criterion
   * must break the bond at the extension e = U sin(pi t / T) of a step.
   */
  template <int dim>
  SingleBondRun
  run_single_bond(PeriArlequin::Simulator<dim>      &simulator,
                  const double                       U,
                  const double                       T,
                  const std::function<bool(double)> &breaks)
  {
    auto &pd = *simulator.get_pd_zone();
    AssertThrow(pd.n_global_particles() == 2 && pd.n_global_bonds() == 2,
                ExcMessage("expected two particles and one bond (stored at both ends)"));
    SingleBondRun run;
    for (int step = 1; simulator.get_time() < T * (1 - 1e-12); ++step)
      {
        simulator.advance();
        if (run.expected_step < 0 && breaks(U * std::sin(numbers::PI * simulator.get_time() / T)))
          run.expected_step = step;
        const auto broken = pd.n_global_broken_bonds();
        if (run.breaking_step < 0 && broken == 2)
          run.breaking_step = step;
        if (run.breaking_step > 0 && broken != 2)
          run.stays_broken = false;
      }
    return run;
  }
} // namespace PeriArlequinTests

#endif
