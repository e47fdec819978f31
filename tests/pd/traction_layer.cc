// The bonds of a traction layer do not break (Peridynamics/Unbreakable traction layer). An
// unnotched glass plate 100 x 40 mm (E = 72 GPa, nu = 0.22, plane stress, lattice 0.625 mm,
// horizon 2 mm, G0 = 3.8 J/m^2: critical stretch sqrt(4 pi G0 / (9 E delta)) = 1.92e-4)
// under a traction of 4 MPa switched on at t = 0 on both y faces, to 10 us (the waves from
// the two faces cross in the middle and reflect once). The continuum's strain stays below
// the superposition of the two step waves, 2 t (1 - nu^2) / E = 1.06e-4 in uniaxial strain
// (t / E = 5.6e-5 once the free x edges relax it): 0.55 of the critical stretch, so no bond
// may break, and with the default none does (exact: a count).
// With the layer breakable, the layer (the particles within dx of a loaded face, which carry
// t / dx) passes the load on through fewer bonds than cross a plane in the bulk and breaks:
// bonds break, and every one of them has an end in the layer; the bulk does not break. This
// is what the default removes, and what makes the first check able to fail. On 2 ranks the
// same counts.

#include <map>
#include <set>

#include "../coupling/coupled_cases.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

namespace
{
  std::string
  plate(const bool breakable_layer)
  {
    return glass_plate_case(false,
                            6.25e-4,
                            0.0025,
                            0,
                            0,
                            4e6,
                            4e-8,
                            1e-5,
                            "force",
                            std::string("subsection Peridynamics\n  set Fracture = true\n"
                                        "  set Critical energy release rate = 3.8\n"
                                        "  set Unbreakable traction layer = ") +
                              (breakable_layer ? "false" : "true") + "\nend\n");
  }

  /** Broken bonds (each once) and those without an end within dx of a y face, all ranks. */
  std::pair<double, double>
  broken_bonds(const PDZone<2> &pd)
  {
    const double                                  dx = 6.25e-4;
    std::map<types::particle_index, unsigned int> local;
    const auto                                    ids = pd.particle_ids();
    for (unsigned int i = 0; i < ids.size(); ++i)
      local[ids[i]] = i;
    const auto x        = pd.reference_positions();
    const auto in_layer = [&](const Point<2> &p) { return p[1] < dx || p[1] > 0.04 - dx; };
    std::set<std::pair<types::particle_index, types::particle_index>> pairs;
    for (const auto &[a, b] : pd.get_bonds().broken_bonds(ids))
      pairs.emplace(std::min(a, b), std::max(a, b));
    // A bond between two ranks is stored on both: count it on the rank of its lower id.
    double all = 0, outside = 0;
    for (const auto &[a, b] : pairs)
      if (local.at(a) < pd.n_owned_particles())
        {
          ++all;
          outside += !in_layer(x[local.at(a)]) && !in_layer(x[local.at(b)]);
        }
    return {Utilities::MPI::sum(all, MPI_COMM_WORLD), Utilities::MPI::sum(outside, MPI_COMM_WORLD)};
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    auto kept = make_simulator<2>(plate(false));
    kept->run();
    check("default: broken bonds by 10 us", broken_bonds(*kept->get_pd_zone()).first, 0, 0);

    auto breakable = make_simulator<2>(plate(true));
    breakable->run();
    const auto [all, outside] = broken_bonds(*breakable->get_pd_zone());
    report("layer breakable: broken bonds by 10 us", all);
    check_above("layer breakable: broken bonds by 10 us", all, 0.5);
    check("layer breakable: broken bonds without an end in the traction layer", outside, 0, 0);
  });
}
