#ifndef periarlequin_simulator_checkpoint_record_h
#define periarlequin_simulator_checkpoint_record_h

#include <periarlequin/simulator.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace PeriArlequin
{
  /**
   * What a checkpoint holds besides the mesh and its cell data (source/simulator/
   * checkpoint.cc writes and reads it): the parameters it must agree with, the clock, the
   * grown PD region, the counters, the works, the history and the output records.
   */
  template <int dim>
  struct Simulator<dim>::CheckpointRecord
  {
    std::string              format    = "PeriArlequin checkpoint 6";
    unsigned int             dimension = dim;
    std::vector<std::string> parameters;
    unsigned int             n_ranks = 0;
    unsigned int             step    = 0;
    /** The pure PD region (grown by an adaptive zone). */
    Region<dim>  pd_region;
    unsigned int converted_cells = 0, repartitions = 0;
    double       conversion_energy = 0, fe_work = 0;
    /** StaticSolver::equilibrium_force_scale() when the checkpoint was written [N^2]. */
    double equilibrium_force_scale = 0;
    /** The adaptive zone's running damage (all ranks), point after point, dim numbers each. */
    std::vector<double> running_damage;
    /** Each rank's share of the PD zone's external work [J]. */
    std::vector<double>                         pd_work;
    std::vector<std::string>                    history_names;
    std::vector<std::vector<double>>            history_rows;
    std::vector<std::pair<double, std::string>> fe_records, pd_records;
    std::vector<std::string>                    postprocessor_states;
    /** The contact model's own state (a projectile's motion; Contact::save_state()). */
    std::string contact_state;
    /** The other files of the checkpoint (the mesh and its cell data) and their checksums. */
    std::vector<std::pair<std::string, std::uint64_t>> files;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &format &dimension &parameters &n_ranks &step &pd_region &converted_cells
        &repartitions &conversion_energy &fe_work &equilibrium_force_scale &running_damage &pd_work
          &history_names &history_rows &fe_records &pd_records &postprocessor_states &contact_state
            &files;
    }
  };

} // namespace PeriArlequin

#endif
