// The Gmsh example (parameter_files/gmsh_plate_with_hole_2d.prm on
// examples/gmsh/plate_with_hole.msh: a glass plate 100 x 50 mm with a hole of radius 6 mm,
// 394 unstructured quadrilaterals, PD around the hole coupled across an 8 mm band, 4 MPa
// pulled at both ends), cut at 11.2 us:
//  - every lattice site of the PD zone's extent (within band + delta + dx/2 of the PD box)
//    inside the meshed plate holds exactly one particle: the count equals an independent
//    count, made here from the plate's box and the hole's polygon read from the .msh file
//    by this test (ray casting), exactly;
//  - the FE-to-particle interpolation N on these distorted cells reproduces a linear field
//    (mapped Q1 holds linear functions exactly) at every particle in an FE cell to 1e-12 of
//    its magnitude: the particles' reference locations come from the inverse mapping;
//  - the crack starts where linear elasticity puts the largest hoop stress of a hole under
//    tension along x, at its top and bottom (Kirsch: 3 sigma at theta = 90 deg, -sigma at
//    0 deg): every damaged particle at the first record with broken bonds lies within two
//    horizons of a pole, none near the hole's left and right ends; and not before the waves
//    from both ends meet at the hole (each alone gives at most about 3 x 4 MPa there, below
//    the bonds' critical stress E s_c = 18 MPa): t_init > 0.05 m / c = 8.98 us
//    (c = sqrt(E / (rho (1 - nu^2))), plane stress); and before 0.05 m / c + 3 us: the two
//    fronts have crossed the hole 2 r / c = 2.2 us after they meet, and with them the
//    superposed 8 MPa, concentrated at the poles to well above 18 MPa, is there;
//  - on 2 ranks the energy history (broken bonds included) equals 1 rank to 1e-10 of each
//    column's magnitude (sums in another order), and bonds broke in that run.

#include <fstream>
#include <map>
#include <sstream>

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  const std::string mesh_file = PERIARLEQUIN_SOURCE_DIR "/examples/gmsh/plate_with_hole.msh";

  std::string
  case_text()
  {
    std::ifstream      file(PERIARLEQUIN_SOURCE_DIR "/parameter_files/gmsh_plate_with_hole_2d.prm");
    std::ostringstream text;
    text << file.rdbuf();
    text << "subsection Geometry\n  set Mesh file = " << mesh_file << "\nend\n"
         << "subsection Time\n  set End time = 1.12e-5\nend\n"
         << quiet_output() << "subsection Output\n  set Energy interval = 10\nend\n"
         << "subsection Postprocess\n  set List of postprocessors = energies, cracks\nend\n";
    return text.str();
  }

  /** The segments of the hole (physical curve 4) of a Gmsh 2.2 ASCII file. */
  std::vector<std::pair<Point<2>, Point<2>>>
  hole_segments()
  {
    std::ifstream                              file(mesh_file);
    std::string                                line;
    std::map<unsigned int, Point<2>>           nodes;
    std::vector<std::pair<Point<2>, Point<2>>> segments;
    while (std::getline(file, line))
      if (line == "$Nodes")
        {
          unsigned int n;
          file >> n;
          for (unsigned int k = 0; k < n; ++k)
            {
              unsigned int id;
              double       x, y, z;
              file >> id >> x >> y >> z;
              nodes[id] = Point<2>(x, y);
            }
        }
      else if (line == "$Elements")
        {
          unsigned int n;
          file >> n;
          std::getline(file, line);
          for (unsigned int k = 0; k < n; ++k)
            {
              std::getline(file, line);
              std::istringstream fields(line);
              unsigned int       id, type, n_tags, physical;
              fields >> id >> type >> n_tags >> physical;
              std::vector<unsigned int> rest;
              unsigned int              value;
              while (fields >> value)
                rest.push_back(value);
              if (type == 1 && physical == 4)
                segments.emplace_back(nodes.at(rest[rest.size() - 2]), nodes.at(rest.back()));
            }
        }
    AssertThrow(segments.size() > 8, ExcMessage("no hole in " + mesh_file));
    return segments;
  }

  bool
  in_polygon(const Point<2> &x, const std::vector<std::pair<Point<2>, Point<2>>> &segments)
  {
    bool inside = false;
    for (const auto &[a, b] : segments)
      if ((a[1] > x[1]) != (b[1] > x[1]) &&
          x[0] < a[0] + (x[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
        inside = !inside;
    return inside;
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    const double   dx = 3.75e-4, delta = 3 * dx, band = 0.008, E = 72e9, nu = 0.22, rho = 2440;
    const Point<2> pd_lower(0.035, 0.01), pd_upper(0.065, 0.04);

    auto simulator = make_simulator<2>(case_text());
    simulator->setup();
    const auto &pd = *simulator->get_pd_zone();

    // Independent count of the sites that must hold a particle.
    const auto         hole     = hole_segments();
    const double       reach    = (band + 2 * (delta + 0.5 * dx)) * (1 + 1e-10);
    unsigned long long expected = 0;
    for (unsigned int i = 0; (i + 0.5) * dx < 0.1; ++i)
      for (unsigned int j = 0; (j + 0.5) * dx < 0.05; ++j)
        {
          const Point<2> x((i + 0.5) * dx, (j + 0.5) * dx);
          if (distance_to_box(x, pd_lower, pd_upper) <= reach && !in_polygon(x, hole))
            ++expected;
        }
    report("sites expected", expected);
    report("particles", pd.n_global_particles());
    check("particles against the sites inside the plate",
          static_cast<double>(pd.n_global_particles()),
          static_cast<double>(expected),
          0);

    // A linear field through N at the particles in FE cells (alpha > 0).
    class Linear : public Function<2>
    {
    public:
      Linear()
        : Function<2>(2)
      {}
      double
      value(const Point<2> &p, const unsigned int c) const override
      {
        return c == 0 ? 1e-3 * (2 * p[0] - 3 * p[1]) + 1e-5 : 1e-3 * (0.5 * p[0] + p[1]) - 2e-5;
      }
    };
    check_below("linear field through N, error / magnitude",
                interpolation_error_at_particles(*simulator, Linear()),
                1e-12);

    // Where and when the crack starts: step until a bond breaks.
    const unsigned int n_steps = simulator->get_n_steps();
    while (simulator->get_step_number() < n_steps && pd.n_global_broken_bonds() == 0)
      simulator->advance();
    AssertThrow(pd.n_global_broken_bonds() > 0, ExcMessage("no bond broke: the case is vacuous"));
    const double wave_speed = std::sqrt(E / (rho * (1 - nu * nu)));
    report("initiation time", simulator->get_time());
    check_above("initiation time - (0.05 m) / c [s]", simulator->get_time() - 0.05 / wave_speed, 0);
    check_below("initiation time [s]", simulator->get_time(), 0.05 / wave_speed + 3e-6);

    // The hole's poles (top, bottom) and sides (left, right), radius 6 mm.
    const Point<2> poles[2]  = {Point<2>(0.05, 0.031), Point<2>(0.05, 0.019)};
    const Point<2> sides[2]  = {Point<2>(0.044, 0.025), Point<2>(0.056, 0.025)};
    const auto     x         = pd.reference_positions();
    const auto     damage    = pd.get_bonds().damage();
    double         from_pole = 0, nearest_side = std::numeric_limits<double>::max();
    unsigned int   n_damaged = 0;
    for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
      if (damage[i] > 0)
        {
          ++n_damaged;
          from_pole =
            std::max(from_pole, std::min(x[i].distance(poles[0]), x[i].distance(poles[1])));
          nearest_side = std::min({nearest_side, x[i].distance(sides[0]), x[i].distance(sides[1])});
        }
    report("damaged particles at initiation", Utilities::MPI::sum(n_damaged, MPI_COMM_WORLD));
    check_below("at initiation, largest distance of damage from a pole / horizon",
                Utilities::MPI::max(from_pole, MPI_COMM_WORLD) / delta,
                2);
    check_above("at initiation, least distance of damage from the hole's sides / horizon",
                Utilities::MPI::min(nearest_side, MPI_COMM_WORLD) / delta,
                2);

    if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      check_below("2 ranks vs 1 rank, largest history difference",
                  parallel_vs_serial_history_difference<2>(case_text(), "plate", "broken_bonds"),
                  1e-10);
  });
}
