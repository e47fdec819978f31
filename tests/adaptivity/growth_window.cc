// After a growth of the adaptive PD zone, the first force evaluation computes only the
// particles near what the growth changed (new particles, moved blending weights, bonds that
// became breakable, and everything within two bonds of them); the rest keep the scalars,
// force densities and energy densities computed at the same displacements before the growth.
// This must give what a full evaluation gives, to the bit: a particle's sums get their terms
// in an order fixed by the lattice alone, whichever bonds a pass visits.
//
// The notched glass plate of crack_cannot_outrun (a crack driven at about half the Rayleigh
// speed towards the edge of an adaptive zone, default adaptive settings, 4 MPa on its long
// edges), run to 14 us, with force blending and with energy blending (the state weights
// enter every pair force). After every growth the windowed results are compared with a full
// evaluation of the same state (PDZone::compute_internal_forces()): the largest difference
// of any owned particle's force density, energy density or model scalar must be exactly 0.
// The restriction must be real: at some growth the window holds less than half of the
// zone's particles (this zone is a strip 15 mm high, so a growth changes a large part of it).
// On 2 ranks (the window of a rank takes the changed scalars of its ghosts from their
// owners) the same verdicts. No repartition (Load imbalance tolerance 100): a repartition
// rebuilds the zone from scratch, with no window to test.

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  std::string
  crack_plate_text(const std::string &blending)
  {
    std::ostringstream text;
    text << "set Dimension = 2\n"
         << "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = 0.1, 0.04\n"
         << "  set Subdivisions = 40, 16\nend\n"
         << "subsection Material\n  set Young's modulus = 72e9\n  set Poisson's ratio = 0.22\n"
         << "  set Density = 2440\n  set Two-dimensional model = plane stress\nend\n"
         << "subsection Peridynamics\n  set Lattice spacing = 6.25e-4\n"
         << "  set Horizon factor = 3.2\n  set Fracture = true\n"
         << "  set Critical energy release rate = 3.8\n"
         << "  set Pre-cracks = 0, 0.02 : 0.05, 0.02\n"
         << "  set Region = 0, 0.0125 : 0.06, 0.0275\nend\n"
         << "subsection Coupling\n  set Method = weak\n  set Blending = " << blending << "\n"
         << "  set Overlap width = 0.005\n  set Damping constant = 10\nend\n"
         << "subsection Adaptive PD zone\n  set Conversion criterion = damage distance\n"
         << "  set Load imbalance tolerance = 100\nend\n"
         << opposite_y_tractions(4e6, 2)
         << "subsection Time\n  set Time step = 4e-8\n  set End time = 1.4e-5\nend\n"
         << quiet_output();
    return text.str();
  }

  /** Largest |a - b| over the first @p n entries. */
  template <typename Value>
  double
  largest_difference(const std::vector<Value> &a, ArrayView<const Value> b, const std::size_t n)
  {
    double largest = 0;
    for (std::size_t i = 0; i < n; ++i)
      if constexpr (std::is_same_v<Value, double>)
        largest = std::max(largest, std::abs(a[i] - b[i]));
      else
        largest = std::max(largest, (a[i] - b[i]).norm());
    return largest;
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    for (const std::string blending : {"force", "energy"})
      {
        auto simulator = make_simulator<2>(crack_plate_text(blending));
        simulator->setup();
        auto        &pd      = *simulator->get_pd_zone();
        unsigned int growths = 0;
        double       largest = 0, smallest_share = 1;
        unsigned int converted = simulator->n_converted_cells();
        while (simulator->get_step_number() < simulator->get_n_steps())
          {
            simulator->advance();
            if (simulator->n_converted_cells() == converted)
              continue;
            converted = simulator->n_converted_cells();
            ++growths;
            const unsigned int n_owned   = pd.n_owned_particles();
            const unsigned int n_scalars = pd.particle_scalars().size() / pd.get_bonds().n_total;
            const std::vector<Tensor<1, 2>> force(pd.force_densities().begin(),
                                                  pd.force_densities().end());
            const std::vector<double>       energy(pd.energy_densities().begin(),
                                             pd.energy_densities().end());
            const std::vector<double>       scalars(pd.particle_scalars().begin(),
                                              pd.particle_scalars().begin() + n_scalars * n_owned);
            const double                    share =
              Utilities::MPI::sum(static_cast<double>(pd.n_evaluated_after_growth()),
                                  MPI_COMM_WORLD) /
              pd.n_global_particles();
            pd.compute_internal_forces();
            largest =
              std::max({largest,
                        largest_difference(force, pd.force_densities(), n_owned),
                        largest_difference(energy, pd.energy_densities(), n_owned),
                        largest_difference(scalars, pd.particle_scalars(), n_scalars * n_owned)});
            smallest_share = std::min(smallest_share, share);
            report(blending + " blending: share of the particles evaluated after growth " +
                     std::to_string(growths),
                   share);
          }
        largest = Utilities::MPI::max(largest, MPI_COMM_WORLD);
        report(blending + " blending: growths", growths);
        check_above(blending + " blending: growths compared", growths, 2.5);
        check(blending + " blending: no repartition", simulator->n_repartitions(), 0, 0);
        check_below(blending +
                      " blending: smallest share of the zone evaluated after a growth (a window)",
                    smallest_share,
                    0.5);
        check(blending + " blending: largest |windowed - full evaluation| of force density, "
                         "energy density, scalars (bits)",
              largest,
              0,
              0);
      }
  });
}
