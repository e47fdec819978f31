#ifndef periarlequin_postprocess_wave_reflection_h
#define periarlequin_postprocess_wave_reflection_h

#include <periarlequin/base/parameters.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <string>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The reflection and transmission of a narrow-band wave packet at an Arlequin overlap, in a
   * strip one FE cell high (2D, plane stress): the measurement behind the absorption study.
   *
   * The strip is pure PD from x = 0 to the overlap, then FE. A packet u_x = A g(x - x0)
   * cos(k (x - x0)), with a Gaussian envelope g of standard deviation sigma = lambda and the
   * lateral contraction of uniaxial stress, starts in the pure PD zone moving towards the
   * overlap (v = -c u', the bar speed c = sqrt(E / rho)). A reference run, PD over the whole
   * strip on the same lattice, carries the same packet on without an interface. At the
   * time T when what the overlap sent back has come back into the pure PD zone (and before
   * it can reach the overlap again), the reflected wave is the difference of the two runs
   * there: its energy is taken as twice its kinetic energy, sum_I m_I |w_I - w_ref,I|^2 over
   * the pure-PD particles (a travelling wave holds as much strain as kinetic energy), and
   * R = that / the packet's initial energy. What got through: T = the FE zone's energy
   * at that time / the energy the reference has carried past the pure PD zone. Both are
   * energy ratios.
   *
   * From the FE side (Incident side = fe) the packet starts in the pure FE zone beyond the
   * overlap, moving to -x; the reference is FE over the whole strip; R is twice the kinetic
   * energy of the difference at the pure-FE nodes (matched by position, lumped masses), T
   * the pure PD zone's energy over the packet's.
   */
  struct WaveReflection
  {
    /** The entries of the subsection "Wave reflection", declared and parsed. */
    void
    entries(ParameterEntries &entries);
    /** Declare the study's parameters in the subsection "Wave reflection". */
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** FE cell size h [m]. */
    double fe_cell_size = 0.02;
    /** h / dx [-]. */
    unsigned int size_ratio = 8;
    /** Overlap width in FE cells [-]. */
    unsigned int overlap_cells = 5;
    /** Wavelength lambda / h [-]. */
    double wavelength = 6;
    /** Horizon factor m = delta / dx [-]. */
    double horizon_factor = 3.015;
    /** Time step over the PD stable-step estimate 0.2 dx / c [-]. */
    double time_step_fraction = 1;
    /** Whether the packet comes from the FE zone (else from the pure PD zone). */
    bool from_fe = false;
    /** The "Coupling" subsection's entries other than the regions, as parameter text. */
    std::string coupling = "set Method = weak\n";

    /** The result of measure(). */
    struct Result
    {
      double reflected, transmitted, incident_energy, time;
    };

    /** Run the reference and the coupled strip and return R and T (on every rank). */
    Result
    measure(const MPI_Comm communicator) const;

    /** The coupled case's parameter text (the reference: @p reference = true). */
    std::string
    case_text(const bool reference) const;

    /** Aluminium of section 6.1 [Pa, -, kg/m^3]. */
    static constexpr double youngs_modulus = 69e9, poissons_ratio = 0.3, density = 2700;
  };
} // namespace PeriArlequin

#endif
