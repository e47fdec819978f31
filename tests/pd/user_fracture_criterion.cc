// A user adds a fracture criterion without editing the library: this file defines a
// criterion on the bond extension itself (a bond breaks when e = |xi + eta| - |xi| exceeds
// a length of the user's, "Peridynamics/critical extension/Critical extension"), registers
// it with PERIARLEQUIN_REGISTER_FRACTURE_CRITERION and selects it by name. Two particles
// 1 mm apart, one held, one pulled along the bond with u = U sin(pi t / T), U = 2 e_c: the
// bond must break at the first step whose extension u exceeds e_c (computed here), exactly,
// and stay broken when u falls back (the default e_c, 1 m, would never break it).

#include <periarlequin/pd/fracture_criterion.h>

#include "../tests.h"

namespace UserCriteria
{
  using namespace dealii;
  using PeriArlequin::BondFamilies;

  template <int dim>
  class CriticalExtension : public PeriArlequin::FractureCriterion<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Critical extension", "1", Patterns::Double(0), "e_c [m].");
    }
    void
    parse_parameters(ParameterHandler &prm) override
    {
      critical_extension = prm.get_double("Critical extension");
    }
    void
    initialize(const PeriArlequin::Parameters::Peridynamics<dim> &,
               const PeriArlequin::PDMaterialModel<dim> &,
               const BondFamilies<dim> &) override
    {}
    void
    break_bonds(PeriArlequin::BreakableBonds<dim> &bonds, ArrayView<const double>) const override
    {
      bonds.for_each_intact([&](const auto &bond) {
        if (bond.extension() > critical_extension)
          bonds.break_bond(bond);
      });
    }

  private:
    double critical_extension = 1;
  };

  PERIARLEQUIN_REGISTER_FRACTURE_CRITERION(CriticalExtension,
                                           "critical extension",
                                           "a bond breaks when its extension exceeds a length")
} // namespace UserCriteria

using namespace PeriArlequinTests;

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const double       dx = 1e-3, e_c = 1e-6, U = 2 * e_c, T = 1e-4;
    std::ostringstream prm;
    prm << std::setprecision(17) << "set Dimension = 2\n"
        << "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = 0.01, 0.01\n"
        << "  set Subdivisions = 2, 2\nend\n"
        << "subsection Peridynamics\n  set Region = 0, 0 : 0.002, 0.001\n"
        << "  set Lattice spacing = " << dx << "\n  set Fracture = true\n"
        << "  set Fracture criterion = critical extension\n"
        << "  subsection critical extension\n    set Critical extension = " << e_c << "\n  end\n"
        << "  subsection Prescribed region 0\n    set Region = 0, 0 : 0.001, 0.001\n  end\n"
        << "  subsection Prescribed region 1\n    set Region = 0.001, 0 : 0.002, 0.001\n"
        << "    subsection Function\n      set Function constants = U=" << U << ", T=" << T
        << "\n      set Function expression = U*sin(pi*t/T); 0\n    end\n  end\nend\n"
        << "subsection Time\n  set Time step = 2e-8\n  set End time = " << T << "\nend\n"
        << quiet_output();
    auto simulator = make_simulator<2>(prm.str());
    simulator->setup();
    auto &pd = *simulator->get_pd_zone();
    AssertThrow(pd.n_global_particles() == 2 && pd.n_global_bonds() == 2,
                ExcMessage("expected two particles and one bond (stored at both ends)"));
    int  first_broken_step = -1, expected_step = -1;
    bool stays_broken = true;
    for (int step = 1; simulator->get_time() < T * (1 - 1e-12); ++step)
      {
        simulator->advance();
        if (expected_step < 0 && U * std::sin(numbers::PI * simulator->get_time() / T) > e_c)
          expected_step = step;
        const auto broken = pd.n_global_broken_bonds();
        if (first_broken_step < 0 && broken == 2)
          first_broken_step = step;
        if (first_broken_step > 0 && broken != 2)
          stays_broken = false;
      }
    report("expected breaking step", expected_step);
    report("breaking step", first_broken_step);
    check("user criterion: breaking step - first step with extension > e_c",
          first_broken_step - expected_step,
          0,
          0);
    check("user criterion: bond stays broken (1 = yes)", stays_broken, 1, 0);
  });
}
