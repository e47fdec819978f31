// The history's columns are matched by name in every build (not only in Debug): the first
// row fixes the columns; a later row that misses a column, names an unknown one or gives one
// twice is refused with an error; values given in another order land in their columns.

#include <periarlequin/io/energy_history.h>

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  /** 1 if @p action throws, 0 otherwise. */
  template <typename Action>
  double
  throws(const Action &action)
  {
    try
      {
        action();
      }
    catch (const std::exception &)
      {
        return 1;
      }
    return 0;
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    PeriArlequin::EnergyHistory history("", MPI_COMM_WORLD);
    history.add_value("a", 1.);
    history.add_value("b", 2.);
    history.end_row();
    history.add_value("b", 4.);
    history.add_value("a", 3.);
    history.end_row();
    check("column b of two rows given in another order, second value",
          history.column("b")[1],
          4.,
          0.);
    check("column a, second value", history.column("a")[1], 3., 0.);

    check("a row without column b refused (1 = yes)",
          throws([&] {
            history.add_value("a", 5.);
            history.end_row();
          }),
          1.,
          0.);
    PeriArlequin::EnergyHistory other("", MPI_COMM_WORLD);
    other.add_value("a", 1.);
    other.end_row();
    check("an unknown column refused (1 = yes)", throws([&] { other.add_value("c", 1.); }), 1., 0.);
    PeriArlequin::EnergyHistory twice("", MPI_COMM_WORLD);
    twice.add_value("a", 1.);
    check("a column given twice in a row refused (1 = yes)",
          throws([&] { twice.add_value("a", 2.); }),
          1.,
          0.);
  });
}
