#ifndef periarlequin_postprocess_crack_diagnostics_h
#define periarlequin_postprocess_crack_diagnostics_h

#include <periarlequin/postprocess/postprocessor.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/particles/property_pool.h>

#include <array>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
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

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &times &tips &path_lengths &active;
      }
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

    /** All of the tracker's state (a checkpoint of CrackDiagnostics). */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &link_distance &branch_separation &first_cracked &n_records &branches &extension;
    }

  private:
    double link_distance, branch_separation;
    /** Record number at which each particle was first cracked. */
    std::map<types::particle_index, unsigned int> first_cracked;
    unsigned int                                  n_records = 0;
    std::vector<Branch>                           branches;
    double                                        extension = 0;
  };

  /**
   * Initiation and kink of a crack that leaves a pre-crack, from the damage field, in the x-y
   * plane (in 3D, projected on it: the crack front runs along z).
   *
   * Definitions. The initial tip and the crack's direction are given. A new cracked particle
   * is one cracked now that was not at the first record, ahead of the tip (within 120 degrees
   * of the crack direction). Initiation is the first record at which a particle within a
   * horizon of the tip has more broken bonds than at the first record; growth is the first
   * record with a new cracked particle a horizon or more from the tip. The kink angle is the
   * direction, measured from the crack direction (counter-clockwise positive), of the
   * least-squares line through the tip (the principal axis of the second moment about the tip)
   * of the new cracked particles at distances within the fit range.
   */
  template <int dim>
  class CrackInitiation
  {
  public:
    using CrackedParticle = typename CrackTracker<dim>::CrackedParticle;

    /**
     * @p direction [rad]; @p fit_range: the least and largest distance from the tip of the
     * particles the kink angle fits [m].
     */
    CrackInitiation(const Point<dim>            &tip,
                    const double                 direction,
                    const double                 horizon,
                    const std::array<double, 2> &fit_range);

    /**
     * The cracked particles at @p time (the same on every rank) and the number of broken bonds
     * of the particles within a horizon of the tip.
     */
    void
    update(const double                        time,
           const std::vector<CrackedParticle> &cracked,
           const unsigned long long            broken_near_tip);

    /** In-plane distance of @p x from the tip [m]. */
    double
    distance_from_tip(const Point<dim> &x) const;

    /** Time of initiation, growth by a horizon [s]; NaN before. */
    double
    initiation_time() const;
    double
    growth_time() const;
    /** Kink angle at the last record [rad]; NaN with fewer than three particles to fit. */
    double
    kink_angle() const;
    unsigned int
    n_fitted_particles() const;

    /** All of the diagnostics' state (a checkpoint of CrackDiagnostics). */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &tip &direction &horizon &fit_range[0] & fit_range[1] &
        first_record &initial_broken_near_tip &initially_cracked &initiation &growth &angle
          &n_fitted;
    }

  private:
    Point<dim>                      tip;
    Tensor<1, 2>                    direction;
    double                          horizon;
    std::array<double, 2>           fit_range;
    bool                            first_record            = true;
    unsigned long long              initial_broken_near_tip = 0;
    std::set<types::particle_index> initially_cracked;
    double                          initiation = std::numeric_limits<double>::quiet_NaN();
    double                          growth     = std::numeric_limits<double>::quiet_NaN();
    double                          angle      = std::numeric_limits<double>::quiet_NaN();
    unsigned int                    n_fitted   = 0;
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
   * (Output/Output interval), for scripts/plot_cracks.sh. Given the initial tip of a
   * pre-crack, also its initiation, growth and kink angle (CrackInitiation), with the stress
   * intensity factors and energy release rate of the crack-tip field at those times when the
   * boundaries carry one.
   */
  template <int dim>
  class CrackDiagnostics : public Postprocessor<dim>
  {
  public:
    /** The entries of subsection "Postprocess/cracks", declared and parsed. */
    void
    entries(ParameterEntries &entries);
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm) override;
    void
    execute(const Simulator<dim> &simulator, EnergyHistory &history) override;
    /** The tracked branches, the initiation events and the initial crack area. */
    std::string
    save_state() const override;
    void
    load_state(const std::string &state) override;

  private:
    /** Update the initiation diagnostics and add their columns (and say when it happens). */
    void
    report_initiation(const Simulator<dim>                                           &simulator,
                      const std::vector<typename CrackTracker<dim>::CrackedParticle> &cracked,
                      EnergyHistory                                                  &history);
    /** Write the damaged particles to <base>_damage_<step>.csv on rank 0. */
    void
    write_damage_map(const Simulator<dim> &simulator) const;

    double damage_threshold = 0.35;
    /** In lattice spacings. */
    double link_distance = 2.;
    /** In horizons. */
    double                             branch_separation = 2.;
    unsigned int                       speed_window      = 5;
    unsigned int                       reported_branches = 4;
    std::unique_ptr<CrackTracker<dim>> tracker;
    /** Without an initial tip, no initiation and kink diagnostics. */
    std::optional<Point<dim>> initial_tip;
    /** In degrees. */
    double initial_direction = 0;
    /** In horizons. */
    std::array<double, 2>                 kink_fit_range = {{1., 5.}};
    std::unique_ptr<CrackInitiation<dim>> initiation;
    /** K_I, K_II [Pa m^(1/2)] and G [J/m^2] of the crack-tip field at initiation and growth. */
    std::array<double, 3> load_at_initiation, load_at_growth;
    double                initial_area = 0;
    /** Damaged particles (id, position, damage) of the last record, sorted by id. */
    std::vector<std::pair<typename CrackTracker<dim>::CrackedParticle, double>> damaged;
  };
} // namespace PeriArlequin

#endif
