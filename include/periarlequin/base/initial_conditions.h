#ifndef periarlequin_base_initial_conditions_h
#define periarlequin_base_initial_conditions_h

#include <periarlequin/base/parameters.h>
#include <periarlequin/base/plugin_registry.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/base/tensor.h>

#include <memory>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The initial displacement and velocity of the body, the same for the FE and the PD zone
   * (the FE zone interpolates them at its nodes, the PD zone evaluates them at the particles'
   * reference positions). Selected by name in "Initial conditions/Model"; a model's own
   * parameters live in "Initial conditions/<name>".
   *
   * Users add a model by deriving from this class and registering it with
   * PERIARLEQUIN_REGISTER_INITIAL_CONDITION in their own source file.
   */
  template <int dim>
  class InitialCondition
  {
  public:
    virtual ~InitialCondition() = default;

    /** Read the parameters declared by the class's static declare_parameters(). */
    virtual void
    parse_parameters(ParameterHandler &prm);

    /** u(x, 0) [m]. */
    virtual Tensor<1, dim>
    displacement(const Point<dim> &x) const = 0;

    /** v(x, 0) [m/s]. */
    virtual Tensor<1, dim>
    velocity(const Point<dim> &x) const = 0;
  };

  template <int dim>
  using InitialConditionRegistry = PluginRegistry<InitialCondition<dim>>;


  /** "function": displacement and velocity as muparser expressions of (x, y[, z]). */
  template <int dim>
  class FunctionInitialCondition : public InitialCondition<dim>
  {
  public:
    FunctionInitialCondition();

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm) override;
    Tensor<1, dim>
    displacement(const Point<dim> &x) const override;
    Tensor<1, dim>
    velocity(const Point<dim> &x) const override;

  private:
    // Evaluation changes the parser's scratch state, not the condition.
    mutable Functions::ParsedFunction<dim> displacement_function, velocity_function;
  };


  /**
   * "wave pulse": the initial pulse of the paper's wave study (eq. 81 in our reading),
   * d(x) = a1 (1 + cos(2 pi s / w1)) (1 + a2 cos(2 pi (s + w1/2) / w2)) for |s| <= w1/2,
   * else 0, with s = x - x0, along one displacement component, at rest. Released, it splits
   * into two pulses running in -x and +x.
   */
  template <int dim>
  class WavePulseInitialCondition : public InitialCondition<dim>
  {
  public:
    void
    entries(ParameterEntries &entries);
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm) override;
    Tensor<1, dim>
    displacement(const Point<dim> &x) const override;
    Tensor<1, dim>
    velocity(const Point<dim> &x) const override;

  private:
    double       amplitude = 3e-4, modulation = 0.3, width = 0.48, modulation_wavelength = 0.03;
    double       centre    = 0;
    unsigned int component = 0;
  };
} // namespace PeriArlequin

/**
 * Register the initial condition template @p classname (instantiated for 2 and 3
 * dimensions) under @p name; its static declare_parameters(), if any, declares the entries
 * of subsection "Initial conditions/<name>".
 */
#define PERIARLEQUIN_REGISTER_INITIAL_CONDITION(classname, name, description)            \
  namespace                                                                              \
  {                                                                                      \
    const bool periarlequin_registered_initial_condition_##classname =                   \
      PeriArlequin::register_plugin_template<PeriArlequin::InitialCondition, classname>( \
        name,                                                                            \
        description);                                                                    \
  }

#endif
