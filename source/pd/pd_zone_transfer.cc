#include <periarlequin/pd/pd_zone.h>

#include <deal.II/base/utilities.h>

#include <boost/range/iterator_range.hpp>
#include <boost/serialization/array.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <unordered_map>

namespace PeriArlequin
{
  namespace
  {
    /**
     * What a particle takes along to its new owner in a repartition or a checkpoint: its
     * kinematics, applied force, settling force and its start, strain energy density (so the
     * energies of the step that repartitioned are those of its force pass) and broken bonds.
     */
    template <int dim>
    struct TransferredParticle
    {
      types::particle_index              id;
      std::array<Tensor<1, dim>, 5>      kinematics;
      double                             settling_start;
      double                             energy_density;
      std::vector<types::particle_index> broken_partners;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &id &kinematics &settling_start &energy_density &broken_partners;
      }
    };
  } // namespace

  template <int dim>
  std::vector<char>
  PDZone<dim>::pack_particle_state(const typename Triangulation<dim>::cell_iterator &cell) const
  {
    std::vector<TransferredParticle<dim>> records;
    for (const auto &particle : particle_handler.particles_in_cell(
           typename Triangulation<dim>::active_cell_iterator(cell)))
      {
        const unsigned int       i        = ghosts.local_index(particle.get_id());
        const bool               settling = !settling_force.empty();
        TransferredParticle<dim> record{particle.get_id(),
                                        {{state.displacements()[i],
                                          state.velocities()[i],
                                          state.accelerations()[i],
                                          applied_force[i],
                                          settling ? settling_force[i] : Tensor<1, dim>()}},
                                        settling ? settling_start[i] :
                                                   -std::numeric_limits<double>::infinity(),
                                        energy_density[i],
                                        broken_partners[i]};
        records.push_back(std::move(record));
      }
    return Utilities::pack(records, false);
  }

  template <int dim>
  void
  PDZone<dim>::attach_particle_state()
  {
    const auto         ids     = ghosts.ids();
    const unsigned int n_owned = ghosts.n_owned();
    broken_partners.assign(n_owned, {});
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int n = bonds.family_begin[i]; n < bonds.family_begin[i + 1]; ++n)
        if (bonds.state[n] == BondFamilies<dim>::broken)
          {
            const unsigned int j = bonds.neighbor(i, n);
            broken_partners[i].push_back(ids[j]);
            if (j < n_owned)
              broken_partners[j].push_back(ids[i]);
          }
    state_handle = triangulation.register_data_attach(
      [this](const typename Triangulation<dim>::cell_iterator &cell,
             const typename Triangulation<dim>::CellStatus) { return pack_particle_state(cell); },
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
        for (auto &record : Utilities::unpack<std::vector<TransferredParticle<dim>>>(data.begin(),
                                                                                     data.end(),
                                                                                     false))
          received.emplace(record.id, std::move(record));
      });
    state_handle = numbers::invalid_unsigned_int;

    build_particle_structures();
    settling_force.assign(ghosts.n_owned(), Tensor<1, dim>());
    settling_start.assign(ghosts.n_owned(), -std::numeric_limits<double>::infinity());
    const auto                          ids = ghosts.ids();
    typename BondFamilies<dim>::IdPairs broken;
    for (unsigned int i = 0; i < ghosts.n_owned(); ++i)
      {
        const auto found = received.find(ids[i]);
        AssertThrow(found != received.end(),
                    ExcMessage("A particle arrived without its state in a repartition or "
                               "from a checkpoint."));
        const auto &[u, v, a, f, s] = found->second.kinematics;
        state.displacements()[i]    = u;
        state.velocities()[i]       = v;
        state.accelerations()[i]    = a;
        applied_force[i]            = f;
        settling_force[i]           = s;
        settling_start[i]           = found->second.settling_start;
        energy_density[i]           = found->second.energy_density;
        for (const types::particle_index partner : found->second.broken_partners)
          broken.emplace_back(std::minmax(ids[i], partner));
      }
    bonds.break_bonds(broken, ghosts);
    latest_settling_start = -std::numeric_limits<double>::infinity();
    for (const double start : settling_start)
      latest_settling_start = std::max(latest_settling_start, start);
    if (std::isfinite(latest_settling_start))
      tracks_work = true;
    else
      {
        settling_force.clear();
        settling_start.clear();
      }
    update_ghost_displacements();
  }

  template class PDZone<2>;
  template class PDZone<3>;
} // namespace PeriArlequin
