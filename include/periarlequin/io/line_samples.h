#ifndef periarlequin_io_line_samples_h
#define periarlequin_io_line_samples_h

#include <periarlequin/base/parameters.h>
#include <periarlequin/fe/fe_zone.h>
#include <periarlequin/pd/pd_zone.h>

#include <deal.II/base/point.h>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * Displacements and velocities along a segment (Output/Sample line) at the output steps: the FE
   * nodes on the segment and the PD particles within dx/2 of it, gathered on rank 0 into
   * \<base\>_line_\<step\>.csv (zone, position, displacement, velocity), sorted by zone and
   * position so that the file does not depend on the partition.
   */
  template <int dim>
  class LineSamples
  {
  public:
    /** The segment from @p a to @p b; PD particles are taken within @p lattice_spacing / 2. */
    LineSamples(const Point<dim>         &a,
                const Point<dim>         &b,
                const Parameters::Output &parameters,
                const double              lattice_spacing,
                const MPI_Comm            communicator);

    /** Write the samples of step @p step; either zone may be nullptr. */
    void
    write(const unsigned int step, const FEZone<dim> *fe_zone, const PDZone<dim> *pd_zone) const;

  private:
    const Point<dim>         a, b;
    const Parameters::Output parameters;
    const double             lattice_spacing;
    const MPI_Comm           communicator;
  };
} // namespace PeriArlequin

#endif
