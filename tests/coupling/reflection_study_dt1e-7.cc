// The paper's section 6.1 reflection study at half resolution, dt = 1e-7 s: weak coupling with
// fine-scale damping sends back at least 10 times less energy into the pure PD zone than the
// bad coupling; strict coupling sits between. Bounds and why: reflection_study.h.

#include "reflection_study.h"

int
main(int argc, char **argv)
{
  return PeriArlequinTests::run_test(argc, argv, [] {
    PeriArlequinTests::reflection_study(1e-7, true);
  });
}
