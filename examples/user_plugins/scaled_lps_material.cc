// A user material model: the library's LPS with a critical stretch scaled by a factor of the
// user's choosing (a calibration knob for fracture), registered under "scaled LPS" with its
// parameter "Peridynamics/scaled LPS/Critical stretch factor".

#include <periarlequin/pd/material_model.h>

namespace UserPlugins
{
  using namespace dealii;

  template <int dim>
  class ScaledLPS : public PeriArlequin::LinearPeridynamicSolid<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Critical stretch factor",
                        "1",
                        Patterns::Double(0),
                        "Factor on the LPS critical stretch of G0 [-].");
    }

    void
    parse_parameters(ParameterHandler &prm) override
    {
      factor = prm.get_double("Critical stretch factor");
    }

    double
    critical_stretch(const double energy_release_rate, const double horizon) const override
    {
      return factor *
             PeriArlequin::LinearPeridynamicSolid<dim>::critical_stretch(energy_release_rate,
                                                                         horizon);
    }

  private:
    double factor = 1;
  };

  PERIARLEQUIN_REGISTER_PD_MATERIAL(ScaledLPS,
                                    "scaled LPS",
                                    "LPS with a scaled critical stretch (a user model)")
} // namespace UserPlugins
