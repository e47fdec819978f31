// Crack tips, branches and crack area from a damage field of known geometry: pre-cracks on
// a 2D lattice (dx = 0.5 mm, delta = 1.6 mm) in a 100 x 60 mm plate. Record 0 holds a
// stem from the left edge to (50, 30) mm along the lattice rows; record 1 adds two branches
// of length L = 20 mm from its end at +-30 degrees (a Y, like a branched crack), record 2
// lengthens the upper branch to 30 mm. The particles cracked at record 0 are the origin.
// Checked against the geometry:
//  - record 0: no tip (nothing grew), crack area of the stem 50 mm within 0.5 delta (bonds
//    near the free left edge are missing from the per-length count: at most half a horizon);
//  - record 1: two branches, each tip within one horizon of its segment's end (the damage of
//    a particle near a crack's end falls below the threshold within a horizon; measured
//    0.16), path lengths L within half a horizon (the polyline along the inclined branch;
//    distances along lattice links alone are 7 % = 0.9 horizon longer at 30 degrees), the
//    crack area of both inclined branches 2 L within 5 % (the |xi|-weighted count is exact
//    along lattice rows; an inclined line is crossed by another mix of bonds; measured 0.5 %);
//  - record 2: the same two branches continue (no new one), the upper tip moved by 10 mm
//    within one horizon, and its speed is 10 mm over the 1e-5 s between the records within
//    5 % (the tip positions are uncertain by about 0.2 horizon = 0.3 mm, 3 % of 10 mm).

#include <periarlequin/postprocess/crack_diagnostics.h>

#include <cmath>

#include "../tests.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

namespace
{
  const double dx = 5e-4, delta = 3.2 * dx;

  std::string
  plate(const std::string &cracks)
  {
    return "set Dimension = 2\n"
           "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = 0.1, 0.06\n"
           "  set Subdivisions = 20, 12\nend\n"
           "subsection Peridynamics\n  set Region = 0, 0 : 0.1, 0.06\n"
           "  set Lattice spacing = 5e-4\n  set Horizon factor = 3.2\n"
           "  set Fracture = true\n  set Critical energy release rate = 3.8\n"
           "  set Pre-cracks = " +
           cracks + "\nend\n" + quiet_output();
  }

  Point<2>
  end_of_branch(const double length, const double angle)
  {
    return Point<2>(0.05 + length * std::cos(angle), 0.03 + length * std::sin(angle));
  }

  std::string
  segment(const Point<2> &a, const Point<2> &b)
  {
    std::ostringstream text;
    text << std::setprecision(12) << a[0] << ", " << a[1] << " : " << b[0] << ", " << b[1];
    return text.str();
  }

  struct Record
  {
    std::vector<CrackTracker<2>::CrackedParticle> cracked;
    double                                        area;
  };

  Record
  record(const std::string &cracks)
  {
    auto simulator = make_simulator<2>(plate(cracks));
    simulator->setup();
    const PDZone<2>          &pd     = *simulator->get_pd_zone();
    const std::vector<double> damage = pd.get_bonds().damage();
    std::vector<double>       local;
    for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
      if (damage[i] >= 0.35)
        local.insert(local.end(),
                     {static_cast<double>(pd.particle_ids()[i]),
                      pd.reference_positions()[i][0],
                      pd.reference_positions()[i][1]});
    Record result;
    for (const auto &part : Utilities::MPI::all_gather(MPI_COMM_WORLD, local))
      for (std::size_t k = 0; k < part.size(); k += 3)
        result.cracked.push_back(
          {static_cast<types::particle_index>(part[k]), Point<2>(part[k + 1], part[k + 2])});
    std::sort(result.cracked.begin(), result.cracked.end(), [](const auto &a, const auto &b) {
      return a.id < b.id;
    });
    result.area = broken_bond_area(pd.get_bonds(), dx, MPI_COMM_WORLD);
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const double      L = 0.02, angle = M_PI / 6;
    const Point<2>    junction(0.05, 0.03);
    const std::string stem  = segment(Point<2>(0, 0.03), junction);
    const std::string lower = segment(junction, end_of_branch(L, -angle));

    CrackTracker<2> tracker(2 * dx, 2 * delta);
    const Record    r0 = record(stem);
    tracker.update(0., r0.cracked);
    check_below("record 0: branches", tracker.n_active_branches(), 0.5);
    check_below("record 0: |stem area - 50 mm| / delta", std::abs(r0.area - 0.05) / delta, 0.5);

    const Record r1 =
      record(stem + " ; " + segment(junction, end_of_branch(L, angle)) + " ; " + lower);
    tracker.update(1e-5, r1.cracked);
    check("record 1: branches", tracker.n_active_branches(), 2, 0);
    const auto &branches = tracker.get_branches();
    for (const auto &branch : branches)
      {
        const bool        upper = branch.tips.back()[1] > 0.03;
        const std::string name  = upper ? "upper" : "lower";
        const Point<2>    end   = end_of_branch(L, upper ? angle : -angle);
        check_below("record 1: " + name + " tip distance to the branch end / delta",
                    branch.tips.back().distance(end) / delta,
                    1.);
        check_below("record 1: " + name + " |path length - L| / delta",
                    std::abs(branch.path_lengths.back() - L) / delta,
                    0.5);
      }
    check_below("record 1: |area of both branches - 2 L| / 2 L",
                std::abs(r1.area - r0.area - 2 * L) / (2 * L),
                0.05);

    const double longer = 0.03;
    const Record r2 =
      record(stem + " ; " + segment(junction, end_of_branch(longer, angle)) + " ; " + lower);
    tracker.update(2e-5, r2.cracked);
    check("record 2: branches", tracker.n_active_branches(), 2, 0);
    check("record 2: branches ever seen", tracker.get_branches().size(), 2, 0);
    for (const auto &branch : tracker.get_branches())
      if (branch.tips.back()[1] > 0.03)
        {
          check_below("record 2: upper tip advance - 10 mm, / delta",
                      std::abs(branch.tips.back().distance(branch.tips[0]) - 0.01) / delta,
                      1.);
          report("record 2: upper tip speed [m/s]", branch.speed(5));
          check_below("record 2: |speed / (10 mm / 1e-5 s) - 1|",
                      std::abs(branch.speed(5) / 1e3 - 1.),
                      0.05);
        }
  });
}
