// Centre-line samples on 2 ranks: each rank holds part of the FE nodes and PD particles on
// the line, rank 0 gathers and sorts them (by zone, then position). The strip case with the
// smooth pulse crossing the overlaps, sampled along y = 0 every 100 steps, on 2 ranks and on
// 1 rank (rank 0 alone): the files must have the same rows in the same order, positions
// equal and displacements within 1e-10 of the largest |u| on the line (sums in another order
// differ by round-off).

#include "coupled_cases.h"

using namespace PeriArlequinTests;

namespace
{
  std::vector<std::vector<std::string>>
  read_csv(const std::string &name)
  {
    std::ifstream                         file(name);
    std::vector<std::vector<std::string>> rows;
    for (std::string line; std::getline(file, line);)
      {
        std::vector<std::string> fields;
        std::stringstream        stream(line);
        for (std::string field; std::getline(stream, field, ',');)
          fields.push_back(field);
        rows.push_back(fields);
      }
    AssertThrow(rows.size() > 1, ExcMessage("no samples in " + name));
    return rows;
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    require_several_ranks();
    const auto text = [&](const std::string &directory) {
      return strip_case("weak",
                        "energy",
                        "diagonal",
                        true,
                        false,
                        smooth_pulse,
                        "0; 0",
                        2e-7,
                        6e-5,
                        1) +
             "subsection Output\n  set Directory = " + directory +
             "\n  set Output interval = 100\n  set Sample line = -1.2, 0 : 1.2, 0\nend\n";
    };
    make_simulator<2>(text("samples_2_ranks"), MPI_COMM_WORLD)->run();
    if (!is_root())
      return;
    make_simulator<2>(text("samples_1_rank"), MPI_COMM_SELF)->run();

    double       difference = 0, largest = 0;
    unsigned int n_rows = 0;
    for (const std::string step : {"000000", "000100", "000200", "000300"})
      {
        const auto parallel = read_csv("samples_2_ranks/solution_line_" + step + ".csv");
        const auto serial   = read_csv("samples_1_rank/solution_line_" + step + ".csv");
        AssertThrow(parallel.size() == serial.size(),
                    ExcMessage("different numbers of samples at step " + step));
        for (unsigned int r = 1; r < serial.size(); ++r)
          {
            AssertThrow(parallel[r][0] == serial[r][0] && parallel[r][1] == serial[r][1] &&
                          parallel[r][2] == serial[r][2],
                        ExcMessage("row " + std::to_string(r) + " of step " + step +
                                   " is another point on 2 ranks"));
            for (unsigned int c = 3; c < 5; ++c)
              {
                largest = std::max(largest, std::abs(std::stod(serial[r][c])));
                difference =
                  std::max(difference,
                           std::abs(std::stod(parallel[r][c]) - std::stod(serial[r][c])));
              }
          }
        n_rows += serial.size() - 1;
      }
    report("samples compared", n_rows);
    check_below("line samples, 2 ranks vs 1 rank: max |u difference| / max |u|",
                difference / largest,
                1e-10);
  });
}
