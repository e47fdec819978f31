#include <periarlequin/pd/pd_zone.h>

#include <deal.II/base/utilities.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace PeriArlequin
{
  namespace
  {
    /** @p region as the text of Peridynamics/Region, for messages. */
    template <int dim>
    std::string
    region_text(const Region<dim> &region)
    {
      std::ostringstream text;
      for (const Box<dim> &box : region.boxes)
        text << (text.tellp() > 0 ? " ; " : "") << box.lower << " : " << box.upper;
      if (!region.cells.empty())
        text << (text.tellp() > 0 ? " ; " : "") << "and " << region.cells.size()
             << " cells of the mesh";
      return text.str();
    }

    /**
     * The boundary with a traction or a displacement nearest to @p point and its distance, over
     * the faces of all ranks' owned cells (each face by its bounding box: exact on a box mesh,
     * a lower bound on curved faces); infinite distance if no boundary is loaded.
     */
    template <int dim>
    std::pair<types::boundary_id, double>
    nearest_loaded_boundary(const Triangulation<dim> &triangulation,
                            const ProblemData<dim>   &data,
                            const MPI_Comm            communicator,
                            const Point<dim>         &point)
    {
      double             nearest = std::numeric_limits<double>::infinity();
      types::boundary_id id      = numbers::invalid_boundary_id;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() < ProblemData<dim>::n_boundaries &&
                data.boundary_conditions[face->boundary_id()].type != BoundaryType::free)
              {
                const auto   corners = face->bounding_box().get_boundary_points();
                const double d       = Box<dim>{corners.first, corners.second}.distance(point);
                if (d < nearest)
                  {
                    nearest = d;
                    id      = face->boundary_id();
                  }
              }
      const double global = Utilities::MPI::min(nearest, communicator);
      return {Utilities::MPI::min(nearest == global ? id : numbers::invalid_boundary_id,
                                  communicator),
              global};
    }
  } // namespace

  template <int dim>
  void
  PDZone<dim>::check_region_follows_cells() const
  {
    // A cell with a vertex inside the region (more than a tolerance from its boundary) and
    // one outside it: its centre's side would decide for all of it.
    const double tolerance = 1e-8 * parameters.lattice_spacing;
    const auto   inside    = [&](const Point<dim> &x) {
      for (const Box<dim> &box : region.boxes)
        {
          bool in = true;
          for (unsigned int d = 0; d < dim; ++d)
            in = in && x[d] > box.lower[d] + tolerance && x[d] < box.upper[d] - tolerance;
          if (in)
            return true;
        }
      return false;
    };
    bool       straddles = false;
    Point<dim> where;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && !straddles)
        {
          bool some_in = false, some_out = false;
          for (const unsigned int v : cell->vertex_indices())
            {
              some_in  = some_in || inside(cell->vertex(v));
              some_out = some_out || !region.contains(cell->vertex(v), tolerance);
            }
          if (some_in && some_out)
            {
              straddles = true;
              where     = cell->center();
            }
        }
    if (Utilities::MPI::logical_or(straddles, communicator))
      {
        std::ostringstream allowed;
        allowed << "with Geometry/Mesh file, boxes whose edges follow the faces of the cells "
                   "(mesh the PD region as surfaces of its own in Gmsh)";
        if (straddles)
          allowed << "; the cell around " << where << " m lies across the region's boundary";
        throw_invalid_parameter("Peridynamics/Region", region_text(region), allowed.str());
      }
  }

  template <int dim>
  void
  PDZone<dim>::check_damage_near_overlap(const double                   time,
                                         const std::vector<StoredBond> &broken) const
  {
    const auto            ids   = ghosts.ids();
    types::particle_index first = std::numeric_limits<types::particle_index>::max();
    unsigned int          local = 0;
    for (const StoredBond &bond : broken)
      {
        const auto watched =
          std::lower_bound(bonds_near_overlap.begin(),
                           bonds_near_overlap.end(),
                           bond.index,
                           [](const auto &entry, const std::size_t n) { return entry.second < n; });
        if (watched != bonds_near_overlap.end() && watched->second == bond.index &&
            ids[watched->first] < first)
          {
            first = ids[watched->first];
            local = watched->first;
          }
      }
    const types::particle_index global_first = Utilities::MPI::min(first, communicator);
    if (global_first == std::numeric_limits<types::particle_index>::max())
      return;
    Point<dim> position;
    for (unsigned int d = 0; d < dim; ++d)
      position[d] =
        Utilities::MPI::max(first == global_first ? ghosts.reference_positions()[local][d] :
                                                    -std::numeric_limits<double>::max(),
                            communicator);
    std::ostringstream statement;
    statement << "Damage reached the overlap at t = " << time << " s: a bond of the particle at ("
              << position << ") m, one bond away from the overlap, broke. The coupling assumes "
              << "an intact continuum in the overlap and the FE zone, so the run stops here.";
    // Damage at a loaded face has a cause of its own, whatever grows or stays fixed.
    const auto [boundary, distance] =
      problem_data ?
        nearest_loaded_boundary(triangulation, *problem_data, communicator, position) :
        std::make_pair(numbers::invalid_boundary_id, std::numeric_limits<double>::infinity());
    const double depth = parameters.coupled_particle_reach();
    if (distance < depth)
      statement << " The particle lies " << distance << " m from boundary " << boundary
                << ", which carries a "
                << (problem_data->boundary_conditions[boundary].type == BoundaryType::traction ?
                      "traction" :
                      "displacement")
                << ": the PD layers along a loaded face carry it at more than the continuum's "
                   "strain and can break (in pure PD too, a surface effect of the lattice; the "
                   "bonds of a traction layer itself are kept by Peridynamics/Unbreakable "
                   "traction layer), and a band along that face cannot hold that damage. A "
                   "No-fail region (Peridynamics/No-fail region) a horizon deep along the face "
                   "keeps those bonds intact; or keep the PD zone two bond reaches ("
                << depth << " m) and the band away from it.";
    AssertThrow(false,
                ExcDamageNearOverlap(
                  statement.str(),
                  "Enlarge the PD region around the crack path (Peridynamics/Region, "
                  "Coupling/Overlap region and Coupling/Finite element region), or let it grow "
                  "with the crack (Adaptive PD zone/Conversion criterion)."));
  }

  template <int dim>
  void
  PDZone<dim>::check_clear_of_loaded_boundaries(const double depth) const
  {
    // The boundary faces with a traction or a displacement, from all cells this rank knows
    // (artificial ones too: without manifolds their faces hold the finer faces); for each,
    // the owned particles at the lattice sites around it, with centre distance - half the
    // face's diameter bounding the distance to the face from below. The check costs the
    // boundary's size, not particles times faces.
    // The faces of cells whose box holds no site of the extent belong to another body (an FE
    // striker or support across a gap): the FE zone loads them.
    const auto holds_sites = [&](const auto &cell) {
      const auto [lower, upper] = cell_bounds(cell);
      bool any                  = false;
      lattice.for_each_site_in(lower, upper, [&](const auto &site) {
        any = any || extent(lattice.position(site));
      });
      return any;
    };
    const auto   x     = ghosts.reference_positions();
    bool         close = false;
    Point<dim>   where;
    unsigned int id = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (!close && face->at_boundary() && face->boundary_id() < ProblemData<dim>::n_boundaries &&
            problem_data->boundary_conditions[face->boundary_id()].type != BoundaryType::free &&
            holds_sites(cell))
          {
            const Point<dim> centre = face->center();
            const double     radius = 0.5 * face->diameter();
            Point<dim>       lower = centre, upper = centre;
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[d] -= radius + depth;
                upper[d] += radius + depth;
              }
            lattice.for_each_site_in(lower, upper, [&](const auto &site) {
              const unsigned int i = ghosts.local_index(lattice.id(site));
              if (!close && i < ghosts.n_owned() && !slave[i] &&
                  x[i].distance(centre) - radius < depth)
                {
                  close = true;
                  where = x[i];
                  id    = face->boundary_id();
                }
            });
          }
    if (Utilities::MPI::logical_or(close, communicator))
      {
        std::ostringstream allowed;
        allowed << "with Geometry/Mesh file, a PD region whose particles (slaves excepted) stay "
                << depth << " m (two bond reaches) away from the boundaries that carry a "
                << "traction or a displacement: give those boundaries to the FE zone";
        if (close)
          allowed << " (the particle at " << where << " m is near boundary " << id << ")";
        throw_invalid_parameter("Peridynamics/Region", region_text(region), allowed.str());
      }
  }

  template <int dim>
  void
  PDZone<dim>::check_horizon_covered() const
  {
    // Ghost particles come from one layer of ghost cells: every cell holding particles must
    // be at least as wide as the bonds reach, delta + dx/2 with the partial volumes of eq. 22.
    double smallest = std::numeric_limits<double>::max();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && particle_handler.n_particles_in_cell(cell) > 0)
        smallest = std::min(smallest, cell_width(cell));
    smallest           = Utilities::MPI::min(smallest, communicator);
    const double reach = parameters.horizon() + 0.5 * parameters.lattice_spacing;
    if (smallest < reach * (1. - 1e-12))
      {
        std::ostringstream allowed;
        allowed << "a horizon whose bonds, reaching delta + dx/2 = " << reach
                << " m, fit in the smallest background cell holding particles (" << smallest
                << " m), since ghost particles come from one layer of cells: use coarser "
                   "cells (Geometry/Subdivisions, Global refinements) or a smaller horizon";
        throw_invalid_parameter("Peridynamics/Horizon factor",
                                parameters.horizon_factor,
                                allowed.str());
      }
  }

  template <int dim>
  void
  PDZone<dim>::check_lattice_fits(const bool coupled) const
  {
    const double dx      = parameters.lattice_spacing;
    const auto   as_text = [](const double x) {
      std::ostringstream text;
      text.precision(3);
      text << x;
      return text.str();
    };
    // Particle ids are lexicographic site indices over the domain's lattice.
    double n_domain_sites = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n_domain_sites *= std::floor((domain.upper[d] - domain.lower[d]) / dx + 1e-8);
    const double largest_id =
      static_cast<double>(std::numeric_limits<types::particle_index>::max());
    if (n_domain_sites > largest_id)
      throw_invalid_parameter("Peridynamics/Lattice spacing",
                              dx,
                              "a spacing for which the lattice over the domain's box has at "
                              "most " +
                                as_text(largest_id) + " sites (particle ids are " +
                                std::to_string(8 * sizeof(types::particle_index)) +
                                "-bit lattice indices); this one would have " +
                                as_text(n_domain_sites) + " sites");
    // The bonds of a full family: the lattice offsets within delta + dx/2.
    const double reach = parameters.horizon_factor + 0.5;
    const double family =
      dim == 2 ? numbers::PI * reach * reach : 4. / 3. * numbers::PI * reach * reach * reach;
    const double largest_family = 1e5;
    if (family > largest_family)
      throw_invalid_parameter("Peridynamics/Horizon factor",
                              parameters.horizon_factor,
                              "a horizon factor whose family holds at most " +
                                as_text(largest_family) + " bonds; this one would hold " +
                                as_text(family));
    // The sites of the region, grown by the slave reach when coupled, clipped to the domain.
    const double grow    = coupled ? parameters.coupled_particle_reach() : 0.;
    double       n_sites = 0;
    for (const Box<dim> &box : parameters.region.boxes)
      {
        double sites = 1;
        for (unsigned int d = 0; d < dim; ++d)
          sites *= std::max(0.,
                            std::min(box.upper[d] + grow, domain.upper[d]) -
                              std::max(box.lower[d] - grow, domain.lower[d])) /
                     dx +
                   1;
        n_sites += sites;
      }
    // A lower bound: a coupled zone holds its overlap too.
    n_sites = std::min(n_sites, n_domain_sites);
    // About 200 bytes a particle and 4.4 a bond of its family: 0.97 KB a particle was
    // measured in 3D at m = 3 (doc/pd_kernel.md); the bond lists take more. The ranks that
    // share this node share its memory.
    const double bytes   = n_sites * (200. + 4.4 * family);
    const double n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    MPI_Comm     node;
    MPI_Comm_split_type(communicator, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    const double ranks_on_node = Utilities::MPI::n_mpi_processes(node);
    MPI_Comm_free(&node);
    const double node_bytes =
      static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
    if (node_bytes > 0 && bytes / n_ranks * ranks_on_node > node_bytes)
      throw_invalid_parameter("Peridynamics/Lattice spacing",
                              dx,
                              "a spacing whose zone fits in memory: 'Peridynamics/Region' "
                              "would hold about " +
                                as_text(n_sites) + " particles with " + as_text(family) +
                                " bonds each, about " + as_text(bytes / 1e9) + " GB, or " +
                                as_text(bytes / n_ranks * ranks_on_node / 1e9) + " GB on the " +
                                as_text(ranks_on_node) + " of " + as_text(n_ranks) +
                                " rank(s) on this node, which has " + as_text(node_bytes / 1e9) +
                                " GB");
  }

  template class PDZone<2>;
  template class PDZone<3>;
} // namespace PeriArlequin
