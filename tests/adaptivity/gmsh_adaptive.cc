// The adaptive PD zone on Gmsh meshes: the plate with a hole of
// parameter_files/gmsh_plate_with_hole_2d.prm (glass, 100 x 50 mm, hole of radius 6 mm, 394
// unstructured quadrilaterals, PD on [35, 65] x [10, 40] mm around the hole, weak coupling
// across an 8 mm band) and the block of coupling/gmsh_block_3d (steel, 40 x 20 x 10 mm, 102
// hexahedra: unstructured quadrilaterals extruded, PD on [12, 28] x [5, 15] mm through the
// thickness, lattice 0.5 mm, band 8 mm). Converted cells join the PD region as cells: no box
// follows them.
// 1. One conversion at t = 0 of the cells a criterion registered here flags (centre in
//    [65, 80] x [10, 40] mm in 2D, [28, 34] x [5, 15] mm in 3D: unstructured cells to the
//    right of the PD region), under a uniform velocity ((3, -2), (3, -2, 1) m/s) and a smooth
//    non-uniform one, no strain:
//    - the momentum of both zones is conserved to round-off (1e-12 relative);
//    - the pure PD region is the union of the PD cells: a particle has the blending weight
//      alpha = 0 exactly when a cell that holds it is PD, which this test decides on its own
//      (the cells whose inverse mapping puts the particle within 1e-10 of the unit cell; a
//      cell is PD when the centre lies in the
//      original region or in the criterion's box); mismatches 0 (alpha is computed from the
//      distance to the region's cells, the test's rule from the mesh alone).
// 2. A running crack grows the zone, on 2 ranks as on 1: the example's 4 MPa pull with the
//    damage-distance criterion and default settings to 20 us. With the fixed zone the cracks
//    from the hole's poles reach the overlap at 14.4 us and the run stops there; here the
//    run reaches the end time and the zone grows; on 2 ranks (repartitioning) broken bonds,
//    converted cells and particles equal rank 0 alone at every record, energies to 1e-10
//    (sums in another order).

#include <periarlequin/adaptivity/conversion_criterion.h>

#include <deal.II/fe/mapping_q.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  /** Is @p c the centre of a cell the test criterion flags? */
  template <int dim>
  bool
  in_flagged_box(const Point<dim> &c)
  {
    if constexpr (dim == 2)
      return c[0] > 0.065 && c[0] < 0.08 && c[1] > 0.01 && c[1] < 0.04;
    return c[0] > 0.028 && c[0] < 0.034 && c[1] > 0.005 && c[1] < 0.015;
  }

  /** Is a cell PD by the test's own rule: its centre in the original region or flagged? */
  template <int dim>
  bool
  pd_cell(const Point<dim> &c)
  {
    const bool original = dim == 2 ? c[0] > 0.035 && c[0] < 0.065 && c[1] > 0.01 && c[1] < 0.04 :
                                     c[0] > 0.012 && c[0] < 0.028 && c[1] > 0.005 && c[1] < 0.015;
    return original || in_flagged_box(c);
  }

  /** Flags the cells of in_flagged_box(). */
  template <int dim>
  class RightOfRegionConversion : public PeriArlequin::CellCentreCriterion<dim>
  {
  protected:
    bool
    converts(const Point<dim> &c) const override
    {
      return in_flagged_box(c);
    }
  };

  std::string
  plate_text(const std::string &adaptive, const double end_time)
  {
    std::ifstream      file(PERIARLEQUIN_SOURCE_DIR "/parameter_files/gmsh_plate_with_hole_2d.prm");
    std::ostringstream text;
    text << file.rdbuf();
    text << "subsection Geometry\n  set Mesh file = " PERIARLEQUIN_SOURCE_DIR
            "/examples/gmsh/plate_with_hole.msh\nend\n"
         << "subsection Time\n  set End time = " << end_time << "\nend\n"
         << adaptive << quiet_output() << "subsection Output\n  set Energy interval = 25\nend\n"
         << "subsection Postprocess\n  set List of postprocessors = energies, cracks, zone "
            "sizes\nend\n";
    return text.str();
  }

  template <int dim>
  std::string
  at_rest_text(const std::string &velocity)
  {
    const std::string conversion =
      "subsection Adaptive PD zone\n  set Conversion criterion = test right of region\n"
      "  set Check interval = 1000\nend\n"
      "subsection Boundary conditions\n  subsection Boundary 0\n    set Type = free\n  end\n"
      "  subsection Boundary 1\n    set Type = free\n  end\nend\n"
      "subsection Initial conditions\nsubsection function\n"
      "  subsection Velocity\n    set Function expression = " +
      velocity + "\n  end\nend\nend\n";
    if constexpr (dim == 2)
      return plate_text(conversion, 1e-7);
    return std::string("set Dimension = 3\nsubsection Geometry\n  set Mesh file = ") +
           PERIARLEQUIN_SOURCE_DIR
           "/tests/coupling/gmsh_block_3d.msh\nend\n"
           "subsection Material\n  set Young's modulus = 200e9\n  set Poisson's ratio = 0.3\n"
           "  set Density = 7800\nend\n"
           "subsection Peridynamics\n  set Region = 0.012, 0.005, 0 : 0.028, 0.015, 0.01\n"
           "  set Lattice spacing = 5e-4\n  set Horizon factor = 3\nend\n"
           "subsection Coupling\n  set Method = weak\n  set Blending = force\n"
           "  set Overlap width = 0.008\nend\n"
           "subsection Time\n  set Time step = 5e-8\n  set End time = 1e-7\n"
           "  set Stability estimate iterations = 20\nend\n" +
           conversion + quiet_output();
  }

  /** The cells whose inverse mapping puts @p x within 1e-10 of the unit cell. */
  template <int dim>
  bool
  held_by_pd_cell(const Triangulation<dim> &triangulation, const Point<dim> &x)
  {
    const MappingQ<dim> mapping(1);
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        if (cell->is_artificial() || !cell->bounding_box().point_inside(x, 1e-10))
          continue;
        try
          {
            const Point<dim> unit = mapping.transform_real_to_unit_cell(cell, x);
            if (GeometryInfo<dim>::is_inside_unit_cell(unit, 1e-10) && pd_cell(cell->center()))
              return true;
          }
        catch (const typename Mapping<dim>::ExcTransformationFailed &)
          {
            // x lies far outside this cell.
          }
      }
    return false;
  }

  template <int dim>
  void
  convert_at_rest(const std::string &velocity)
  {
    const std::string name      = std::to_string(dim) + "D, velocity (" + velocity + "): ";
    auto              simulator = make_simulator<dim>(at_rest_text<dim>(velocity));
    simulator->setup();
    const auto momentum = [&] {
      return simulator->get_fe_zone().linear_momentum() +
             simulator->get_pd_zone()->linear_momentum();
    };
    const Tensor<1, dim> before    = momentum();
    const unsigned int   converted = simulator->grow_pd_zone();
    const auto  &triangulation     = simulator->get_fe_zone().get_dof_handler().get_triangulation();
    unsigned int expected          = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && in_flagged_box(cell->center()))
        ++expected;
    check(name + "cells converted (counted by centre here)",
          converted,
          Utilities::MPI::sum(expected, MPI_COMM_WORLD),
          0);
    check_below(name + "|momentum change| / |momentum|",
                (momentum() - before).norm() / before.norm(),
                1e-12);

    // alpha = 0 exactly at the particles that a PD cell holds.
    const auto  &pd_zone    = *simulator->get_pd_zone();
    const auto   x          = pd_zone.reference_positions();
    const auto   alpha      = pd_zone.blending_weights();
    unsigned int mismatches = 0, in_pd_cells = 0;
    for (unsigned int i = 0; i < pd_zone.n_owned_particles(); ++i)
      {
        const bool in_pd = held_by_pd_cell(triangulation, x[i]);
        mismatches += in_pd != (alpha[i] == 0);
        in_pd_cells += in_pd;
      }
    check_above(name + "particles in PD cells",
                Utilities::MPI::sum(in_pd_cells, MPI_COMM_WORLD),
                0.5);
    check(name + "particles with alpha = 0 not in a PD cell, or in one with alpha > 0",
          Utilities::MPI::sum(mismatches, MPI_COMM_WORLD),
          0,
          0);
  }
} // namespace

PERIARLEQUIN_REGISTER_CONVERSION_CRITERION(RightOfRegionConversion,
                                           "test right of region",
                                           "cells right of the PD region (test)")

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    for (const std::string velocity : {"3; -2", "3 + sin(40*x); -2 + cos(30*y)"})
      convert_at_rest<2>(velocity);
    for (const std::string velocity : {"3; -2; 1", "3 + sin(40*x); -2 + cos(30*y); 1 + sin(50*z)"})
      convert_at_rest<3>(velocity);

    // The plate with a hole under its pull (loaded faces x = 0 and x = 0.1 m): with the
    // strain criterion the zone grows toward the loaded faces, whose cells must stay FE.
    for (const std::string criterion : {"damage distance", "damage distance, strain"})
      {
        const std::string running =
          plate_text("subsection Adaptive PD zone\n  set Conversion criterion = " + criterion +
                       "\nend\n",
                     2e-5);
        auto plate = make_simulator<2>(running, MPI_COMM_WORLD);
        plate->run();
        const auto       &history = plate->get_energy_history();
        const std::string name    = criterion + ": ";
        check(name + "end time reached [us]", 1e6 * plate->get_time(), 20, 1e-9);
        check_above(name + "broken bond ends during the run (cracks ran)",
                    history.column("broken_bonds").back(),
                    100);
        check_above(name + "cells converted (the zone grew)",
                    history.column("converted_cells").back(),
                    0.5);
        // No particle that carries its own force within two bond reaches 2 (delta + dx/2)
        // of a loaded face (the case's horizon 3 dx, dx = 0.375 mm): the bound is exact, a
        // particle at it is allowed.
        const auto  &pd_zone  = *plate->get_pd_zone();
        const auto   x        = pd_zone.reference_positions();
        const double dx       = 3.75e-4;
        double       smallest = 1;
        for (unsigned int i = 0; i < pd_zone.n_owned_particles(); ++i)
          if (!pd_zone.is_slave(i))
            smallest = std::min({smallest, x[i][0], 0.1 - x[i][0]});
        check_above(name + "distance of the free particles from a loaded face over 2 (delta + "
                           "dx/2)",
                    Utilities::MPI::min(smallest, MPI_COMM_WORLD) / (2 * (3 * dx + 0.5 * dx)),
                    1 - 1e-9);
        check_growth_matches_rank_0(*plate, running);
      }
  });
}
