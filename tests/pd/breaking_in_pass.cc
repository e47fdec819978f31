// Under the critical-stretch criterion the LPS model breaks bonds inside its vectorised
// dilatation pass on the stencil layout (the bonds' byte mask), not in a loop of its own over
// the stored bonds. Both must break the same bonds: the pass forms each extension with the
// operations of BondFamilies::extension() and compares it as BreakableBonds does, and the
// dilatations then sum the same terms in the same order. So every comparison here has
// tolerance 0. The loop of its own is the criterion "stretch in a loop", registered below: it
// returns no critical_stretch(), so the PD zone breaks its bonds through break_bonds() and
// BreakableBonds::break_above_stretch(), as every criterion without a critical stretch does.
//  - One force evaluation of the cracked random blocks (2D, 3D; strain about 1e-2, a no-fail
//    layer whose bonds are unbreakable) at a tenth of the largest bond stretch: a fifth of
//    the bonds break (measured 0.20 in 2D, 0.21 in 3D; checked between 0.1 and 0.6); the
//    same bonds (the damage of every particle), the same force and energy densities.
//  - A running crack: the pre-cracked plate pulled apart, 300 steps, by the pass on 2
//    threads, by the pass on 1 thread and by the loop: the same energy history, broken-bond
//    count included, at every step.
// The .mpirun=2 output is the 1-rank one: on 2 ranks the bonds between the ranks are held by
// both, and each rank's pass must decide them as the other's does.

#include <periarlequin/pd/fracture_criterion.h>

#include <algorithm>

#include "../tests.h"
#include "plate.h"

namespace
{
  using namespace dealii;
  using namespace PeriArlequin;

  /** The critical stretch of CriticalStretchCriterion, broken in a loop over the bonds. */
  template <int dim>
  class StretchInALoop : public FractureCriterion<dim>
  {
  public:
    void
    initialize(const Parameters::Peridynamics<dim> &parameters,
               const PDMaterialModel<dim>          &model,
               const BondFamilies<dim> &) override
    {
      stretch = parameters.critical_stretch > 0 ?
                  parameters.critical_stretch :
                  model.critical_stretch(parameters.energy_release_rate, parameters.horizon());
    }
    void
    break_bonds(BreakableBonds<dim> &bonds, ArrayView<const double>) const override
    {
      bonds.break_above_stretch(stretch);
    }

  private:
    double stretch = 0;
  };

  PERIARLEQUIN_REGISTER_FRACTURE_CRITERION(StretchInALoop,
                                           "stretch in a loop",
                                           "the critical stretch, in a loop over the bonds")
} // namespace

using namespace PeriArlequinTests;

namespace
{
  /** Fracture by the criterion @p name, on the stencil layout. */
  std::string
  criterion(const std::string &name)
  {
    return "subsection Peridynamics\n  set Fracture = true\n  set Fracture criterion = " + name +
           "\n  set Force kernel = stencil\nend\n";
  }

  /** Owned particles (over all ranks) where @p a and @p b differ. */
  template <typename T>
  unsigned int
  n_differing(const ArrayView<const T> a, const ArrayView<const T> b)
  {
    unsigned int differing = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      differing += !(a[i] == b[i]);
    return Utilities::MPI::sum(differing, MPI_COMM_WORLD);
  }

  /**
   * A tenth of the largest stretch of the block's intact breakable bonds (the same on every
   * partition).
   */
  template <int dim>
  double
  breaking_stretch(const std::string &block)
  {
    auto simulator =
      make_simulator<dim>(block + criterion("critical stretch") +
                          "subsection Peridynamics\n  set Critical stretch = 1\nend\n");
    simulator->setup();
    const auto         &pd    = *simulator->get_pd_zone();
    BondFamilies<dim>   bonds = pd.get_bonds();
    BreakableBonds<dim> view(bonds, pd.get_state().displacements());
    double              largest = 0;
    view.for_each_intact([&](const auto &bond) {
      largest = std::max(largest, bond.extension() / bond.reference.length);
    });
    return Utilities::MPI::max(largest, MPI_COMM_WORLD) / 10.;
  }

  template <int dim>
  void
  compare_one_evaluation(const std::string &title, const std::string &block)
  {
    const std::string breaking = "subsection Peridynamics\n  set Critical stretch = " +
                                 Utilities::to_string(breaking_stretch<dim>(block)) + "\nend\n";
    auto in_pass = make_simulator<dim>(block + criterion("critical stretch") + breaking);
    auto in_loop = make_simulator<dim>(block + criterion("stretch in a loop") + breaking);
    in_pass->setup();
    in_loop->setup();
    auto &a = *in_pass->get_pd_zone();
    auto &b = *in_loop->get_pd_zone();
    AssertThrow(Utilities::MPI::min(int(a.get_bonds().uses_stencil()), MPI_COMM_WORLD) == 1 &&
                  a.get_critical_stretch() > 0 && b.get_critical_stretch() == 0,
                ExcMessage("not the stencil pass against the loop"));
    const auto bonds_before = a.n_global_bonds();
    a.compute_forces(0.);
    b.compute_forces(0.);
    const double broken_share = double(a.n_global_broken_bonds()) / bonds_before;
    check_above(title + ", share of the bonds broken in the pass", broken_share, 0.1);
    check_below(title + ", share of the bonds broken in the pass", broken_share, 0.6);
    check_below(title + ", broken bonds, pass minus loop",
                std::abs(double(a.n_global_broken_bonds()) - double(b.n_global_broken_bonds())),
                0.5);
    const std::vector<double> damage_a = a.get_bonds().damage(), damage_b = b.get_bonds().damage();
    check_below(title + ", particles whose damage differs",
                n_differing(make_array_view(damage_a), make_array_view(damage_b)),
                0.5);
    check_below(title + ", particles whose force density differs",
                n_differing(a.force_densities(), b.force_densities()),
                0.5);
    check_below(title + ", particles whose energy density differs",
                n_differing(a.energy_densities(), b.energy_densities()),
                0.5);
  }

  /** A layer of no-fail particles along the block's bottom: unbreakable bonds in the mask. */
  std::string
  no_fail_layer(const unsigned int dim)
  {
    return std::string("subsection Peridynamics\n  set No-fail region = ") +
           (dim == 2 ? "0, 0 : 0.02, 0.004" : "0, 0, 0 : 0.01, 0.01, 0.003") + "\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(
    argc,
    argv,
    [] {
      require_two_threads();
      compare_one_evaluation<2>("2D cracked block", cracked_random_block<2>() + no_fail_layer(2));
      compare_one_evaluation<3>("3D cracked block", cracked_random_block<3>() + no_fail_layer(3));

      const std::string plate   = plate_parameters(8e-4, true, 300);
      auto              in_pass = make_simulator<2>(plate + criterion("critical stretch"));
      auto in_pass_one_thread   = make_simulator<2>(plate + criterion("critical stretch"));
      auto in_loop              = make_simulator<2>(plate + criterion("stretch in a loop"));
      in_pass->run();
      on_one_thread([&] { in_pass_one_thread->run(); });
      in_loop->run();
      require_active_column(*in_pass, "pre-cracked plate, in the pass", "broken_bonds");
      check("pre-cracked plate, 300 steps, histories, pass vs loop",
            history_difference(in_pass->get_energy_history(),
                               in_loop->get_energy_history(),
                               "pre-cracked plate"),
            0.,
            0.);
      check("pre-cracked plate, 300 steps, histories, pass on 1 thread vs 2",
            history_difference(in_pass_one_thread->get_energy_history(),
                               in_pass->get_energy_history(),
                               "pre-cracked plate"),
            0.,
            0.);
    },
    2);
}
