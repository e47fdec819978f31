// A user postprocessor: the linear momentum of the PD particles [kg m/s] in the directions the
// user lists ("Postprocess/momentum/Components"), as columns momentum_x, ... of the history.

#include <periarlequin/postprocess/postprocessor.h>
#include <periarlequin/simulator.h>

namespace UserPlugins
{
  using namespace dealii;

  template <int dim>
  class Momentum : public PeriArlequin::Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Components",
                        "x, y",
                        Patterns::MultipleSelection("x|y|z"),
                        "Directions whose momentum is recorded.");
    }

    void
    parse_parameters(ParameterHandler &prm) override
    {
      components = Utilities::split_string_list(prm.get("Components"));
    }

    void
    execute(const PeriArlequin::Simulator<dim> &simulator,
            PeriArlequin::EnergyHistory        &history) override
    {
      Tensor<1, dim> momentum;
      if (const auto *pd = simulator.get_pd_zone())
        for (unsigned int i = 0; i < pd->n_owned_particles(); ++i)
          if (!pd->is_slave(i))
            momentum += pd->particle_mass(i) * pd->get_state().velocities()[i];
      for (const std::string &component : components)
        {
          const unsigned int d = component[0] - 'x';
          history.add_value("momentum_" + component,
                            d < dim ? Utilities::MPI::sum(momentum[d], MPI_COMM_WORLD) : 0.);
        }
    }

  private:
    std::vector<std::string> components;
  };

  PERIARLEQUIN_REGISTER_POSTPROCESSOR(Momentum,
                                      "momentum",
                                      "linear momentum of the PD particles (a user postprocessor)")
} // namespace UserPlugins
