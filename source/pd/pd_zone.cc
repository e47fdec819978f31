#include <periarlequin/pd/pd_zone.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/vector.h>

#include <boost/serialization/array.hpp>
#include <boost/serialization/vector.hpp>

#include <array>
#include <iterator>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>

namespace PeriArlequin
{

  namespace
  {
    template <int dim>
    Point<dim>
    to_point(const std::vector<double> &coordinates)
    {
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = coordinates[d];
      return p;
    }
  } // namespace

  template <int dim>
  PDZone<dim>::PDZone(parallel::distributed::Triangulation<dim> &triangulation,
                      const Parameters::Peridynamics<dim>       &parameters,
                      const Parameters::Material                &material,
                      const Parameters::Geometry                &geometry,
                      std::unique_ptr<PDMaterialModel<dim>>      model,
                      std::unique_ptr<FractureCriterion<dim>>    fracture,
                      const SiteFilter                          &extent)
    : triangulation(triangulation)
    , parameters(parameters)
    , material(material)
    , communicator(triangulation.get_communicator())
    , mapping(1)
    , general_cells(!geometry.mesh_file.empty())
    , ghosts(particle_handler, communicator)
    , model(std::move(model))
    , fracture(std::move(fracture))
    , prescribed(parameters)
    , extent(extent ? extent : SiteFilter([this](const Point<dim> &x) {
        return region.contains(x);
      }))
    , region(parameters.region)
    , blending_weight([](const Point<dim> &) { return 0.; })
    , lattice(to_point<dim>(geometry.lower_corner),
              to_point<dim>(geometry.upper_corner),
              parameters.lattice_spacing)
  {
    const double dx = parameters.lattice_spacing;
    for (unsigned int d = 0; d < dim; ++d)
      {
        domain.lower[d] = geometry.lower_corner[d];
        domain.upper[d] = geometry.upper_corner[d];
      }
    for (const auto &box : parameters.region.boxes)
      if (!domain.contains(box.lower, 1e-12 * dx) || !domain.contains(box.upper, 1e-12 * dx))
        {
          std::ostringstream box_text;
          box_text << box.lower << " : " << box.upper;
          throw_invalid_parameter("Peridynamics/Region",
                                  box_text.str(),
                                  general_cells ?
                                    "boxes inside the bounding box of 'Geometry/Mesh file'" :
                                    "boxes inside the domain 'Geometry/Lower corner' to "
                                    "'Geometry/Upper corner'");
        }
    bonds.build_stencil(dx, parameters.horizon());
  }

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
      return text.str();
    }

    /**
     * The unit coordinates of @p x in @p cell if the cell holds it (closed, within
     * @p tolerance in unit coordinates), else nothing.
     */
    template <int dim>
    std::optional<Point<dim>>
    unit_point_in(const Mapping<dim>                                       &mapping,
                  const typename Triangulation<dim>::active_cell_iterator &cell,
                  const Point<dim>                                         &x,
                  const double                                              tolerance)
    {
      if (!cell->bounding_box().point_inside(x, tolerance * cell->diameter()))
        return {};
      try
        {
          const Point<dim> unit = mapping.transform_real_to_unit_cell(cell, x);
          if (GeometryInfo<dim>::is_inside_unit_cell(unit, tolerance))
            return unit;
        }
      catch (const typename Mapping<dim>::ExcTransformationFailed &)
        {}
      return {};
    }

    /**
     * Which cells of the whole local mesh (artificial ones too: without manifolds they cover
     * the domain exactly) hold a point: a hash grid of their bounding boxes.
     */
    template <int dim>
    class CellLocator
    {
    public:
      CellLocator(const Triangulation<dim> &triangulation, const Mapping<dim> &mapping)
        : mapping(mapping)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          bin_size = std::max(bin_size, cell->diameter());
        for (const auto &cell : triangulation.active_cell_iterators())
          {
            const auto [lower, upper] = cell->bounding_box().get_boundary_points();
            const auto first = bin(lower), last = bin(upper);
            std::array<long, dim> b;
            const auto visit = [&](const auto &self, const unsigned int d) -> void {
              if (d == dim)
                {
                  bins[b].push_back(cell);
                  return;
                }
              for (b[d] = first[d]; b[d] <= last[d]; ++b[d])
                self(self, d + 1);
            };
            visit(visit, 0);
          }
      }

      bool
      holds(const Point<dim> &x) const
      {
        const auto found = bins.find(bin(x));
        if (found == bins.end())
          return false;
        for (const auto &cell : found->second)
          if (unit_point_in<dim>(mapping, cell, x, 1e-10))
            return true;
        return false;
      }

    private:
      std::array<long, dim>
      bin(const Point<dim> &x) const
      {
        std::array<long, dim> b;
        for (unsigned int d = 0; d < dim; ++d)
          b[d] = static_cast<long>(std::floor(x[d] / bin_size));
        return b;
      }

      struct BinHash
      {
        std::size_t
        operator()(const std::array<long, dim> &b) const
        {
          std::size_t h = 0;
          for (const long c : b)
            h = h * 1000003u + static_cast<std::size_t>(c);
          return h;
        }
      };

      const Mapping<dim> &mapping;
      double              bin_size = 0;
      std::unordered_map<std::array<long, dim>,
                         std::vector<typename Triangulation<dim>::active_cell_iterator>,
                         BinHash>
        bins;
    };
  } // namespace

  template <int dim>
  std::pair<Point<dim>, Point<dim>>
  PDZone<dim>::cell_bounds(const typename Triangulation<dim>::cell_iterator &cell) const
  {
    if (!general_cells)
      return {cell->vertex(0), cell->vertex(GeometryInfo<dim>::vertices_per_cell - 1)};
    // The bounding box, closed on top: owns_site() decides between the cells that share it.
    const BoundingBox<dim> box   = cell->bounding_box();
    Point<dim>             upper = box.get_boundary_points().second;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] += 1e-10 * parameters.lattice_spacing;
    return {box.get_boundary_points().first, upper};
  }

  template <int dim>
  bool
  PDZone<dim>::owns_site(const typename Triangulation<dim>::active_cell_iterator &cell,
                         const Point<dim>                                         &x) const
  {
    if (!general_cells)
      return true;
    constexpr double                tolerance = 1e-10;
    const std::optional<Point<dim>> unit      = unit_point_in<dim>(mapping, cell, x, tolerance);
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
            unit_point_in<dim>(mapping, other, x, tolerance))
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
          normal = cross_product_3d(face->vertex(3) - face->vertex(0),
                                    face->vertex(2) - face->vertex(1));
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
    return 1000 + n * bonds.stencil.size();
  }

  template <int dim>
  bool
  PDZone<dim>::contains_cell(const typename Triangulation<dim>::active_cell_iterator &cell) const
  {
    return region.contains(cell->center());
  }

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
  void
  PDZone<dim>::setup(const ProblemData<dim> &data, const double dt)
  {
    initialize_particle_handler(data, dt);
    if (general_cells)
      check_region_follows_cells();
    insert_particles([this](const Point<dim> &x, types::particle_index) { return extent(x); });
    AssertThrow(particle_handler.n_global_particles() > 0,
                ExcMessage("Invalid input: parameter 'Peridynamics/Region' holds no lattice "
                           "site of spacing 'Peridynamics/Lattice spacing'; allowed: boxes "
                           "that contain at least one lattice cell centre."));
    build_particle_structures();
    if (fracture)
      fracture->initialize(parameters, *model, bonds);
    set_initial_state();
  }

  template <int dim>
  void
  PDZone<dim>::initialize_particle_handler(const ProblemData<dim> &data, const double dt)
  {
    problem_data = &data;
    time_step    = dt;
    particle_handler.initialize(triangulation, mapping, n_particle_properties());
  }

  template <int dim>
  unsigned int
  PDZone<dim>::n_particle_properties() const
  {
    return 2 * dim + 1 + model->n_particle_scalars();
  }

  template <int dim>
  std::string
  PDZone<dim>::name() const
  {
    return "PD";
  }

  template <int dim>
  void
  PDZone<dim>::insert_particles(
    const std::function<bool(const Point<dim> &, types::particle_index)> &accept)
  {
    if (general_cells)
      vertex_to_cells = GridTools::vertex_to_cell_map(triangulation);
    const auto for_each_site = [&](const auto &cell, const auto &visit) {
      const auto [lower, upper] = cell_bounds(cell);
      lattice.for_each_site_in(lower, upper, [&](const auto &site) {
        const Point<dim> x = lattice.position(site);
        if (accept(x, lattice.id(site)) && owns_site(cell, x))
          visit(site, x);
      });
    };
    // The storage of the particles held now, of those to insert and of the ghosts to come
    // (the accepted sites of the ghost cells), reserved at once: grown one particle at a
    // time, it can reach twice that.
    std::size_t n_accepted = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() || cell->is_ghost())
        for_each_site(cell, [&](const auto &, const Point<dim> &) { ++n_accepted; });
    particle_handler.reserve(
      particle_handler.n_locally_owned_particles() +
      std::distance(particle_handler.begin_ghost(), particle_handler.end_ghost()) + n_accepted);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for_each_site(cell, [&](const auto &site, const Point<dim> &x) {
          particle_handler.insert_particle(
            x, mapping.transform_real_to_unit_cell(cell, x), lattice.id(site), cell);
        });
    particle_handler.update_cached_numbers();
    vertex_to_cells.clear();
  }

  namespace
  {
    /** The kernel that Peridynamics/Force kernel asks for, and that @p model offers. */
    template <int dim>
    typename BondFamilies<dim>::Kernel
    force_kernel(const std::string &choice, const PDMaterialModel<dim> &model)
    {
      using Kernel = typename BondFamilies<dim>::Kernel;
      if (choice == "bond list" || (choice == "automatic" && !model.supports_stencil()))
        return Kernel::bond_list;
      if (!model.supports_stencil())
        throw_invalid_parameter("Peridynamics/Force kernel",
                                choice,
                                "'bond list' or 'automatic' with this material model (it has "
                                "no stencil kernel)");
      return choice == "stencil" ? Kernel::stencil : Kernel::automatic;
    }
  } // namespace

  template <int dim>
  void
  PDZone<dim>::build_particle_structures()
  {
    ghosts.reinit();
    check_horizon_covered();
    compute_blending_weights();
    // Bonds in the overlap and the slave layer never break: the coupling assumes a continuum
    // there.
    // On a general mesh a site of the extent may lie outside the mesh (a hole, a notch): no
    // particle, no bond, and no error.
    std::unique_ptr<CellLocator<dim>> locator;
    if (general_cells)
      locator = std::make_unique<CellLocator<dim>>(triangulation, mapping);
    const SiteFilter extent_in_mesh = [&](const Point<dim> &x) {
      return extent(x) && (!locator || locator->holds(x));
    };
    bonds.build(lattice, ghosts, extent_in_mesh, parameters.pre_cracks, [this](const Point<dim> &x) {
      return parameters.no_fail_region.contains(x) || blending_weight(x) > 0;
    }, force_kernel(parameters.force_kernel, *model));
    find_bonds_near_overlap();
    model->initialize(material, bonds);

    const unsigned int n_owned = ghosts.n_owned(), n_total = ghosts.n_total();
    state.reinit(n_owned, n_total);
    force_density.assign(n_owned, Tensor<1, dim>());
    energy_density.assign(n_owned, 0.);
    model_scalars.assign(n_total * model->n_particle_scalars(), 0.);
    applied_force.assign(n_owned, Tensor<1, dim>());
    prescribed.reinit(ghosts.reference_positions(), n_owned);
    find_boundary_layers();
    tracks_work = problem_data->has_body_force || problem_data->has_tractions() ||
                  !prescribed.empty(communicator);
  }

  template <int dim>
  void
  PDZone<dim>::find_bonds_near_overlap()
  {
    // The particles near the overlap: pure PD (alpha = 0) with a bond to the overlap or the
    // slave layer (alpha > 0), owned and ghosts.
    const unsigned int  n_owned = ghosts.n_owned();
    const auto          x       = ghosts.reference_positions();
    std::vector<double> near(ghosts.n_total(), 0.);
    bool                cut = false, any_weighted = false;
    Point<dim>          cut_at;
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
        {
          const unsigned int j = bonds.neighbor(i, n);
          any_weighted         = any_weighted || alpha[i] > 0;
          if (alpha[i] == 0 && alpha[j] > 0)
            near[i] = 1;
          if (j < n_owned && alpha[j] == 0 && alpha[i] > 0)
            near[j] = 1;
          if ((alpha[i] > 0 || alpha[j] > 0) && bonds.state[n] == BondFamilies<dim>::broken &&
              !cut)
            {
              cut    = true;
              cut_at = alpha[i] > 0 ? x[i] : x[j];
            }
        }
    if (Utilities::MPI::logical_or(cut, communicator))
      {
        std::ostringstream where;
        where << "a crack that cuts bonds of the overlap or the slave layer";
        if (cut)
          where << " (at " << cut_at << " m)";
        throw_invalid_parameter("Peridynamics/Pre-cracks",
                                where.str(),
                                "cracks in the pure PD region, more than a bond away from the "
                                "overlap: the coupling assumes an intact continuum there; "
                                "enlarge Peridynamics/Region or move the overlap");
      }
    checks_overlap = fracture && Utilities::MPI::logical_or(any_weighted, communicator);
    ghosts.update_ghosts(make_array_view(near), 1);
    // Their bonds among themselves and into the pure PD zone, intact now (those into the
    // overlap are unbreakable).
    bonds_near_overlap.clear();
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
        {
          const unsigned int j = bonds.neighbor(i, n);
          if (bonds.state[n] == BondFamilies<dim>::intact && (near[i] > 0 || near[j] > 0))
            bonds_near_overlap.emplace_back(near[i] > 0 ? i : j, n);
        }
  }

  template <int dim>
  void
  PDZone<dim>::check_damage_near_overlap(const double time) const
  {
    const auto            ids   = ghosts.ids();
    types::particle_index first = std::numeric_limits<types::particle_index>::max();
    unsigned int          local = 0;
    for (const auto &[i, n] : bonds_near_overlap)
      if (bonds.state[n] == BondFamilies<dim>::broken && ids[i] < first)
        {
          first = ids[i];
          local = i;
        }
    const types::particle_index global_first = Utilities::MPI::min(first, communicator);
    if (global_first == std::numeric_limits<types::particle_index>::max())
      return;
    Point<dim> position;
    for (unsigned int d = 0; d < dim; ++d)
      position[d] = Utilities::MPI::max(first == global_first ?
                                          ghosts.reference_positions()[local][d] :
                                          -std::numeric_limits<double>::max(),
                                        communicator);
    std::ostringstream message;
    message << "Damage reached the overlap at t = " << time << " s: a bond of the particle at ("
            << position << ") m, one bond away from the overlap, broke. The coupling assumes "
            << "an intact continuum in the overlap and the FE zone, so the run stops here. "
            << "Enlarge the PD region around the crack path (Peridynamics/Region, "
            << "Coupling/Overlap region and Coupling/Finite element region), or let it grow "
            << "with the crack (Adaptive PD zone; if it does already, a larger damage "
            << "distance or a smaller check interval).";
    AssertThrow(false, ExcMessage(message.str()));
  }

  template <int dim>
  void
  PDZone<dim>::find_boundary_layers()
  {
    // The first layer of lattice sites along a face lies within dx of it, whatever the
    // alignment of the lattice with the face: it carries a traction. A displacement is
    // prescribed on every particle within two bond reaches (delta + dx/2) of the face (slaves
    // follow the FE nodes instead): the free particles and all their neighbours then have
    // complete families, so the dilatations that enter a free particle's force are those of
    // the bulk and no free particle feels the surface; the layer is the fictitious boundary
    // layer, inside the domain.
    const double dx    = parameters.lattice_spacing;
    const double depth = 2. * (parameters.horizon() + 0.5 * dx);
    const auto   x     = ghosts.reference_positions();
    traction_faces.assign(ghosts.n_owned(), 0);
    if (general_cells)
      {
        check_clear_of_loaded_boundaries(depth);
        return;
      }
    for (unsigned int b = 0; b < ProblemData<dim>::n_boundaries; ++b)
      {
        const auto        &condition = problem_data->boundary_conditions[b];
        const unsigned int direction = b / 2;
        std::array<bool, dim> components;
        for (unsigned int d = 0; d < dim; ++d)
          components[d] = condition.type == BoundaryType::displacement && condition.components[d];
        for (unsigned int i = 0; i < ghosts.n_owned(); ++i)
          {
            const double distance = (b % 2 == 0) ? x[i][direction] - domain.lower[direction] :
                                                   domain.upper[direction] - x[i][direction];
            if (condition.type == BoundaryType::traction && distance < dx * (1. - 1e-12))
              traction_faces[i] |= (1u << b);
            else if (condition.type == BoundaryType::displacement && !slave[i] &&
                     distance < depth * (1. - 1e-12))
              prescribed.add(i, x[i], *condition.function, components);
          }
      }
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
    const auto   x     = ghosts.reference_positions();
    bool         close = false;
    Point<dim>   where;
    unsigned int id = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (!close && face->at_boundary() &&
            face->boundary_id() < ProblemData<dim>::n_boundaries &&
            problem_data->boundary_conditions[face->boundary_id()].type != BoundaryType::free)
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
  PDZone<dim>::set_initial_state()
  {
    const InitialCondition<dim> &initial = *problem_data->initial_condition;
    const auto                   x = ghosts.reference_positions();
    const auto                   u = state.displacements(), v = state.velocities();
    for (unsigned int i = 0; i < ghosts.n_owned(); ++i)
      {
        u[i] = initial.displacement(x[i]);
        v[i] = initial.velocity(x[i]);
      }
    work = 0;
  }

  template <int dim>
  std::vector<unsigned int>
  PDZone<dim>::extend(const SiteFilter &grown_extent)
  {
    // What the rebuild must keep, by particle id: kinematics, applied forces (the next step's
    // work increment starts from them) and the bonds broken so far.
    const unsigned int                  n_old = ghosts.n_owned();
    const auto                          old_ids = ghosts.ids();
    std::unordered_map<types::particle_index, unsigned int> old_index;
    for (unsigned int i = 0; i < n_old; ++i)
      old_index[old_ids[i]] = i;
    const ParticleState<dim>            old_state = state;
    const std::vector<Tensor<1, dim>>   old_applied_force = applied_force;
    const auto broken = bonds.broken_bonds(old_ids);

    for ([[maybe_unused]] const Point<dim> &x : ghosts.reference_positions())
      Assert(grown_extent(x), ExcMessage("PDZone::extend(): the extent must only grow."));
    extent = grown_extent;
    insert_particles([&](const Point<dim> &x, const types::particle_index id) {
      return old_index.count(id) == 0 && extent(x);
    });
    build_particle_structures();

    const auto ids = ghosts.ids();
    bonds.break_bonds(broken, ids);

    std::vector<unsigned int> added;
    for (unsigned int i = 0; i < ghosts.n_owned(); ++i)
      {
        const auto found = old_index.find(ids[i]);
        if (found == old_index.end())
          {
            added.push_back(i);
            continue;
          }
        const unsigned int j          = found->second;
        state.displacements()[i] = old_state.displacements()[j];
        state.velocities()[i]    = old_state.velocities()[j];
        state.accelerations()[i] = old_state.accelerations()[j];
        applied_force[i]         = old_applied_force[j];
      }
    update_ghost_displacements();
    return added;
  }

  namespace
  {
    /**
     * What a particle takes along to its new owner in a repartition or a checkpoint: its
     * kinematics, applied force, strain energy density (so the energies of the step that
     * repartitioned are those of its force pass) and broken bonds.
     */
    template <int dim>
    struct TransferredParticle
    {
      types::particle_index              id;
      std::array<Tensor<1, dim>, 4>      kinematics;
      double                             energy_density;
      std::vector<types::particle_index> broken_partners;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &id &kinematics &energy_density &broken_partners;
      }
    };
  } // namespace

  template <int dim>
  std::vector<char>
  PDZone<dim>::pack_particle_state(const typename Triangulation<dim>::cell_iterator &cell) const
  {
    std::vector<TransferredParticle<dim>> records;
    const auto                            ids = ghosts.ids();
    for (const auto &particle : particle_handler.particles_in_cell(
           typename Triangulation<dim>::active_cell_iterator(cell)))
      {
        const unsigned int       i = ghosts.local_index(particle.get_id());
        TransferredParticle<dim> record{particle.get_id(),
                                        {{state.displacements()[i],
                                          state.velocities()[i],
                                          state.accelerations()[i],
                                          applied_force[i]}},
                                        energy_density[i],
                                        {}};
        for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
          if (bonds.state[n] == BondFamilies<dim>::broken)
            record.broken_partners.push_back(ids[bonds.neighbor(i, n)]);
        records.push_back(std::move(record));
      }
    return Utilities::pack(records, false);
  }

  template <int dim>
  void
  PDZone<dim>::attach_particle_state()
  {
    state_handle = triangulation.register_data_attach(
      [this](const typename Triangulation<dim>::cell_iterator &cell,
             const typename Triangulation<dim>::CellStatus) {
        return pack_particle_state(cell);
      },
      /*returns_variable_size_data=*/true);
  }

  template <int dim>
  void
  PDZone<dim>::prepare_for_repartition()
  {
    particle_handler.prepare_for_coarsening_and_refinement();
    attach_particle_state();
  }

  template <int dim>
  void
  PDZone<dim>::prepare_for_serialization()
  {
    particle_handler.prepare_for_serialization();
    attach_particle_state();
  }

  template <int dim>
  void
  PDZone<dim>::unpack_after_repartition()
  {
    Assert(state_handle != numbers::invalid_unsigned_int,
           ExcMessage("Call prepare_for_repartition() first."));
    particle_handler.unpack_after_coarsening_and_refinement();
    receive_particle_state();
  }

  template <int dim>
  void
  PDZone<dim>::setup_from_checkpoint(const ProblemData<dim> &data, const double dt)
  {
    initialize_particle_handler(data, dt);
    particle_handler.deserialize();
    // The handles of a loaded triangulation are those of the save, in the order registered.
    attach_particle_state();
    receive_particle_state();
    if (fracture)
      fracture->initialize(parameters, *model, bonds);
  }

  template <int dim>
  void
  PDZone<dim>::receive_particle_state()
  {
    std::unordered_map<types::particle_index, TransferredParticle<dim>> received;
    triangulation.notify_ready_to_unpack(
      state_handle,
      [&received](const typename Triangulation<dim>::cell_iterator &,
                  const typename Triangulation<dim>::CellStatus,
                  const boost::iterator_range<std::vector<char>::const_iterator> &data) {
        for (auto &record :
             Utilities::unpack<std::vector<TransferredParticle<dim>>>(data.begin(),
                                                                      data.end(),
                                                                      false))
          received.emplace(record.id, std::move(record));
      });
    state_handle = numbers::invalid_unsigned_int;

    build_particle_structures();
    const auto                                   ids = ghosts.ids();
    std::set<typename BondFamilies<dim>::IdPair> broken;
    for (unsigned int i = 0; i < ghosts.n_owned(); ++i)
      {
        const auto found = received.find(ids[i]);
        AssertThrow(found != received.end(),
                    ExcMessage("A particle arrived without its state in a repartition or "
                               "from a checkpoint."));
        const auto &[u, v, a, f] = found->second.kinematics;
        state.displacements()[i] = u;
        state.velocities()[i]    = v;
        state.accelerations()[i] = a;
        applied_force[i]         = f;
        energy_density[i]        = found->second.energy_density;
        for (const types::particle_index partner : found->second.broken_partners)
          broken.emplace(std::minmax(ids[i], partner));
      }
    bonds.break_bonds(broken, ids);
    update_ghost_displacements();
  }

  template <int dim>
  double
  PDZone<dim>::local_external_work() const
  {
    return work;
  }

  template <int dim>
  void
  PDZone<dim>::set_local_external_work(const double work_so_far)
  {
    work = work_so_far;
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
  PDZone<dim>::update_ghosts(ArrayView<double> values, const unsigned int n_per_particle)
  {
    ghosts.update_ghosts(values, n_per_particle);
  }

  template <int dim>
  void
  PDZone<dim>::update_ghost_displacements()
  {
    ghosts.update_ghosts(state.displacements());
  }

  template <int dim>
  void
  PDZone<dim>::compute_blending_weights()
  {
    // alpha is a function of the reference position: ghosts need no communication.
    const unsigned int n_total = ghosts.n_total(), n_owned = ghosts.n_owned();
    const auto         x       = ghosts.reference_positions();
    alpha.resize(n_total);
    state_weight.resize(n_total);
    for (unsigned int i = 0; i < n_total; ++i)
      {
        alpha[i]        = blending_weight(x[i]);
        state_weight[i] = energy_blending ? 1. - alpha[i] : 1.;
      }
    force_weight.resize(n_owned);
    mass_weight.resize(n_owned);
    slave.resize(n_owned);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        slave[i]        = 1. - alpha[i] < minimum_weight;
        force_weight[i] = energy_blending ? 1. : 1. - alpha[i];
        mass_weight[i]  = 1. - alpha[i];
      }
  }

  template <int dim>
  unsigned int
  PDZone<dim>::n_owned_particles() const
  {
    return ghosts.n_owned();
  }

  template <int dim>
  ArrayView<const Point<dim>>
  PDZone<dim>::reference_positions() const
  {
    return ghosts.reference_positions();
  }

  template <int dim>
  ArrayView<const types::particle_index>
  PDZone<dim>::particle_ids() const
  {
    return ghosts.ids();
  }

  template <int dim>
  ParticleState<dim> &
  PDZone<dim>::get_state()
  {
    return state;
  }

  template <int dim>
  const ParticleState<dim> &
  PDZone<dim>::get_state() const
  {
    return state;
  }

  template <int dim>
  ArrayView<const Tensor<1, dim>>
  PDZone<dim>::force_densities() const
  {
    return make_array_view(force_density);
  }

  template <int dim>
  ArrayView<const double>
  PDZone<dim>::particle_scalars() const
  {
    return make_array_view(model_scalars);
  }

  template <int dim>
  const PDMaterialModel<dim> &
  PDZone<dim>::get_material_model() const
  {
    return *model;
  }

  template <int dim>
  ArrayView<const double>
  PDZone<dim>::energy_densities() const
  {
    return make_array_view(energy_density);
  }

  template <int dim>
  ArrayView<const double>
  PDZone<dim>::blending_weights() const
  {
    return make_array_view(alpha);
  }

  template <int dim>
  bool
  PDZone<dim>::is_prescribed(const unsigned int i) const
  {
    return prescribed.contains(i);
  }

  template <int dim>
  bool
  PDZone<dim>::is_slave(const unsigned int i) const
  {
    return slave[i];
  }

  template <int dim>
  const BondFamilies<dim> &
  PDZone<dim>::get_bonds() const
  {
    return bonds;
  }

  template <int dim>
  types::particle_index
  PDZone<dim>::n_global_particles() const
  {
    return particle_handler.n_global_particles();
  }

  template <int dim>
  std::size_t
  PDZone<dim>::n_global_bonds() const
  {
    return Utilities::MPI::sum(bonds.n_bond_ends(), communicator);
  }

  template <int dim>
  std::size_t
  PDZone<dim>::n_global_broken_bonds() const
  {
    return Utilities::MPI::sum(bonds.n_broken_bond_ends(), communicator);
  }

  template <int dim>
  double
  PDZone<dim>::get_critical_stretch() const
  {
    return fracture ? fracture->critical_stretch() : 0.;
  }

  template <int dim>
  MPI_Comm
  PDZone<dim>::get_communicator() const
  {
    return communicator;
  }

  template <int dim>
  const Parameters::Peridynamics<dim> &
  PDZone<dim>::get_parameters() const
  {
    return parameters;
  }

  template <int dim>
  const Box<dim> &
  PDZone<dim>::get_domain() const
  {
    return domain;
  }

  template <int dim>
  double
  PDZone<dim>::particle_volume() const
  {
    return std::pow(parameters.lattice_spacing, dim);
  }

  template <int dim>
  double
  PDZone<dim>::particle_mass(const unsigned int i) const
  {
    return material.density * particle_volume() * mass_weight[i];
  }

  template <int dim>
  Tensor<1, dim>
  PDZone<dim>::blended_force(const unsigned int i) const
  {
    return (force_weight[i] * particle_volume()) * force_density[i];
  }

  template <int dim>
  void
  PDZone<dim>::set_blending(const WeightFunction &alpha_function,
                            const bool            energy,
                            const double          minimum_pd_weight)
  {
    blending_weight     = alpha_function;
    energy_blending     = energy;
    minimum_weight      = minimum_pd_weight;
  }

  template <int dim>
  std::vector<std::pair<typename Triangulation<dim>::active_cell_iterator, Point<dim>>>
  PDZone<dim>::owned_particle_locations() const
  {
    std::vector<std::pair<typename Triangulation<dim>::active_cell_iterator, Point<dim>>>
      locations;
    locations.reserve(ghosts.n_owned());
    for (const auto &particle : particle_handler)
      locations.emplace_back(particle.get_surrounding_cell(), particle.get_reference_location());
    return locations;
  }

  template <int dim>
  std::vector<std::pair<unsigned int, double>>
  PDZone<dim>::lattice_interpolation(const Point<dim> &x) const
  {
    // The lattice weights, renormalised over the sites that hold a particle here.
    std::vector<std::pair<unsigned int, double>> weights;
    double                                       total = 0;
    for (const auto &[id, w] : lattice.interpolation_weights(x))
      {
        const unsigned int j = ghosts.local_index(id);
        if (j == numbers::invalid_unsigned_int)
          continue;
        weights.emplace_back(j, w);
        total += w;
      }
    AssertThrow(total > 0,
                ExcMessage("No PD particle next to a point that must follow the PD field."));
    for (auto &entry : weights)
      entry.second /= total;
    return weights;
  }

  template <int dim>
  std::vector<std::string>
  PDZone<dim>::store_output_properties()
  {
    const unsigned int        n_scalars = model->n_particle_scalars();
    const std::vector<double> damage    = bonds.damage();
    unsigned int              i         = 0;
    for (auto &particle : particle_handler)
      {
        const ArrayView<double> properties = particle.get_properties();
        for (unsigned int d = 0; d < dim; ++d)
          {
            properties[d]       = state.displacements()[i][d];
            properties[dim + d] = state.velocities()[i][d];
          }
        properties[2 * dim] = damage[i];
        for (unsigned int k = 0; k < n_scalars; ++k)
          properties[2 * dim + 1 + k] = model_scalars[n_scalars * i + k];
        ++i;
      }
    std::vector<std::string> names(dim, "displacement");
    names.insert(names.end(), dim, "velocity");
    names.push_back("damage");
    for (const auto &name : model->particle_scalar_names())
      names.push_back(name);
    return names;
  }

  template <int dim>
  const Particles::ParticleHandler<dim> &
  PDZone<dim>::get_particle_handler() const
  {
    return particle_handler;
  }

  template class PDZone<2>;
  template class PDZone<3>;
} // namespace PeriArlequin
