#include <periarlequin/pd/pd_zone.h>

#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <cmath>
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
    , model(std::move(model))
    , fracture(std::move(fracture))
    , extent(extent ? extent : SiteFilter([this](const Point<dim> &x) {
        return this->parameters.region.contains(x);
      }))
    , blending_weight([](const Point<dim> &) { return 0.; })
    , lattice(to_point<dim>(geometry.lower_corner),
              to_point<dim>(geometry.upper_corner),
              parameters.lattice_spacing)
  {
    const double dx = parameters.lattice_spacing;
    Box<dim> domain;
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
                                  "boxes inside the domain 'Geometry/Lower corner' to "
                                  "'Geometry/Upper corner'");
        }
    bonds.build_stencil(dx, parameters.horizon());
  }

  namespace
  {
    template <int dim>
    std::pair<Point<dim>, Point<dim>>
    cell_bounds(const typename Triangulation<dim>::cell_iterator &cell)
    {
      return {cell->vertex(0), cell->vertex(GeometryInfo<dim>::vertices_per_cell - 1)};
    }
  } // namespace

  template <int dim>
  unsigned int
  PDZone<dim>::cell_weight(const typename Triangulation<dim>::cell_iterator &cell) const
  {
    const auto [lower, upper] = cell_bounds<dim>(cell);
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
    return parameters.region.contains(cell->center());
  }

  template <int dim>
  void
  PDZone<dim>::setup(const ProblemData<dim> &data, const double dt)
  {
    problem_data = &data;
    time_step    = dt;
    generate_particles();
    check_horizon_covered();
    compute_blending_weights();
    build_bonds();
    model->initialize(material, bonds);
    if (fracture)
      fracture->initialize(parameters, *model);

    const unsigned int n_total = reference_position.size();
    displacement.assign(n_total, Tensor<1, dim>());
    velocity.assign(n_owned, Tensor<1, dim>());
    acceleration.assign(n_owned, Tensor<1, dim>());
    force_density.assign(n_owned, Tensor<1, dim>());
    energy_density.assign(n_owned, 0.);
    model_scalars.assign(n_total * model->n_particle_scalars(), 0.);
    applied_force.assign(n_owned, Tensor<1, dim>());

    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int r = 0; r < parameters.prescribed.size(); ++r)
        if (parameters.prescribed[r].region.contains(reference_position[i]))
          {
            prescribed_particles.push_back({i, r, Tensor<1, dim>()});
            break;
          }

    auto &u0 = data.initial_displacement;
    auto &v0 = data.initial_velocity;
    u0.set_time(0.);
    v0.set_time(0.);
    Vector<double> value(dim);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        u0.vector_value(reference_position[i], value);
        for (unsigned int d = 0; d < dim; ++d)
          displacement[i][d] = value(d);
        v0.vector_value(reference_position[i], value);
        for (unsigned int d = 0; d < dim; ++d)
          velocity[i][d] = value(d);
      }
    work        = 0;
    tracks_work = Utilities::MPI::logical_or(data.has_body_force || !prescribed_particles.empty(),
                                             communicator);
  }

  template <int dim>
  std::string
  PDZone<dim>::name() const
  {
    return "PD";
  }

  template <int dim>
  void
  PDZone<dim>::generate_particles()
  {
    const unsigned int n_properties = 2 * dim + 1 + model->n_particle_scalars();
    particle_handler.initialize(triangulation, mapping, n_properties);
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        const auto [lower, upper] = cell_bounds<dim>(cell);
        lattice.for_each_site_in(lower, upper, [&](const auto &site) {
          const Point<dim> x = lattice.position(site);
          if (extent(x))
            particle_handler.insert_particle(
              x, mapping.transform_real_to_unit_cell(cell, x), lattice.id(site), cell);
        });
      }
    particle_handler.update_cached_numbers();
    AssertThrow(particle_handler.n_global_particles() > 0,
                ExcMessage("Invalid input: parameter 'Peridynamics/Region' holds no lattice "
                           "site of spacing 'Peridynamics/Lattice spacing'; allowed: boxes "
                           "that contain at least one lattice cell centre."));
    particle_handler.exchange_ghost_particles(true);

    reference_position.clear();
    particle_id.clear();
    for (const auto &particle : particle_handler)
      {
        reference_position.push_back(particle.get_location());
        particle_id.push_back(particle.get_id());
      }
    n_owned = reference_position.size();
    for (auto ghost = particle_handler.begin_ghost(); ghost != particle_handler.end_ghost();
         ++ghost)
      {
        reference_position.push_back(ghost->get_location());
        particle_id.push_back(ghost->get_id());
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
        {
          const auto [lower, upper] = cell_bounds<dim>(cell);
          for (unsigned int d = 0; d < dim; ++d)
            smallest = std::min(smallest, upper[d] - lower[d]);
        }
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
  PDZone<dim>::build_bonds()
  {
    auto &local_index = local_index_of_id;
    local_index.clear();
    local_index.reserve(particle_id.size());
    for (unsigned int i = 0; i < particle_id.size(); ++i)
      local_index[particle_id[i]] = i;
    bonds.weighted_volume.assign(reference_position.size(), 0.);

    for (unsigned int i = 0; i < n_owned; ++i)
      {
        const auto site = lattice.site(particle_id[i]);
        bonds.begin_family();
        for (unsigned int k = 0; k < bonds.stencil.size(); ++k)
          {
            const auto other = lattice.neighbour(site, bonds.stencil[k].offset);
            if (!other)
              continue;
            const auto found = local_index.find(lattice.id(*other));
            if (found == local_index.end())
              {
                AssertThrow(!extent(lattice.position(*other)),
                            ExcMessage("A neighbour within the horizon is neither owned nor a "
                                       "ghost particle: the ghost layer does not cover the "
                                       "horizon."));
                continue;
              }
            const unsigned int j = found->second;
            // The full family gives the weighted volume; a bond between two owned particles
            // is stored only at the lower local index.
            bonds.weighted_volume[i] +=
              bonds.stencil[k].length * bonds.stencil[k].length * bonds.stencil[k].volume;
            if (j < n_owned && j < i)
              continue;
            // Test the crack with the ends in the order of their global ids, so that the
            // ranks holding the two ends decide alike even for a bond grazing a crack tip.
            const bool         i_first = particle_id[i] < particle_id[j];
            const Point<dim>  &first   = reference_position[i_first ? i : j];
            const Point<dim>  &second  = reference_position[i_first ? j : i];
            auto               state   = BondFamilies<dim>::intact;
            for (const auto &crack : parameters.pre_cracks)
              if (crack.cuts(first, second))
                state = BondFamilies<dim>::broken;
            if (state != BondFamilies<dim>::broken &&
                (parameters.no_fail_region.contains(reference_position[i]) ||
                 parameters.no_fail_region.contains(reference_position[j])))
              state = BondFamilies<dim>::unbreakable;
            bonds.add_bond(j, k, state);
          }
      }
    bonds.end_families(n_owned, reference_position.size());
    update_ghosts(bonds.weighted_volume, 1);
  }

  template <int dim>
  void
  PDZone<dim>::update_ghosts(std::vector<double> &values, const unsigned int n_per_particle)
  {
    unsigned int i = 0;
    for (auto &particle : particle_handler)
      {
        const ArrayView<double> properties = particle.get_properties();
        for (unsigned int k = 0; k < n_per_particle; ++k)
          properties[k] = values[n_per_particle * i + k];
        ++i;
      }
    particle_handler.update_ghost_particles();
    for (auto ghost = particle_handler.begin_ghost(); ghost != particle_handler.end_ghost();
         ++ghost, ++i)
      {
        AssertThrow(ghost->get_id() == particle_id[i],
                    ExcMessage("Ghost particles changed order: rebuild the index maps."));
        const ArrayView<const double> properties = ghost->get_properties();
        for (unsigned int k = 0; k < n_per_particle; ++k)
          values[n_per_particle * i + k] = properties[k];
      }
  }

  template <int dim>
  void
  PDZone<dim>::update_ghost_displacements()
  {
    exchange_buffer.resize(dim * reference_position.size());
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        exchange_buffer[dim * i + d] = displacement[i][d];
    update_ghosts(exchange_buffer, dim);
    for (unsigned int i = n_owned; i < reference_position.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        displacement[i][d] = exchange_buffer[dim * i + d];
  }

  template <int dim>
  void
  PDZone<dim>::compute_internal_forces()
  {
    update_ghost_displacements();
    model->compute_particle_scalars(bonds, displacement, model_scalars);
    if (model->n_particle_scalars() > 0)
      update_ghosts(model_scalars, model->n_particle_scalars());
    model->compute_forces(
      bonds, displacement, model_scalars, state_weight, force_density, energy_density);
  }

  template <int dim>
  void
  PDZone<dim>::impose_prescribed_motion(const double time)
  {
    const double dt = time_step;
    Vector<double> before(dim), now(dim), after(dim);
    for (auto &p : prescribed_particles)
      {
        const auto &condition = parameters.prescribed[p.region];
        auto       &function  = *condition.function;
        const auto &x         = reference_position[p.local_index];
        function.set_time(time - dt);
        function.vector_value(x, before);
        function.set_time(time);
        function.vector_value(x, now);
        function.set_time(time + dt);
        function.vector_value(x, after);
        for (unsigned int d = 0; d < dim; ++d)
          {
            if (!condition.components[d])
              continue;
            if (condition.prescribes_velocity)
              {
                p.velocity[d]                  = now(d);
                acceleration[p.local_index][d] = (after(d) - before(d)) / (2. * dt);
              }
            else
              {
                displacement[p.local_index][d] = now(d);
                p.velocity[d]                  = (after(d) - before(d)) / (2. * dt);
                acceleration[p.local_index][d] = (after(d) - 2. * now(d) + before(d)) / (dt * dt);
              }
          }
      }
    restore_prescribed_velocities();
  }

  template <int dim>
  void
  PDZone<dim>::restore_prescribed_velocities()
  {
    for (const auto &p : prescribed_particles)
      for (unsigned int d = 0; d < dim; ++d)
        if (parameters.prescribed[p.region].components[d])
          velocity[p.local_index][d] = p.velocity[d];
  }

  template <int dim>
  void
  PDZone<dim>::predict(const double dt)
  {
    if (tracks_work)
      {
        previous_displacement.assign(displacement.begin(), displacement.begin() + n_owned);
        previous_applied_force = applied_force;
      }
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        displacement[i] += dt * velocity[i] + (0.5 * dt * dt) * acceleration[i];
        velocity[i] += (0.5 * dt) * acceleration[i];
      }
  }

  template <int dim>
  void
  PDZone<dim>::compute_accelerations(const double time)
  {
    const ProblemData<dim> &data = *problem_data;
    update_ghost_displacements();
    if (fracture)
      fracture->break_bonds(bonds, displacement);
    model->compute_particle_scalars(bonds, displacement, model_scalars);
    if (model->n_particle_scalars() > 0)
      update_ghosts(model_scalars, model->n_particle_scalars());
    model->compute_forces(
      bonds, displacement, model_scalars, state_weight, force_density, energy_density);

    const double   rho = material.density, volume = particle_volume();
    Vector<double> body(dim);
    auto          &body_force = data.body_force;
    body_force.set_time(time);
    std::vector<Tensor<1, dim>> prescribed_acceleration;
    for (const auto &p : prescribed_particles)
      prescribed_acceleration.push_back(acceleration[p.local_index]);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        Tensor<1, dim> b;
        if (data.has_body_force)
          {
            body_force.vector_value(reference_position[i], body);
            for (unsigned int d = 0; d < dim; ++d)
              b[d] = body(d);
          }
        // A slave's acceleration is that of the FE field, set by the coupling.
        if (!is_slave[i])
          acceleration[i] = (force_weight[i] * force_density[i] + (1. - alpha[i]) * b) /
                            (rho * mass_weight[i]);
        applied_force[i] = (1. - alpha[i]) * volume * b;
      }
    for (unsigned int k = 0; k < prescribed_particles.size(); ++k)
      {
        const unsigned int i         = prescribed_particles[k].local_index;
        const auto        &condition = parameters.prescribed[prescribed_particles[k].region];
        for (unsigned int d = 0; d < dim; ++d)
          if (condition.components[d])
            {
              acceleration[i][d] = prescribed_acceleration[k][d];
              // Load plus support reaction: m a - f V.
              applied_force[i][d] = particle_mass(i) * acceleration[i][d] - blended_force(i)[d];
            }
      }
  }

  template <int dim>
  void
  PDZone<dim>::account_work()
  {
    if (!tracks_work)
      return;
    // Trapezoidal work of the applied forces over the step.
    double increment = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      increment += (previous_applied_force[i] + applied_force[i]) *
                   (displacement[i] - previous_displacement[i]);
    work += 0.5 * increment;
  }

  template <int dim>
  void
  PDZone<dim>::correct(const double dt)
  {
    for (unsigned int i = 0; i < n_owned; ++i)
      velocity[i] += (0.5 * dt) * acceleration[i];
    // Prescribed components keep the velocity computed for this time in
    // compute_accelerations().
    restore_prescribed_velocities();
  }

  namespace
  {
    /**
     * Pseudo-random value in [-1, 1) from a particle id and a component: a start vector for
     * power iterations with a component on every mode, the same on every partition.
     */
    double
    hashed_value(const types::particle_index id, const unsigned int component)
    {
      std::uint64_t h = (id * 3 + component + 1) * 0x9E3779B97F4A7C15ULL;
      h ^= h >> 31;
      h *= 0xBF58476D1CE4E5B9ULL;
      h ^= h >> 29;
      return static_cast<double>(h >> 11) / static_cast<double>(1ULL << 52) - 1.;
    }
  } // namespace

  template <int dim>
  double
  PDZone<dim>::estimate_stable_time_step(const unsigned int max_iterations)
  {
    const std::vector<Tensor<1, dim>> saved = displacement;
    std::vector<Tensor<1, dim>>       x(n_owned);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        x[i][d] = hashed_value(particle_id[i], d);
    const auto norm = [&](const std::vector<Tensor<1, dim>> &v) {
      double sum = 0;
      for (unsigned int i = 0; i < n_owned; ++i)
        sum += v[i] * v[i];
      return std::sqrt(Utilities::MPI::sum(sum, communicator));
    };
    // The operator is applied as -f(eps x) / (rho eps) with eps x far below the lattice
    // spacing, where the force is linear in the displacement to about 1e-8.
    double eigenvalue = 0;
    for (unsigned int it = 0; it < max_iterations; ++it)
      {
        const double scale = 1. / norm(x);
        double       max_entry = 0;
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            x[i] *= scale;
            for (unsigned int d = 0; d < dim; ++d)
              max_entry = std::max(max_entry, std::abs(x[i][d]));
          }
        const double eps = 1e-8 * parameters.lattice_spacing /
                           Utilities::MPI::max(max_entry, communicator);
        for (unsigned int i = 0; i < n_owned; ++i)
          displacement[i] = is_slave[i] ? Tensor<1, dim>() : eps * x[i];
        compute_internal_forces();
        double rayleigh = 0;
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            const Tensor<1, dim> y =
              is_slave[i] ? Tensor<1, dim>() :
                            -(force_weight[i] * force_density[i]) /
                              (material.density * mass_weight[i] * eps);
            rayleigh += x[i] * y;
            x[i] = y;
          }
        rayleigh             = Utilities::MPI::sum(rayleigh, communicator);
        const bool converged = std::abs(rayleigh - eigenvalue) <= 1e-6 * rayleigh;
        eigenvalue           = rayleigh;
        if (converged)
          break;
      }
    displacement = saved;
    compute_internal_forces();
    AssertThrow(eigenvalue > 0,
                ExcMessage("The PD stable-step estimate found no positive eigenvalue: does "
                           "the PD zone have bonds?"));
    return 2. / std::sqrt(eigenvalue);
  }

  template <int dim>
  double
  PDZone<dim>::kinetic_energy() const
  {
    double sum = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      if (!is_slave[i])
        sum += mass_weight[i] * (velocity[i] * velocity[i]);
    return 0.5 * material.density * particle_volume() * Utilities::MPI::sum(sum, communicator);
  }

  template <int dim>
  double
  PDZone<dim>::strain_energy() const
  {
    // With energy blending the model weighted the densities already.
    double sum = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      sum += (energy_blending ? 1. : 1. - alpha[i]) * energy_density[i];
    return particle_volume() * Utilities::MPI::sum(sum, communicator);
  }

  template <int dim>
  std::pair<double, double>
  PDZone<dim>::energies_in(const Region<dim> &region) const
  {
    double sums[2] = {0, 0};
    for (unsigned int i = 0; i < n_owned; ++i)
      if (region.contains(reference_position[i]))
        {
          sums[0] += velocity[i] * velocity[i];
          sums[1] += energy_density[i];
        }
    Utilities::MPI::sum(ArrayView<const double>(sums, 2), communicator, ArrayView<double>(sums, 2));
    return {0.5 * material.density * particle_volume() * sums[0], particle_volume() * sums[1]};
  }

  template <int dim>
  double
  PDZone<dim>::external_work() const
  {
    return Utilities::MPI::sum(work, communicator);
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
                            const double          minimum_weight)
  {
    blending_weight     = alpha_function;
    energy_blending     = energy;
    minimum_mass_weight = minimum_weight;
  }

  template <int dim>
  void
  PDZone<dim>::compute_blending_weights()
  {
    // alpha is a function of the reference position: ghosts need no communication.
    const unsigned int n_total = reference_position.size();
    alpha.resize(n_total);
    state_weight.resize(n_total);
    for (unsigned int i = 0; i < n_total; ++i)
      {
        alpha[i]        = blending_weight(reference_position[i]);
        state_weight[i] = energy_blending ? 1. - alpha[i] : 1.;
      }
    force_weight.resize(n_owned);
    mass_weight.resize(n_owned);
    is_slave.resize(n_owned);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        is_slave[i]     = alpha[i] >= 1.;
        force_weight[i] = energy_blending ? 1. : 1. - alpha[i];
        mass_weight[i]  = std::max(1. - alpha[i], minimum_mass_weight);
      }
  }

  template <int dim>
  std::vector<std::pair<typename Triangulation<dim>::active_cell_iterator, Point<dim>>>
  PDZone<dim>::owned_particle_locations() const
  {
    std::vector<std::pair<typename Triangulation<dim>::active_cell_iterator, Point<dim>>>
      locations;
    locations.reserve(n_owned);
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
        const auto found = local_index_of_id.find(id);
        if (found == local_index_of_id.end())
          continue;
        weights.emplace_back(found->second, w);
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
            properties[d]       = displacement[i][d];
            properties[dim + d] = velocity[i][d];
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
