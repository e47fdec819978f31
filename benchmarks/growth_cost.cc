/**
 * The cost of one growth of an adaptive PD zone against the cells it converts and the size of
 * the zone (benchmarks/adaptive_growth.sh runs it).
 *
 *   periarlequin-growth-cost LATTICE_SPACING ZONE_LENGTH CELLS_PER_SIDE GROWTHS [STEPS_BETWEEN]
 *
 * A 2D plate 0.05 m high, FE cells 2 mm, a PD zone over its full height from x = 0 to
 * ZONE_LENGTH [m] (an overlap band of 2 cells), at rest. The criterion "advancing patch" below
 * converts, at each check, a patch of CELLS_PER_SIDE x CELLS_PER_SIDE FE cells at mid-height,
 * each patch ahead of the last, as a crack tip would drive it. GROWTHS checks, STEPS_BETWEEN
 * (10) steps apart. The time loop prints its timing sections: "PD zone growth" over GROWTHS is
 * the cost of one growth; the other sections over the steps, the cost of one step.
 */
#include <periarlequin/adaptivity/conversion_criterion.h>
#include <periarlequin/simulator.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iostream>
#include <sstream>

namespace
{
  using namespace dealii;

  /** Geometry shared by the case text and the criterion. */
  constexpr double cell_size = 0.002, plate_height = 0.05;

  /**
   * Each call flags a square patch of cells at mid-height whose left side is the right edge of
   * the patch flagged before (the first at "Start"): a tip that runs ahead by a patch a check.
   */
  template <int dim>
  class AdvancingPatch : public PeriArlequin::CellCentreCriterion<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Start", "0", Patterns::Double(), "x of the first patch [m].");
      prm.declare_entry("Cells per side", "2", Patterns::Integer(1), "Patch side [cells].");
    }

    void
    parse_parameters(ParameterHandler &prm) override
    {
      next_left = prm.get_double("Start");
      side      = prm.get_integer("Cells per side") * cell_size;
    }

    void
    mark_cells(const PeriArlequin::FEZone<dim> &fe_zone,
               const PeriArlequin::PDZone<dim> &pd_zone,
               std::vector<bool>               &convert) const override
    {
      PeriArlequin::CellCentreCriterion<dim>::mark_cells(fe_zone, pd_zone, convert);
      next_left += side;
    }

  protected:
    bool
    converts(const Point<dim> &c) const override
    {
      return c[0] > next_left && c[0] < next_left + side &&
             std::abs(c[1] - 0.5 * plate_height) < 0.5 * side;
    }

  private:
    mutable double next_left = 0;
    double         side      = 0;
  };
} // namespace

PERIARLEQUIN_REGISTER_CONVERSION_CRITERION(AdvancingPatch,
                                           "advancing patch",
                                           "a square patch of cells ahead of the last (benchmark)")

int
main(int argc, char **argv)
{
  // Threads as the application: DEAL_II_NUM_THREADS, else every core.
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, numbers::invalid_unsigned_int);
  if (argc < 5)
    {
      std::cerr << "usage: " << argv[0]
                << " LATTICE_SPACING ZONE_LENGTH CELLS_PER_SIDE GROWTHS [STEPS_BETWEEN]\n";
      return 1;
    }
  const double dx = std::stod(argv[1]);
  // Whole FE cells: the zone's edge on a cell face.
  const double       zone_length = cell_size * std::round(std::stod(argv[2]) / cell_size);
  const unsigned int side = std::stoi(argv[3]), growths = std::stoi(argv[4]);
  const unsigned int between = argc > 5 ? std::stoi(argv[5]) : 10;
  // Room for the patches, the band and the slave layer beyond the last one.
  const double length =
    cell_size * std::ceil((zone_length + side * cell_size * growths + 8 * cell_size) / cell_size);
  const double time_step = 0.4 * dx / 6000.;

  std::ostringstream text;
  text << "set Dimension = 2\n"
       << "subsection Geometry\n  set Lower corner = 0, 0\n  set Upper corner = " << length << ", "
       << plate_height << "\n  set Subdivisions = " << std::lround(length / cell_size) << ", "
       << std::lround(plate_height / cell_size) << "\nend\n"
       << "subsection Material\n  set Young's modulus = 72e9\n  set Poisson's ratio = 0.22\n"
       << "  set Density = 2440\nend\n"
       << "subsection Peridynamics\n  set Lattice spacing = " << dx
       << "\n  set Horizon factor = 3.015\n  set Fracture = true\n"
       << "  set Critical energy release rate = 3.8\n  set Region = 0, 0 : " << zone_length << ", "
       << plate_height << "\nend\n"
       << "subsection Coupling\n  set Method = weak\n  set Blending = force\n"
       << "  set Overlap width = " << 2 * cell_size << "\n  set Damping constant = 10\nend\n"
       << "subsection Adaptive PD zone\n  set Conversion criterion = advancing patch\n"
       << "  set Check interval = " << between << "\n  subsection advancing patch\n"
       << "    set Start = " << zone_length << "\n    set Cells per side = " << side
       << "\n  end\nend\n"
       << "subsection Time\n  set Time step = " << time_step
       << "\n  set End time = " << time_step * (between * growths + 0.5) << "\nend\n"
       << "subsection Output\n  set Output interval = 0\n  set Energy interval = 0\n"
       << "  set Progress interval = 0\n  set Print timing summary = true\nend\n";

  try
    {
      ParameterHandler prm;
      PeriArlequin::Simulator<2>::declare_parameters(prm);
      prm.parse_input_from_string(text.str());
      PeriArlequin::Simulator<2> simulator(prm, MPI_COMM_WORLD);
      simulator.run();
    }
  catch (const std::exception &error)
    {
      std::cerr << error.what() << std::endl;
      return 1;
    }
  return 0;
}
