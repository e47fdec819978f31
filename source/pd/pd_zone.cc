#include <periarlequin/base/parallel_loops.h>
#include <periarlequin/pd/cell_locator.h>
#include <periarlequin/pd/pd_zone.h>

#include <deal.II/base/utilities.h>

#include <array>
#include <optional>
#include <sstream>

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
    , extent(extent ? extent :
                      SiteFilter([this](const Point<dim> &x) { return region.contains(x); }))
    , region(parameters.region)
    , blending_weight([](const Point<dim> &) { return 0.; })
    , lattice(to_point<dim>(geometry.lower_corner),
              to_point<dim>(geometry.upper_corner),
              parameters.lattice_spacing)
    , volume(std::pow(parameters.lattice_spacing, dim))
  {
    const double dx = parameters.lattice_spacing;
    for (unsigned int d = 0; d < dim; ++d)
      {
        domain.lower[d] = geometry.lower_corner[d];
        domain.upper[d] = geometry.upper_corner[d];
      }
    check_lattice_fits(static_cast<bool>(extent));
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
    if (parameters.contact.enabled)
      contact = std::make_unique<ParticleContact<dim>>(parameters.contact,
                                                       dx,
                                                       material.youngs_modulus,
                                                       communicator);
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
  PDZone<dim>::build_particle_structures(const typename BondFamilies<dim>::IdPairs &broken,
                                         const HeldBefore                          *before)
  {
    ghosts.reinit();
    check_horizon_covered();
    compute_blending_weights();
    // On a general mesh a site of the extent may lie outside the mesh (a hole, a notch): no
    // particle, no bond, and no error.
    std::unique_ptr<internal::CellLocator<dim>> locator;
    if (general_cells)
      locator = std::make_unique<internal::CellLocator<dim>>(triangulation, mapping);
    const SiteFilter extent_in_mesh = [&](const Point<dim> &x) {
      return extent(x) && (!locator || locator->holds(x));
    };
    const std::vector<bool>                                      no_fail = unbreakable_particles();
    std::optional<typename BondFamilies<dim>::PreviousNumbering> previous;
    changed_by_growth.clear();
    growth_changes_known  = false;
    growth_window_pending = false;
    if (before)
      {
        const unsigned int n_owned = ghosts.n_owned();
        previous.emplace();
        previous->owned_index.assign(n_owned, numbers::invalid_unsigned_int);
        previous->touched.assign(ghosts.n_total(), true);
        changed_by_growth.assign(ghosts.n_total(), true);
        bool all_held = true;
        for (unsigned int p = 0; p < before->ids.size(); ++p)
          if (const unsigned int i = ghosts.local_index(before->ids[p]);
              i != numbers::invalid_unsigned_int)
            {
              previous->touched[i] = no_fail[i] != before->no_fail[p];
              changed_by_growth[i] = previous->touched[i] || alpha[i] != before->alpha[p];
              if (i < n_owned)
                previous->owned_index[i] = p;
            }
          else
            all_held = false;
        growth_changes_known = all_held;
        // A particle that left would change families that no new particle touches: keep none.
        if (!all_held)
          previous.reset();
      }
    bonds.build(lattice,
                ghosts,
                extent_in_mesh,
                parameters.pre_cracks,
                no_fail,
                broken,
                force_kernel(parameters.force_kernel, *model),
                previous ? &*previous : nullptr);
    restrict_force_pass();
    find_bonds_near_overlap();
    model->initialize(material, bonds);
    new_damage.clear();

    const unsigned int n_owned = ghosts.n_owned(), n_total = ghosts.n_total();
    state.reinit(n_owned, n_total);
    force_density.assign(n_owned, Tensor<1, dim>());
    energy_density.assign(n_owned, 0.);
    model_scalars.assign(n_total * model->n_particle_scalars(), 0.);
    applied_force.assign(n_owned, Tensor<1, dim>());
    prescribed.reinit(ghosts.reference_positions(), n_owned);
    find_boundary_layers();
    tracks_work = problem_data->has_body_force || problem_data->has_tractions() ||
                  !prescribed.empty(communicator) || !settling_force.empty();
    if (contact)
      {
        std::vector<types::global_cell_index> particle_cells;
        particle_cells.reserve(n_owned);
        for (const auto &particle : particle_handler)
          particle_cells.push_back(particle.get_surrounding_cell()->global_active_cell_index());
        std::unordered_set<types::global_cell_index> held_cells;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() || cell->is_ghost())
            held_cells.insert(cell->global_active_cell_index());
        contact->reinit(std::move(particle_cells), std::move(held_cells));
      }
  }

  template <int dim>
  void
  PDZone<dim>::restrict_force_pass()
  {
    // A particle of force weight 0 (a slave where alpha = 1, force blending) moves with the
    // FE field and passes no force on: its force is not computed. A bond whose ends both have
    // state weight 0 (energy blending, alpha = 1) carries no force.
    const unsigned int n_owned = ghosts.n_owned(), n_total = ghosts.n_total();
    std::vector<bool>  force_used(n_total, false), state_used(n_total);
    unforced.clear();
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        force_used[i] = force_weight[i] != 0.;
        if (!force_used[i])
          unforced.push_back(i);
      }
    for (unsigned int i = 0; i < n_total; ++i)
      state_used[i] = state_weight[i] != 0.;
    bonds.restrict_force_pass(force_used, state_used);
  }

  template <int dim>
  std::vector<bool>
  PDZone<dim>::unbreakable_particles() const
  {
    // Tested on the threads into bytes (the bits of a std::vector<bool> share their words).
    const auto                x = ghosts.reference_positions();
    std::vector<std::uint8_t> tested(ghosts.n_total());
    for_each_subrange(tested.size(), [&](const unsigned int first, const unsigned int end) {
      for (unsigned int i = first; i < end; ++i)
        tested[i] = alpha[i] > 0 || parameters.no_fail_region.contains(x[i]) ||
                    (parameters.unbreakable_traction_layer && traction_layers_at(x[i]) != 0);
    });
    return std::vector<bool>(tested.begin(), tested.end());
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
    // Only the families that can hold a bond to a weighted particle are scanned (all of them
    // on the bond lists).
    std::vector<bool> weighted(ghosts.n_total());
    for (unsigned int t = 0; t < weighted.size(); ++t)
      weighted[t] = alpha[t] > 0;
    const std::vector<std::uint8_t> next_to_weighted = bonds.owned_within_reach(weighted);
    // On the threads: each chunk lists the particles it finds near the overlap (its own and
    // the owned other ends of its bonds, marked after) and the first bond to the overlap
    // that a crack cuts.
    struct ChunkFindings
    {
      std::vector<unsigned int> near;
      bool                      any_weighted = false, cut = false;
      Point<dim>                cut_at;
    };
    std::vector<ChunkFindings> found(max_fixed_chunks);
    const unsigned int         n_chunks = for_each_fixed_chunk(
      n_owned,
      [&](const unsigned int c, const unsigned int first, const unsigned int end) {
        ChunkFindings &chunk = found[c];
        for (unsigned int i = first; i < end; ++i)
          {
            if (!next_to_weighted[i])
              continue;
            for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
              {
                const unsigned int j = bonds.neighbor(i, n);
                chunk.any_weighted   = chunk.any_weighted || alpha[i] > 0;
                if (alpha[i] == 0 && alpha[j] > 0)
                  chunk.near.push_back(i);
                if (j < n_owned && alpha[j] == 0 && alpha[i] > 0)
                  chunk.near.push_back(j);
                if ((alpha[i] > 0 || alpha[j] > 0) && bonds.state[n] == BondFamilies<dim>::broken &&
                    !chunk.cut)
                  {
                    chunk.cut    = true;
                    chunk.cut_at = alpha[i] > 0 ? x[i] : x[j];
                  }
              }
          }
      });
    for (unsigned int c = 0; c < n_chunks; ++c)
      {
        for (const unsigned int i : found[c].near)
          near[i] = 1;
        any_weighted = any_weighted || found[c].any_weighted;
        if (found[c].cut && !cut)
          {
            cut    = true;
            cut_at = found[c].cut_at;
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
    std::vector<bool> near_flag(ghosts.n_total());
    for (unsigned int t = 0; t < near_flag.size(); ++t)
      near_flag[t] = near[t] > 0;
    const std::vector<std::uint8_t> next_to_near = bonds.owned_within_reach(near_flag);
    bonds_near_overlap = join_over_chunks<std::pair<unsigned int, std::size_t>>(
      n_owned,
      [&](const unsigned int                                 first,
          const unsigned int                                 end,
          std::vector<std::pair<unsigned int, std::size_t>> &list) {
        for (unsigned int i = first; i < end; ++i)
          {
            if (!next_to_near[i])
              continue;
            for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
              {
                const unsigned int j = bonds.neighbor(i, n);
                if (bonds.state[n] == BondFamilies<dim>::intact && (near[i] > 0 || near[j] > 0))
                  list.emplace_back(near[i] > 0 ? i : j, n);
              }
          }
      });
  }

  template <int dim>
  void
  PDZone<dim>::find_boundary_layers()
  {
    // The first layer of lattice sites along a face carries a traction: the sites within dx
    // of the face of the lattice's cells (at an upper face that is the domain's face less
    // the strip no whole cell fills where dx does not divide the domain; measured from the
    // domain's face, that layer lies up to 1.5 dx away and a traction there was lost). A
    // displacement is prescribed on every particle within two bond reaches (delta + dx/2) of the
    // face (slaves follow the FE nodes instead): the free particles and all their neighbours then
    // have complete families, so the dilatations that enter a free particle's force are those of
    // the bulk and no free particle feels the surface; the layer is the fictitious boundary
    // layer, inside the domain.
    const double depth = 2. * (parameters.horizon() + 0.5 * parameters.lattice_spacing);
    const auto   x     = ghosts.reference_positions();
    traction_faces.assign(ghosts.n_owned(), 0);
    if (general_cells)
      {
        check_clear_of_loaded_boundaries(depth);
        return;
      }
    for_each_subrange(ghosts.n_owned(), [&](const unsigned int first, const unsigned int end) {
      for (unsigned int i = first; i < end; ++i)
        traction_faces[i] = traction_layers_at(x[i]);
    });
    for (unsigned int b = 0; b < ProblemData<dim>::n_boundaries; ++b)
      {
        const auto &condition = problem_data->boundary_conditions[b];
        if (condition.type != BoundaryType::displacement)
          continue;
        const unsigned int    direction = b / 2;
        std::array<bool, dim> components;
        for (unsigned int d = 0; d < dim; ++d)
          components[d] = condition.components[d];
        // On the threads: each chunk lists the particles of the layer, prescribed after in
        // their order.
        const std::vector<unsigned int> layer = join_over_chunks<unsigned int>(
          ghosts.n_owned(),
          [&](const unsigned int first, const unsigned int end, std::vector<unsigned int> &list) {
            for (unsigned int i = first; i < end; ++i)
              {
                const double distance = (b % 2 == 0) ? x[i][direction] - domain.lower[direction] :
                                                       domain.upper[direction] - x[i][direction];
                if (!slave[i] && distance < depth * (1. - 1e-12))
                  list.push_back(i);
              }
          });
        for (const unsigned int i : layer)
          prescribed.add(i, x[i], *condition.function, components, b);
      }
  }

  template <int dim>
  std::uint8_t
  PDZone<dim>::traction_layers_at(const Point<dim> &x) const
  {
    if (general_cells || !problem_data)
      return 0;
    const double     dx            = parameters.lattice_spacing;
    const Point<dim> lattice_upper = lattice.upper_corner();
    std::uint8_t     faces         = 0;
    for (unsigned int b = 0; b < ProblemData<dim>::n_boundaries; ++b)
      if (problem_data->boundary_conditions[b].type == BoundaryType::traction)
        {
          const unsigned int direction   = b / 2;
          const double from_lattice_face = (b % 2 == 0) ? x[direction] - domain.lower[direction] :
                                                          lattice_upper[direction] - x[direction];
          if (from_lattice_face < dx * (1. - 1e-12))
            faces |= (1u << b);
        }
    return faces;
  }

  template <int dim>
  void
  PDZone<dim>::set_initial_state()
  {
    const InitialCondition<dim> &initial = *problem_data->initial_condition;
    const auto                   x       = ghosts.reference_positions();
    const auto                   u = state.displacements(), v = state.velocities();
    for (unsigned int i = 0; i < ghosts.n_owned(); ++i)
      {
        u[i] = initial.displacement(x[i]);
        v[i] = initial.velocity(x[i]);
      }
    work = 0;
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
    const auto         x = ghosts.reference_positions();
    alpha.resize(n_total);
    state_weight.resize(n_total);
    // A distance search each: on the threads (after every growth of an adaptive zone).
    for_each_subrange(
      n_total,
      [&](const unsigned int first, const unsigned int end) {
        for (unsigned int i = first; i < end; ++i)
          {
            alpha[i]        = blending_weight(x[i]);
            state_weight[i] = energy_blending ? 1. - alpha[i] : 1.;
          }
      },
      256);
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
  types::particle_index
  PDZone<dim>::n_lattice_sites() const
  {
    return lattice.size();
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
  const std::vector<Point<dim>> &
  PDZone<dim>::new_damage_points() const
  {
    return new_damage;
  }

  template <int dim>
  double
  PDZone<dim>::get_critical_stretch() const
  {
    return fracture ? fracture->critical_stretch() : 0.;
  }

  template <int dim>
  const ParticleContact<dim> *
  PDZone<dim>::get_particle_contact() const
  {
    return contact.get();
  }

  template <int dim>
  unsigned int
  PDZone<dim>::n_touching_particles() const
  {
    return contact ? Utilities::MPI::sum(contact->n_touching(), communicator) : 0;
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
    blending_weight = alpha_function;
    energy_blending = energy;
    minimum_weight  = minimum_pd_weight;
  }

  template <int dim>
  std::vector<std::pair<typename Triangulation<dim>::active_cell_iterator, Point<dim>>>
  PDZone<dim>::owned_particle_locations() const
  {
    std::vector<std::pair<typename Triangulation<dim>::active_cell_iterator, Point<dim>>> locations;
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
