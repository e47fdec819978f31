#include <periarlequin/postprocess/postprocessor.h>
#include <periarlequin/simulator.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace PeriArlequin
{
  template <int dim>
  std::string
  Postprocessor<dim>::save_state() const
  {
    return {};
  }

  template <int dim>
  void
  Postprocessor<dim>::load_state(const std::string &)
  {}

  template <int dim>
  void
  Postprocessor<dim>::parse_parameters(ParameterHandler &)
  {}

  template <int dim>
  void
  EnergyPostprocessor<dim>::execute(const Simulator<dim> &simulator, EnergyHistory &history)
  {
    const FEZone<dim> *fe         = simulator.has_fe_zone() ? &simulator.get_fe_zone() : nullptr;
    const PDZone<dim> *pd         = simulator.get_pd_zone();
    const double       fe_kinetic = fe ? fe->kinetic_energy() : 0.,
                 fe_strain        = fe ? fe->strain_energy() : 0.;
    const double pd_kinetic       = pd ? pd->kinetic_energy() : 0.,
                 pd_strain        = pd ? pd->strain_energy() : 0.;
    const double work = (fe ? fe->external_work() : 0.) + (pd ? pd->external_work() : 0.);
    // A moving obstacle (a projectile) is part of the system.
    const Contact<dim> *contact = simulator.get_contact();
    const double        kinetic =
      fe_kinetic + pd_kinetic + (contact ? contact->obstacle_kinetic_energy() : 0.);
    const double strain = fe_strain + pd_strain;
    history.add_value("kinetic_energy", kinetic);
    history.add_value("strain_energy", strain);
    history.add_value("external_work", work);
    history.add_value("total_energy", kinetic + strain - work);
    history.add_value("fe_kinetic_energy", fe_kinetic);
    history.add_value("fe_strain_energy", fe_strain);
    history.add_value("pd_kinetic_energy", pd_kinetic);
    history.add_value("pd_strain_energy", pd_strain);
    history.add_value("broken_bonds", pd ? pd->n_global_broken_bonds() : 0.);
  }

  template <int dim>
  void
  MonitorRegionEnergies<dim>::execute(const Simulator<dim> &simulator, EnergyHistory &history)
  {
    const PDZone<dim> *pd = simulator.get_pd_zone();
    const auto         energies =
      pd ? pd->energies_in(simulator.get_monitor_region()) : std::pair<double, double>();
    history.add_value("pure_pd_kinetic_energy", energies.first);
    history.add_value("pure_pd_strain_energy", energies.second);
    history.add_value("pure_pd_energy", energies.first + energies.second);
  }

  template <int dim>
  void
  ConstraintResiduals<dim>::execute(const Simulator<dim> &simulator, EnergyHistory &history)
  {
    const Coupling<dim> *coupling = simulator.get_coupling();
    const auto           residuals =
      coupling ? coupling->constraint_residuals() : std::pair<double, double>();
    history.add_value("constraint_residual", residuals.first);
    history.add_value("constraint_rate_residual", residuals.second);
    history.add_value("multiplier_iterations", coupling ? coupling->last_solver_iterations() : 0.);
  }

  template <int dim>
  void
  BondStretches<dim>::execute(const Simulator<dim> &simulator, EnergyHistory &history)
  {
    const PDZone<dim> *pd         = simulator.get_pd_zone();
    double             largest[3] = {0, 0, 0};
    if (pd)
      {
        const BondFamilies<dim> &bonds = pd->get_bonds();
        const auto               u     = pd->get_state().displacements();
        const auto               alpha = pd->blending_weights();
        for (unsigned int i = 0; i < bonds.n_owned; ++i)
          for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
            {
              if (bonds.state[n] == BondFamilies<dim>::broken)
                continue;
              const unsigned int j     = bonds.neighbor(i, n);
              const auto        &entry = bonds.stencil[bonds.stencil_index[n]];
              const double       stretch =
                BondFamilies<dim>::extension(entry, u[j] - u[i]).first / entry.length;
              const double       a    = std::max(alpha[i], alpha[j]);
              const unsigned int part = a >= 1. ? 2 : (a > 0. ? 1 : 0);
              largest[part]           = std::max(largest[part], stretch);
            }
        Utilities::MPI::max(ArrayView<const double>(largest, 3),
                            pd->get_communicator(),
                            ArrayView<double>(largest, 3));
      }
    history.add_value("max_stretch_pure_pd", largest[0]);
    history.add_value("max_stretch_overlap", largest[1]);
    history.add_value("max_stretch_slave_layer", largest[2]);
  }

  template <int dim>
  void
  ParticleContactHistory<dim>::execute(const Simulator<dim> &simulator, EnergyHistory &history)
  {
    const PDZone<dim>          *pd      = simulator.get_pd_zone();
    const ParticleContact<dim> *contact = pd ? pd->get_particle_contact() : nullptr;
    history.add_value("touching_particles", pd ? pd->n_touching_particles() : 0);
    history.add_value("contact_energy",
                      contact ?
                        Utilities::MPI::sum(contact->local_energy(), pd->get_communicator()) :
                        0.);
  }

  template <int dim>
  void
  ContactForces<dim>::execute(const Simulator<dim> &simulator, EnergyHistory &history)
  {
    const Contact<dim> *contact = simulator.get_contact();
    const auto          force   = contact ? contact->total_force() : Tensor<1, dim>();
    const char         *axes[3] = {"x", "y", "z"};
    for (unsigned int d = 0; d < dim; ++d)
      history.add_value(std::string("contact_force_") + axes[d], force[d]);
    history.add_value("contact_nodes", contact ? contact->n_touching_nodes() : 0);
    if (contact)
      for (const auto &[column, value] : contact->history_columns())
        history.add_value(column, value);
  }

  template <int dim>
  void
  Probes<dim>::entries(ParameterEntries &entries)
  {
    entries.add("Points",
                points_text,
                Patterns::Anything(),
                "Points 'x, y[, z] : x, y[, z] : ...' [m] whose velocity is recorded.");
  }

  template <int dim>
  void
  Probes<dim>::declare_parameters(ParameterHandler &prm)
  {
    ParameterEntries::declare_here<Probes<dim>>(prm);
  }

  template <int dim>
  void
  Probes<dim>::parse_parameters(ParameterHandler &prm)
  {
    ParameterEntries::parse_here(prm, *this, "Postprocess/probes/");
    points = parse_point_list<dim>(points_text, "Postprocess/probes/Points");
  }

  template <int dim>
  void
  Probes<dim>::locate(const Simulator<dim> &simulator)
  {
    const FEZone<dim> *fe = simulator.has_fe_zone() ? &simulator.get_fe_zone() : nullptr;
    const PDZone<dim> *pd = simulator.get_pd_zone();
    const MPI_Comm     communicator =
      fe ? fe->get_dof_handler().get_communicator() : pd->get_communicator();
    const unsigned int rank    = Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    fe_locations.assign(points.size(), std::nullopt);
    fe_owner.assign(points.size(), n_ranks);
    particle.assign(points.size(), numbers::invalid_unsigned_int);
    particle_owner.assign(points.size(), n_ranks);
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        // The FE field, from the lowest rank whose cells hold the point.
        if (fe)
          fe_locations[k] = fe->locate(points[k]);
        fe_owner[k] = Utilities::MPI::min(fe_locations[k] ? rank : n_ranks, communicator);
        if (fe_owner[k] < n_ranks)
          continue;
        // The nearest particle, the lowest in (z, y, x) among equally near ones: each rank's
        // candidate (distance, position), then the same choice on every rank.
        std::vector<double> candidate;
        if (pd)
          {
            const auto &positions = pd->reference_positions();
            const auto  key       = [&](const unsigned int i) {
              std::vector<double> values{positions[i].distance(points[k])};
              for (int d = dim - 1; d >= 0; --d)
                values.push_back(positions[i][d]);
              return values;
            };
            for (unsigned int i = 0; i < pd->n_owned_particles(); ++i)
              if (const auto here = key(i); candidate.empty() || here < candidate)
                {
                  candidate   = here;
                  particle[k] = i;
                }
          }
        const auto all = Utilities::MPI::all_gather(communicator, candidate);
        for (unsigned int r = 0; r < n_ranks; ++r)
          if (!all[r].empty() && (particle_owner[k] == n_ranks || all[r] < all[particle_owner[k]]))
            particle_owner[k] = r;
        if (particle_owner[k] == n_ranks)
          throw_invalid_parameter("Postprocess/probes/Points",
                                  points_text,
                                  "points in the model (point " + std::to_string(k) +
                                    " lies in no FE cell and the model has no PD particle)");
      }
  }

  template <int dim>
  void
  Probes<dim>::execute(const Simulator<dim> &simulator, EnergyHistory &history)
  {
    const FEZone<dim> *fe = simulator.has_fe_zone() ? &simulator.get_fe_zone() : nullptr;
    const PDZone<dim> *pd = simulator.get_pd_zone();
    const std::array<std::size_t, 4> zones{{simulator.n_repartitions(),
                                            simulator.n_converted_cells(),
                                            fe ? fe->n_dofs() : 0,
                                            pd ? pd->n_global_particles() : 0}};
    if (!located || zones != located_for)
      {
        locate(simulator);
        located_for = zones;
        located     = true;
      }
    const MPI_Comm communicator =
      fe ? fe->get_dof_handler().get_communicator() : pd->get_communicator();
    const unsigned int               rank = Utilities::MPI::this_mpi_process(communicator);
    typename FEZone<dim>::VectorType velocity;
    if (fe)
      {
        fe->initialize_vector(velocity);
        velocity.copy_locally_owned_data_from(fe->get_state().velocity);
        velocity.update_ghost_values();
      }
    // Each point's value from the rank that evaluates it, summed in one reduction.
    std::vector<double> values(points.size() * dim, 0.);
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        Tensor<1, dim> value;
        if (fe_owner[k] == rank)
          value = fe->point_value(velocity, *fe_locations[k]);
        else if (particle_owner[k] == rank)
          value = pd->get_state().velocities()[particle[k]];
        for (unsigned int d = 0; d < dim; ++d)
          values[k * dim + d] = value[d];
      }
    Utilities::MPI::sum(values, communicator, values);
    const char *axes[3] = {"x", "y", "z"};
    for (unsigned int k = 0; k < points.size(); ++k)
      for (unsigned int d = 0; d < dim; ++d)
        history.add_value("probe_" + std::to_string(k) + "_v_" + axes[d], values[k * dim + d]);
  }

  template <int dim>
  void
  LinearMomentum<dim>::execute(const Simulator<dim> &simulator, EnergyHistory &history)
  {
    Tensor<1, dim> momentum;
    if (simulator.has_fe_zone())
      momentum += simulator.get_fe_zone().linear_momentum();
    if (simulator.get_pd_zone())
      momentum += simulator.get_pd_zone()->linear_momentum();
    const char *axes[3] = {"x", "y", "z"};
    for (unsigned int d = 0; d < dim; ++d)
      history.add_value(std::string("linear_momentum_") + axes[d], momentum[d]);
  }

  template <int dim>
  void
  SupportReactions<dim>::execute(const Simulator<dim> &simulator, EnergyHistory &history)
  {
    // Supports: the boundary ids of the box, then the prescribed regions.
    constexpr unsigned int n_supports =
      2 * dim + Parameters::Peridynamics<dim>::n_prescribed_regions;
    // Per support and component: reaction, displacement, prescribed components.
    std::vector<double> sums(3 * n_supports * dim, 0.);
    const auto          add = [&](const unsigned int support,
                         const unsigned int d,
                         const double       reaction,
                         const double       displacement) {
      if (support >= n_supports)
        return;
      double *entry = &sums[3 * (support * dim + d)];
      entry[0] += reaction;
      entry[1] += displacement;
      entry[2] += 1;
    };
    if (simulator.has_fe_zone())
      {
        const FEZone<dim> &fe    = simulator.get_fe_zone();
        const auto        &force = fe.applied_forces();
        const auto        &u     = fe.get_state().displacement;
        for (const auto &dof : fe.get_prescribed_dofs())
          add(dof.boundary_id,
              dof.component,
              force.local_element(dof.local_index),
              u.local_element(dof.local_index));
      }
    if (const PDZone<dim> *pd = simulator.get_pd_zone())
      pd->for_each_support_component(add);
    Utilities::MPI::sum(sums, simulator.get_communicator(), sums);
    if (columns.empty())
      for (unsigned int k = 0; k < n_supports * dim; ++k)
        if (sums[3 * k + 2] > 0)
          columns.push_back(k);
    const char *axes[3] = {"x", "y", "z"};
    for (const unsigned int k : columns)
      {
        const unsigned int support = k / dim;
        const std::string  name =
          (support < 2 * dim ? "boundary" + std::to_string(support) :
                               "region" + std::to_string(support - 2 * dim)) +
          "_" + axes[k % dim];
        history.add_value("reaction_" + name, sums[3 * k]);
        history.add_value("displacement_" + name, sums[3 * k + 1] / std::max(sums[3 * k + 2], 1.));
      }
  }

  template <int dim>
  void
  ZoneSizes<dim>::execute(const Simulator<dim> &simulator, EnergyHistory &history)
  {
    const PDZone<dim> *pd = simulator.get_pd_zone();
    history.add_value("pd_particles", pd ? pd->n_global_particles() : 0);
    history.add_value("fe_dofs", simulator.has_fe_zone() ? simulator.get_fe_zone().n_dofs() : 0);
    history.add_value("converted_cells", simulator.n_converted_cells());
    history.add_value("conversion_energy", simulator.conversion_energy_change());
    history.add_value("repartitions", simulator.n_repartitions());
    history.add_value("load_imbalance", pd ? simulator.load_imbalance() : 0.);

    const auto        &output = simulator.get_output_parameters();
    const unsigned int step   = simulator.get_step_number();
    const bool         due    = output.output_interval > 0 &&
                     (step % output.output_interval == 0 || step == simulator.get_n_steps());
    if (!pd || !due || Utilities::MPI::this_mpi_process(pd->get_communicator()) != 0)
      return;
    std::ostringstream name;
    name << output.directory << "/" << output.base_name << "_pd_region_" << std::setw(6)
         << std::setfill('0') << step << ".csv";
    std::ofstream file(name.str());
    AssertThrow(file, ExcMessage("Cannot write " + name.str()));
    file << "# t = " << std::setprecision(10) << simulator.get_time() << " s\n"
         << (dim == 2 ? "x0,y0,x1,y1\n" : "x0,y0,z0,x1,y1,z1\n");
    for (const Box<dim> &box : pd->get_region().boxes)
      for (unsigned int k = 0; k < 2 * dim; ++k)
        file << (k < dim ? box.lower[k] : box.upper[k - dim]) << (k + 1 < 2 * dim ? ',' : '\n');
    // Cells of a general mesh that joined the region: their vertices, in deal.II's order.
    const auto &cells = pd->get_region().cells;
    if (cells.empty())
      return;
    std::string cells_name = name.str();
    cells_name.replace(cells_name.rfind("_pd_region_"), 11, "_pd_cells_");
    std::ofstream cells_file(cells_name);
    AssertThrow(cells_file, ExcMessage("Cannot write " + cells_name));
    cells_file << "# t = " << std::setprecision(10) << simulator.get_time()
               << " s; each line the vertices x, y" << (dim == 3 ? ", z" : "")
               << " of a cell, in deal.II's order\n";
    for (const CellShape<dim> &cell : cells)
      for (unsigned int v = 0; v < cell.vertices.size(); ++v)
        for (unsigned int d = 0; d < dim; ++d)
          cells_file << cell.vertices[v][d]
                     << (v + 1 < cell.vertices.size() || d + 1 < dim ? ',' : '\n');
  }

  template class Postprocessor<2>;
  template class Postprocessor<3>;
  template class EnergyPostprocessor<2>;
  template class EnergyPostprocessor<3>;
  template class MonitorRegionEnergies<2>;
  template class MonitorRegionEnergies<3>;
  template class ConstraintResiduals<2>;
  template class ConstraintResiduals<3>;
  template class BondStretches<2>;
  template class BondStretches<3>;
  template class ContactForces<2>;
  template class ContactForces<3>;
  template class ParticleContactHistory<2>;
  template class ParticleContactHistory<3>;
  template class Probes<2>;
  template class Probes<3>;
  template class LinearMomentum<2>;
  template class LinearMomentum<3>;
  template class SupportReactions<2>;
  template class SupportReactions<3>;
  template class ZoneSizes<2>;
  template class ZoneSizes<3>;
  template class PluginRegistry<Postprocessor<2>>;
  template class PluginRegistry<Postprocessor<3>>;

  PERIARLEQUIN_REGISTER_POSTPROCESSOR(
    EnergyPostprocessor,
    "energies",
    "kinetic, strain and total energy, external work, per zone; broken bonds")
  PERIARLEQUIN_REGISTER_POSTPROCESSOR(
    MonitorRegionEnergies,
    "monitor region energies",
    "kinetic and strain energy of the PD particles in Output/Monitor region")
  PERIARLEQUIN_REGISTER_POSTPROCESSOR(
    BondStretches,
    "bond stretches",
    "largest bond stretch in the pure PD zone, the overlap and the slave layer")
  PERIARLEQUIN_REGISTER_POSTPROCESSOR(ContactForces,
                                      "contact forces",
                                      "total contact force on the body and nodes in contact")
  PERIARLEQUIN_REGISTER_POSTPROCESSOR(ParticleContactHistory,
                                      "particle contact",
                                      "PD particles touching another and the contact potential")
  PERIARLEQUIN_REGISTER_POSTPROCESSOR(Probes,
                                      "probes",
                                      "velocity at points (FE field, or the nearest PD particle "
                                      "in the pure PD zone)")
  PERIARLEQUIN_REGISTER_POSTPROCESSOR(SupportReactions,
                                      "support reactions",
                                      "load and mean displacement of every support (displacement "
                                      "boundary, prescribed region), per prescribed component")
  PERIARLEQUIN_REGISTER_POSTPROCESSOR(LinearMomentum,
                                      "linear momentum",
                                      "linear momentum of both zones, per component")
  PERIARLEQUIN_REGISTER_POSTPROCESSOR(
    ZoneSizes,
    "zone sizes",
    "PD particles, FE DoFs, cells converted to PD, the energy change of the conversions, "
    "repartitions and the load imbalance (largest rank load over the mean, minus one)")
  PERIARLEQUIN_REGISTER_POSTPROCESSOR(
    ConstraintResiduals,
    "constraint residuals",
    "|g|, |g_dot| of the coupling constraint and the multiplier CG iterations")
} // namespace PeriArlequin
