#ifndef periarlequin_io_pd_output_h
#define periarlequin_io_pd_output_h

#include <periarlequin/base/parameters.h>
#include <periarlequin/io/pvd_series.h>
#include <periarlequin/pd/pd_zone.h>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * Particle output of the PD zone (Particles::DataOut): one .pvtu (with a .vtu per rank) per
   * output step carrying displacement, velocity, damage and the material model's particle
   * scalars, plus a .pvd record so that ParaView shows the series against simulated time.
   */
  template <int dim>
  class PDOutput
  {
  public:
    PDOutput(PDZone<dim> &pd_zone, const Parameters::Output &parameters);

    void
    write(const unsigned int step, const double time);

    /** The .pvd record of the files written (kept in checkpoints). */
    PVDSeries &
    get_series();

  private:
    PDZone<dim>             &pd_zone;
    const Parameters::Output parameters;
    PVDSeries                series;
  };
} // namespace PeriArlequin

#endif
