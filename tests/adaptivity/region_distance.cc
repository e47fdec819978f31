// The distance to a PD region grown cell by cell (hundreds of boxes), through the binned
// search that the blending field uses, against a scan of all boxes written out here (the
// Euclidean distance to each box, the least of them). Regions: FE cells (2.5 mm) scattered
// at random over a grid, joined and coalesced as a growth does (2D: 40 x 40 cells, 30 % of
// them; 3D: 14^3, 15 %), and a region of a few boxes (below the binning threshold). Points:
// random ones over the region's bounding box widened by half its size on every side (inside,
// near and far from the boxes, outside the grid), and the corners of every box and cell
// (on bin and box edges).
// Tolerance: the search takes the least of the same per-box distances as
// Region::distance(), so it must equal it to the bit (0); against the scan written here (its
// own sum of squares and square root), 1e-15 relative (one rounding of the square root).
// The search capped at 5 mm (as a blending weight asks, beyond the band alpha = 1): exact below
// the cap, at least the cap beyond it; no point may be answered otherwise (0).

#include <periarlequin/base/regions.h>

#include <random>

#include "../tests.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

namespace
{
  /**
   * FE cells (2.5 mm) of a grid @p n cells a side, each taken with probability @p fill, joined
   * and coalesced as a growth does: a region of scattered patches, as a zone grown by many
   * cracks is.
   */
  template <int dim>
  Region<dim>
  grown_region(const int n, const double fill, std::mt19937 &random)
  {
    const double                           h = 2.5e-3;
    std::uniform_real_distribution<double> unit(0, 1);
    Region<dim>                            region;
    std::array<int, dim>                   cell{};
    for (unsigned int c = 0; c < std::pow(n, dim); ++c)
      {
        for (unsigned int d = 0, rest = c; d < dim; ++d, rest /= n)
          cell[d] = rest % n;
        if (unit(random) >= fill)
          continue;
        Box<dim> box;
        for (unsigned int d = 0; d < dim; ++d)
          {
            box.lower[d] = cell[d] * h;
            box.upper[d] = (cell[d] + 1) * h;
          }
        region.boxes.push_back(box);
      }
    region.coalesce(1e-9);
    return region;
  }

  template <int dim>
  void
  compare(const std::string &name, const Region<dim> &region, std::mt19937 &random)
  {
    Point<dim> lower = region.boxes[0].lower, upper = region.boxes[0].upper;
    for (const auto &box : region.boxes)
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = std::min(lower[d], box.lower[d]);
          upper[d] = std::max(upper[d], box.upper[d]);
        }
    std::vector<Point<dim>> points;
    for (const auto &box : region.boxes)
      {
        points.push_back(box.lower);
        points.push_back(box.upper);
      }
    std::uniform_real_distribution<double> unit(-0.5, 1.5);
    for (unsigned int k = 0; k < 20000; ++k)
      {
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = lower[d] + unit(random) * (upper[d] - lower[d]);
        points.push_back(p);
      }

    const RegionDistance<dim> search(region);
    double                    differs_from_region = 0, differs_from_scan = 0;
    unsigned int              inside = 0, beyond_cap = 0, capped_wrong = 0;
    // Two cells: the band of a blending field (beyond it alpha = 1).
    const double cap = 5e-3;
    for (const auto &p : points)
      {
        double scan = std::numeric_limits<double>::infinity();
        for (const auto &box : region.boxes)
          scan = std::min(scan, distance_to_box(p, box.lower, box.upper));
        const double found  = search.distance(p);
        differs_from_region = std::max(differs_from_region, std::abs(found - region.distance(p)));
        differs_from_scan =
          std::max(differs_from_scan, std::abs(found - scan) / std::max(scan, 1e-300));
        inside += scan == 0;
        // Below the cap the capped search is exact; at or beyond it, any number >= cap.
        const double capped = search.distance(p, cap);
        beyond_cap += scan >= cap;
        capped_wrong += scan < cap ? capped != found : !(capped >= cap);
      }
    report(name + ": boxes", region.boxes.size());
    report(name + ": points", points.size());
    report(name + ": points inside", inside);
    check(name + ": |search - Region::distance| [m]", differs_from_region, 0, 0);
    check_below(name + ": |search - scan| / scan", differs_from_scan, 1e-15);
    report(name + ": points at 5 mm or more", beyond_cap);
    check(name + ": capped at 5 mm, points answered wrongly", capped_wrong, 0, 0);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    std::mt19937 random(2026);
    compare<2>("2D grown", grown_region<2>(40, 0.3, random), random);
    compare<3>("3D grown", grown_region<3>(14, 0.15, random), random);
    compare<2>("2D few boxes", grown_region<2>(4, 0.4, random), random);
  });
}
