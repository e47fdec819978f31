#ifndef periarlequin_postprocess_crack_diagnostics_h
#define periarlequin_postprocess_crack_diagnostics_h

#include <deal.II/base/point.h>
#include <deal.II/base/mpi.h>
#include <deal.II/particles/property_pool.h>

#include <periarlequin/postprocess/postprocessor.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  template <int dim>
  class BondFamilies;

  /**
   * Crack tips and branches from the damage field, the same on every partition (it works on
   * the damaged particles gathered and sorted by id).
   *
   * Definitions. A particle is cracked when its damage reaches the threshold; two cracked
   * particles are linked when they are at most the link distance apart, and a crack is a
   * connected set of them. A particle's distance along links from the crack's origin (the
   * particles cracked at the first record, i.e. pre-cracks, or for a crack that nucleated
   * later, its particles of the record that first saw it) orders the particles; a tip is a
   * cracked particle farther along than the branch separation and the farthest (ties: the
   * larger id) within the branch separation around it. Its path length is the length of the
   * polyline through the points of its chain of links a branch separation apart (links
   * zigzag on a lattice). The crack extension is the path length of the farthest particle.
   * Two branches
   * are therefore told apart once their tips are more than the branch separation apart.
   * Tips are matched to the tips of the previous record nearest first; a tip left over
   * starts a new branch.
   */
  template <int dim>
  class CrackTracker
  {
  public:
    struct CrackedParticle
    {
      types::particle_index id;
      Point<dim>            position;
    };

    /** A crack branch: its tip and path length at each record that saw it. */
    struct Branch
    {
      std::vector<double>     times;
      std::vector<Point<dim>> tips;
      std::vector<double>     path_lengths;
      /** Was it seen at the last record? */
      bool active = true;

      /** Least-squares slope of the path length over the last @p window records [m/s]. */
      double
      speed(const unsigned int window) const;
    };

    CrackTracker(const double link_distance, const double branch_separation);

    /** The cracked particles at @p time, sorted by id (the same on every rank). */
    void
    update(const double time, const std::vector<CrackedParticle> &cracked);

    const std::vector<Branch> &
    get_branches() const;
    /** Branches seen at the last record. */
    unsigned int
    n_active_branches() const;
    /** The largest path length at the last record [m]. */
    double
    crack_extension() const;

  private:
    double link_distance, branch_separation;
    /** Record number at which each particle was first cracked. */
    std::map<types::particle_index, unsigned int> first_cracked;
    unsigned int                                  n_records = 0;
    std::vector<Branch>                           branches;
    double                                        extension = 0;
  };

  /**
   * The crack-length measure of a set of broken bonds: sum |xi| V v over the broken bonds,
   * each once, divided by the same sum over the bonds that cross a unit area of a plane
   * normal to a lattice axis. It is exactly the area (2D: the length) of a straight crack
   * along a lattice plane, and weighs the bonds like the energy of a bond at a fixed critical
   * stretch, which grows with |xi|, for other directions. Summed over all ranks [m^(dim-1)].
   */
  template <int dim>
  double
  broken_bond_area(const BondFamilies<dim> &bonds,
                   const double             lattice_spacing,
                   const MPI_Comm           communicator);

  /**
   * Crack diagnostics ("cracks"): number of branches, tip position, path length and speed of
   * each branch (CrackTracker), the crack extension, the crack area measured by the broken
   * bonds (broken_bond_area()) created since the start and the energy they dissipated,
   * G0 times that area (Peridynamics/Critical energy release rate; 2D: per unit thickness).
   * Maps of the damaged particles are written as CSV (x, y[, z], damage; a first line
   * "# t = <time> s; domain <lower corner> <upper corner>") with the ParaView output
   * (Output/Output interval), for scripts/plot_cracks.sh.
   */
  template <int dim>
  class CrackDiagnostics : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm) override;
    void
    execute(const Simulator<dim> &simulator, EnergyHistory &history) override;

  private:
    /** Write the damaged particles to <base>_damage_<step>.csv on rank 0. */
    void
    write_damage_map(const Simulator<dim> &simulator) const;

    double                             damage_threshold   = 0.35;
    /** In lattice spacings. */
    double                             link_distance      = 2.;
    /** In horizons. */
    double                             branch_separation  = 2.;
    unsigned int                       speed_window       = 5;
    unsigned int                       reported_branches  = 4;
    std::unique_ptr<CrackTracker<dim>> tracker;
    double                             initial_area = 0;
    /** Damaged particles (id, position, damage) of the last record, sorted by id. */
    std::vector<std::pair<typename CrackTracker<dim>::CrackedParticle, double>> damaged;
  };
} // namespace PeriArlequin

#endif
