#include <periarlequin/pd/cell_locator.h>
#include <periarlequin/pd/pd_zone.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/grid/grid_tools.h>

#include <iterator>
#include <limits>
#include <optional>

namespace PeriArlequin
{
  template <int dim>
  std::pair<Point<dim>, Point<dim>>
  PDZone<dim>::cell_bounds(const typename Triangulation<dim>::cell_iterator &cell) const
  {
    if (!general_cells)
      return {cell->vertex(0), cell->vertex(GeometryInfo<dim>::vertices_per_cell - 1)};
    // The bounding box, widened on both sides beyond the reach of owns_site()'s tolerance:
    // a site on a face (a lattice row on a mesh line) must be seen by every cell that may own
    // it, whatever the round-off of its coordinates; owns_site() then picks one.
    const BoundingBox<dim> box = cell->bounding_box();
    double                 pad = 0;
    for (unsigned int d = 0; d < dim; ++d)
      pad = std::max(pad, 1e-9 * box.side_length(d));
    auto [lower, upper] = box.get_boundary_points();
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] -= pad;
        upper[d] += pad;
      }
    return {lower, upper};
  }

  template <int dim>
  bool
  PDZone<dim>::owns_site(const typename Triangulation<dim>::active_cell_iterator &cell,
                         const Point<dim>                                        &x) const
  {
    if (!general_cells)
      return true;
    constexpr double                tolerance = 1e-10;
    const std::optional<Point<dim>> unit =
      internal::unit_point_in<dim>(mapping, cell, x, tolerance);
    if (!unit)
      return false;
    bool on_boundary = false;
    for (unsigned int d = 0; d < dim; ++d)
      on_boundary = on_boundary || (*unit)[d] < tolerance || (*unit)[d] > 1. - tolerance;
    if (!on_boundary)
      return true;
    // A site on a face, an edge or a vertex belongs to the cell of the smallest CellId that
    // holds it, among the cells around this one (ghosts included: the decision is the same
    // on every rank).
    for (const unsigned int v : cell->vertex_indices())
      for (const auto &other : vertex_to_cells[cell->vertex_index(v)])
        if (other != cell && other->id() < cell->id() &&
            internal::unit_point_in<dim>(mapping, other, x, tolerance))
          return false;
    return true;
  }

  template <int dim>
  double
  PDZone<dim>::cell_width(const typename Triangulation<dim>::active_cell_iterator &cell) const
  {
    if (!general_cells)
      {
        const auto [lower, upper] = cell_bounds(cell);
        double width              = upper[0] - lower[0];
        for (unsigned int d = 1; d < dim; ++d)
          width = std::min(width, upper[d] - lower[d]);
        return width;
      }
    // Twice the least distance from the centre to the line (plane) of a face: the height of
    // a parallelogram (parallelepiped), the least width of a box.
    double half = std::numeric_limits<double>::max();
    for (const unsigned int f : cell->face_indices())
      {
        const auto     face = cell->face(f);
        Tensor<1, dim> normal;
        if constexpr (dim == 2)
          {
            const Tensor<1, dim> t = face->vertex(1) - face->vertex(0);
            normal[0]              = t[1];
            normal[1]              = -t[0];
          }
        else
          normal =
            cross_product_3d(face->vertex(3) - face->vertex(0), face->vertex(2) - face->vertex(1));
        half = std::min(half, std::abs((cell->center() - face->center()) * normal) / normal.norm());
      }
    return 2. * half;
  }

  template <int dim>
  unsigned int
  PDZone<dim>::cell_weight(const typename Triangulation<dim>::cell_iterator &cell) const
  {
    const auto [lower, upper] = cell_bounds(cell);
    unsigned int n            = 0;
    lattice.for_each_site_in(lower, upper, [&](const auto &site) {
      n += extent(lattice.position(site));
    });
    return weight_of_cell_with(n);
  }

  template <int dim>
  unsigned int
  PDZone<dim>::cell_load(const typename Triangulation<dim>::active_cell_iterator &cell) const
  {
    return weight_of_cell_with(particle_handler.n_particles_in_cell(cell));
  }

  template <int dim>
  unsigned int
  PDZone<dim>::weight_of_cell_with(const unsigned int n_particles) const
  {
    return 1000 + n_particles * bonds.stencil.size();
  }

  template <int dim>
  bool
  PDZone<dim>::contains_cell(const typename Triangulation<dim>::active_cell_iterator &cell) const
  {
    return region.contains(cell->center());
  }

  template <int dim>
  void
  PDZone<dim>::set_region(const Region<dim> &grown)
  {
    region = grown;
  }

  template <int dim>
  const Region<dim> &
  PDZone<dim>::get_region() const
  {
    return region;
  }

  template <int dim>
  bool
  PDZone<dim>::has_general_cells() const
  {
    return general_cells;
  }

  template <int dim>
  void
  PDZone<dim>::insert_particles(
    const std::function<bool(const Point<dim> &, types::particle_index)> &accept,
    const CellFilter                                                     &cells)
  {
    if (general_cells)
      vertex_to_cells = GridTools::vertex_to_cell_map(triangulation);
    const auto for_each_site = [&](const auto &cell, const auto &visit) {
      if (cells && !cells(cell))
        return;
      const auto [lower, upper] = cell_bounds(cell);
      lattice.for_each_site_in(lower, upper, [&](const auto &site) {
        const Point<dim> x = lattice.position(site);
        if (accept(x, lattice.id(site)) && owns_site(cell, x))
          visit(site, x);
      });
    };
    // The storage of the particles held now, of those to insert and of the ghosts to come
    // (the accepted sites of the ghost cells), reserved at once: grown one particle at a
    // time, it can reach twice that. A zone that grows reserves a quarter more, so that its
    // next growths do not copy the storage again.
    std::size_t n_accepted = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() || cell->is_ghost())
        for_each_site(cell, [&](const auto &, const Point<dim> &) { ++n_accepted; });
    const std::size_t n_held = particle_handler.n_locally_owned_particles();
    const std::size_t needed =
      n_held + std::distance(particle_handler.begin_ghost(), particle_handler.end_ghost()) +
      n_accepted;
    if (needed > reserved_particles)
      {
        reserved_particles = n_held > 0 ? needed + needed / 4 : needed;
        particle_handler.reserve(reserved_particles);
      }
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for_each_site(cell, [&](const auto &site, const Point<dim> &x) {
          particle_handler.insert_particle(x,
                                           mapping.transform_real_to_unit_cell(cell, x),
                                           lattice.id(site),
                                           cell);
        });
    particle_handler.update_cached_numbers();
    vertex_to_cells.clear();
  }

  template <int dim>
  std::vector<unsigned int>
  PDZone<dim>::extend(const SiteFilter &grown_extent, const CellFilter &may_hold_new_sites)
  {
    // What the rebuild must keep, by particle id: kinematics, applied forces (the next step's
    // work increment starts from them), settling forces and the bonds broken so far.
    const unsigned int                       n_old        = ghosts.n_owned();
    const auto                               old_ids_view = ghosts.ids();
    const std::vector<types::particle_index> old_ids(old_ids_view.begin(),
                                                     old_ids_view.begin() + n_old);
    const ParticleState<dim>                 old_state          = state;
    const std::vector<Tensor<1, dim>>        old_applied_force  = applied_force;
    const std::vector<Tensor<1, dim>>        old_settling_force = settling_force;
    const std::vector<double>                old_settling_start = settling_start;
    const std::vector<Tensor<1, dim>>        old_force_density  = force_density;
    const std::vector<double>                old_energy_density = energy_density;
    const std::vector<double>                old_scalars        = model_scalars;
    const auto                               broken             = bonds.broken_bonds(old_ids_view);
    const HeldBefore                         held_before{{old_ids_view.begin(), old_ids_view.end()},
                                 unbreakable_particles(),
                                 alpha};

    for ([[maybe_unused]] const Point<dim> &x : ghosts.reference_positions())
      Assert(grown_extent(x), ExcMessage("PDZone::extend(): the extent must only grow."));
    extent = grown_extent;
    // A site of an owned cell holds an owned particle already if the old numbering knows it.
    insert_particles(
      [&](const Point<dim> &x, const types::particle_index id) {
        return ghosts.local_index(id) == numbers::invalid_unsigned_int && extent(x);
      },
      may_hold_new_sites);
    build_particle_structures(broken, &held_before);

    std::vector<unsigned int> previous(ghosts.n_owned(), numbers::invalid_unsigned_int);
    const unsigned int        n_scalars = model->n_particle_scalars();
    if (!settling_force.empty())
      {
        settling_force.assign(ghosts.n_owned(), Tensor<1, dim>());
        settling_start.assign(ghosts.n_owned(), -std::numeric_limits<double>::infinity());
      }
    for (unsigned int j = 0; j < n_old; ++j)
      {
        const unsigned int i     = ghosts.local_index(old_ids[j]);
        previous[i]              = j;
        state.displacements()[i] = old_state.displacements()[j];
        state.velocities()[i]    = old_state.velocities()[j];
        state.accelerations()[i] = old_state.accelerations()[j];
        applied_force[i]         = old_applied_force[j];
        // The model's outputs, for the growth's window (open_growth_window()).
        force_density[i]  = old_force_density[j];
        energy_density[i] = old_energy_density[j];
        std::copy_n(old_scalars.begin() + n_scalars * j,
                    n_scalars,
                    model_scalars.begin() + n_scalars * i);
        if (!settling_force.empty())
          {
            settling_force[i] = old_settling_force[j];
            settling_start[i] = old_settling_start[j];
          }
      }
    update_ghost_displacements();
    growth_window_pending = true;
    return previous;
  }

  template class PDZone<2>;
  template class PDZone<3>;
} // namespace PeriArlequin
