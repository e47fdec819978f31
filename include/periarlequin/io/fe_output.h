#ifndef periarlequin_io_fe_output_h
#define periarlequin_io_fe_output_h

#include <periarlequin/base/parameters.h>
#include <periarlequin/fe/fe_zone.h>
#include <periarlequin/io/pvd_series.h>

#include <deal.II/lac/la_parallel_vector.h>

#include <string>
#include <utility>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * Field output of the FE zone: one .pvtu (with a .vtu per rank) per output step carrying
   * displacement, velocity, the stress tensor components and the von Mises stress, plus a
   * .pvd record so that ParaView shows the series against simulated time.
   */
  template <int dim>
  class FEOutput
  {
  public:
    FEOutput(const FEZone<dim> &fe_zone, const Parameters::Output &parameters);

    void
    write(const unsigned int                                step,
          const double                                      time,
          const LinearAlgebra::distributed::Vector<double> &displacement,
          const LinearAlgebra::distributed::Vector<double> &velocity);

    /** The .pvd record of the files written (kept in checkpoints). */
    PVDSeries &
    get_series();

  private:
    const FEZone<dim>       &fe_zone;
    const Parameters::Output parameters;
    PVDSeries                series;
  };
} // namespace PeriArlequin

#endif
