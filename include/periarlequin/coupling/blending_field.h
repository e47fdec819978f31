#ifndef periarlequin_coupling_blending_field_h
#define periarlequin_coupling_blending_field_h

#include <periarlequin/base/parameters.h>
#include <periarlequin/base/regions.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <limits>
#include <string>

namespace PeriArlequin
{
  using namespace dealii;

  /** The shape of alpha across an overlap. */
  enum class BlendingProfile
  {
    /** alpha = l1 / (l1 + l2), eq. 37: linear across a strip. */
    linear,
    /** 0 in the half of the overlap next to the PD region, 1 in the other half (fig. 8). */
    step
  };

  namespace Parameters
  {
    /** Where the blending weight alpha enters the forces (doc/method.md, section 4). */
    enum class Blending
    {
      /** FE weight inside the integral (eq. 47b), PD weight per node (eq. 55). */
      paper,
      /** Weight inside the sums on both sides: forces derive from the blended Hamiltonian. */
      energy,
      /** Nodal weights on both sides: passes the patch test, not conservative. */
      force
    };

    inline const SelectionNames<Blending> blending_names = {{"paper", Blending::paper},
                                                            {"energy", Blending::energy},
                                                            {"force", Blending::force}};

    enum class MultiplierSolver
    {
      /** The paper's row-sum diagonal of A (eq. 68). */
      diagonal,
      /** Conjugate gradients on A, to a relative residual of 1e-12. */
      cg
    };

    inline const SelectionNames<MultiplierSolver> multiplier_solver_names =
      {{"diagonal", MultiplierSolver::diagonal}, {"cg", MultiplierSolver::cg}};

    /** When the fine-scale damping force takes its velocity within a step (doc/method.md, 6). */
    enum class DampingIntegration
    {
      /**
       * At the velocity of the end of the step (solved per node): stable at any damping up
       * to the undamped stable step.
       */
      implicit,
      /**
       * At the half-step velocity (the paper's eq. 79c): the damping lowers the stable step
       * to 2 / omega (sqrt(1 + xi^2) - xi), xi = C_I / (2 omega).
       */
      half_step
    };

    inline const SelectionNames<DampingIntegration> damping_integration_names =
      {{"implicit", DampingIntegration::implicit}, {"half step", DampingIntegration::half_step}};

    /** The Arlequin coupling: zones, blending, multipliers, fine-scale damping. */
    struct Coupling
    {
      /** "none" (uncoupled: pure FE, pure PD or independent bodies) or a registered name. */
      std::string method = "none";
      /** Overlap (0 < alpha < 1) and pure FE (alpha = 1) regions; pure PD is the PD region. */
      std::string overlap_text, fe_region_text;
      /** Width of the band around the PD region that is the overlap (0: the regions) [m]. */
      double             overlap_width         = 0.;
      Blending           blending              = Blending::energy;
      MultiplierSolver   multiplier_solver     = MultiplierSolver::diagonal;
      bool               damping               = true;
      double             damping_constant      = 10.;
      double             damping_wave_speed    = 0.;
      double             damping_overlap_width = 0.;
      DampingIntegration damping_integration   = DampingIntegration::implicit;
      double             minimum_pd_weight     = 0.1;
      /** Steps between two checks of the FE strain against the critical stretch (0: none). */
      unsigned int strain_check_interval = 10;

      /** Are the zones coupled? */
      bool
      coupled() const;

      void
      entries(ParameterEntries &entries);
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters

  /**
   * The blending weight alpha(x) of eq. 37: 0 in the pure PD region, 1 in the pure FE region,
   * alpha = l1 / (l1 + l2) in the overlap with l1 the distance to the pure PD region and l2 the
   * distance to the pure FE region, so it is linear across a strip. For the "bad" coupling it
   * is the step that splits the overlap into a PD-to-FE half (alpha = 0) and an FE-to-PD half
   * (alpha = 1) (BlendingProfile::step).
   *
   * The zones are given either as boxes (Coupling/Overlap region and Finite element region;
   * check_against_mesh() checks that they cover the domain, that the alpha = 0 and alpha = 1
   * edges neither touch nor cross and that the overlap is at least one FE cell wide), or as a band
   * of width w around the PD region (Coupling/Overlap width): alpha = min(1, l1 / w), which is
   * eq. 37 across a strip and needs no FE region. Only a band follows a PD region that grows
   * (add_to_pd_region()).
   */
  template <int dim>
  class BlendingField
  {
  public:
    BlendingField(const Parameters::Coupling &coupling,
                  const BlendingProfile       profile,
                  const Region<dim>          &pure_pd_region);

    /**
     * The checks that need the mesh, given the largest cell extent in each direction [m] and
     * points that sample the domain (a box: its half-cell grid; a mesh file: the vertices
     * and centres of the cells): a band at least one cell wide; boxes whose alpha = 0 and
     * alpha = 1 edges are at least one cell apart, and that cover every point.
     */
    void
    check_against_mesh(const Tensor<1, dim> &cell_size, const std::vector<Point<dim>> &points);

    /** alpha(x) in [0, 1]. */
    double
    value(const Point<dim> &x) const;

    /** Is @p x in the overlap (both zones present)? Closed on both edges. */
    bool
    in_overlap(const Point<dim> &x) const;

    /** Width of the overlap through @p x, l1 + l2 [m]. */
    double
    overlap_width(const Point<dim> &x) const;

    /**
     * Distance from @p x to the part where alpha < 1 (PD region and overlap) [m]; one of
     * @p cap or more may come back as any number >= @p cap (RegionDistance::distance()).
     */
    double
    distance_to_pd_part(const Point<dim> &x,
                        const double      cap = std::numeric_limits<double>::infinity()) const;

    /** The pure PD region (alpha = 0). */
    const Region<dim> &
    pd_region() const;

    /** Is the overlap a band around the PD region (Coupling/Overlap width > 0)? */
    bool
    is_band() const;

    /**
     * Add @p converted (boxes, or cells of a general mesh) to the pure PD region; the band of
     * the overlap moves outward with it.
     * Only for a band.
     */
    void
    add_to_pd_region(const Region<dim> &converted);
    /**
     * Make the pure PD region @p grown, a region that add_to_pd_region() reached in an
     * earlier run (a checkpoint). Only for a band.
     */
    void
    set_pd_region(const Region<dim> &grown);

  private:
    BlendingProfile profile;
    Region<dim>     pure_pd, overlap_region, pure_fe;
    /** The entries the boxes came from, for messages. */
    std::string overlap_text, fe_region_text;
    /** Width of the band (0: the overlap and FE regions are boxes) [m]. */
    double band_width;
    /** Distances to pure_pd (a grown region has many pieces). */
    RegionDistance<dim> distance_to_pure_pd;
    /** Tolerance for merging the boxes of the PD region [m] (set by check_against_mesh()). */
    double length_tolerance = 0;
  };
} // namespace PeriArlequin

#endif
