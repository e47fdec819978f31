#ifndef periarlequin_base_separable_field_h
#define periarlequin_base_separable_field_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <utility>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * A vector field that is a factor of time times a field of space, f(x, t) = g(t) h(x). A
   * prescribed motion is evaluated at every prescribed point in every step, three times for
   * the central differences of its velocity and acceleration; a Function that also derives
   * from this class lets the zones evaluate h once per point at set-up and g three times per
   * step (the crack-tip field, whose h costs trigonometric functions and a power).
   */
  template <int dim>
  class SeparableField
  {
  public:
    virtual ~SeparableField() = default;

    /** g(t). */
    virtual double
    time_factor(const double t) const = 0;

    /** h(x): the field where g = 1. */
    virtual Tensor<1, dim>
    spatial_field(const Point<dim> &x) const = 0;
  };

  /**
   * g(t - dt), g(t), g(t + dt) of the separable fields met in one step, each evaluated once.
   */
  template <int dim>
  class TimeFactors
  {
  public:
    TimeFactors(const double time, const double time_step)
      : time(time)
      , time_step(time_step)
    {}

    const std::array<double, 3> &
    operator()(const SeparableField<dim> &field)
    {
      for (const auto &[known_field, factors] : known)
        if (known_field == &field)
          return factors;
      known.emplace_back(&field,
                         std::array<double, 3>{{field.time_factor(time - time_step),
                                                field.time_factor(time),
                                                field.time_factor(time + time_step)}});
      return known.back().second;
    }

  private:
    const double                                                               time, time_step;
    std::vector<std::pair<const SeparableField<dim> *, std::array<double, 3>>> known;
  };
} // namespace PeriArlequin

#endif
