#include <periarlequin/base/parameters.h>
#include <periarlequin/base/regions.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace PeriArlequin
{
  namespace
  {
    /** Split "a, b : c, d" into points of @p dim coordinates each; @p n_points 0: any number. */
    template <int dim>
    std::vector<Point<dim>>
    parse_points(const std::string &text,
                 const unsigned int n_points,
                 const std::string &parameter,
                 const std::string &what)
    {
      const auto              parts = Utilities::split_string_list(text, ':');
      std::vector<Point<dim>> points;
      try
        {
          for (const std::string &part : parts)
            {
              const auto coordinates =
                Utilities::string_to_double(Utilities::split_string_list(part, ','));
              if (coordinates.size() != dim)
                throw std::invalid_argument("size");
              Point<dim> p;
              for (unsigned int d = 0; d < dim; ++d)
                p[d] = coordinates[d];
              points.push_back(p);
            }
        }
      catch (const std::exception &)
        {
          points.clear();
        }
      if (n_points == 0 ? points.empty() : points.size() != n_points)
        throw_invalid_parameter(parameter,
                                text,
                                what + ": " +
                                  (n_points == 0 ? "one or more" : std::to_string(n_points)) +
                                  " points of " + std::to_string(dim) +
                                  " coordinates separated by ':'");
      return points;
    }
  } // namespace

  template <int dim>
  bool
  Box<dim>::contains(const Point<dim> &p, const double tolerance) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      if (p[d] < lower[d] - tolerance || p[d] > upper[d] + tolerance)
        return false;
    return true;
  }

  template <int dim>
  std::pair<Point<dim>, Point<dim>>
  parse_segment(const std::string &text, const std::string &parameter)
  {
    const auto points = parse_points<dim>(text, 2, parameter, "a segment");
    return {points[0], points[1]};
  }

  template <int dim>
  std::vector<Point<dim>>
  parse_point_list(const std::string &text, const std::string &parameter)
  {
    return parse_points<dim>(text, 0, parameter, "a list of points");
  }

  template <int dim>
  double
  Box<dim>::distance(const Point<dim> &p) const
  {
    double sum = 0;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double outside = std::max({lower[d] - p[d], p[d] - upper[d], 0.});
        sum += outside * outside;
      }
    return std::sqrt(sum);
  }

  template <int dim>
  Tensor<1, dim>
  Box<dim>::gap(const Box<dim> &other) const
  {
    Tensor<1, dim> g;
    for (unsigned int d = 0; d < dim; ++d)
      g[d] = std::max({other.lower[d] - upper[d], lower[d] - other.upper[d], 0.});
    return g;
  }

  template <int dim>
  double
  Region<dim>::distance(const Point<dim> &p) const
  {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto &box : boxes)
      {
        nearest = std::min(nearest, box.distance(p));
        if (nearest == 0)
          break;
      }
    return nearest;
  }

  namespace
  {
    /** Call @p visit(bin) for every bin of the grid range [@p lower, @p upper] (inclusive). */
    template <int dim, typename Visitor>
    void
    for_each_bin(const std::array<int, dim> &lower,
                 const std::array<int, dim> &upper,
                 const Visitor              &visit)
    {
      std::array<int, dim> bin = lower;
      while (true)
        {
          visit(bin);
          unsigned int d = 0;
          for (; d < dim; ++d)
            {
              if (++bin[d] <= upper[d])
                break;
              bin[d] = lower[d];
            }
          if (d == dim)
            return;
        }
    }
  } // namespace

  template <int dim>
  RegionDistance<dim>::RegionDistance(const Region<dim> &source)
    : region(source)
  {
    const std::vector<Box<dim>> &boxes = region.boxes;
    // A few boxes are scanned; so is a region without extent.
    if (boxes.size() <= 8)
      return;
    Box<dim> hull = boxes[0];
    for (const auto &box : boxes)
      for (unsigned int d = 0; d < dim; ++d)
        {
          hull.lower[d] = std::min(hull.lower[d], box.lower[d]);
          hull.upper[d] = std::max(hull.upper[d], box.upper[d]);
        }
    double volume = 1, longest = 0;
    for (unsigned int d = 0; d < dim; ++d)
      {
        volume *= hull.upper[d] - hull.lower[d];
        longest = std::max(longest, hull.upper[d] - hull.lower[d]);
      }
    if (!(longest > 0))
      return;
    // About four bins a box (a flat hull: along its longest side), at most sixteen.
    const double n_boxes = boxes.size();
    bin_width = std::max(std::pow(volume / (4. * n_boxes), 1. / dim), longest / (4. * n_boxes));
    std::size_t n_all = 0;
    do
      {
        n_all = 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            n_bins[d] =
              static_cast<unsigned int>(std::floor((hull.upper[d] - hull.lower[d]) / bin_width)) +
              1;
            n_all *= n_bins[d];
          }
        if (n_all > 16 * boxes.size())
          bin_width *= 2;
      }
    while (n_all > 16 * boxes.size());
    origin = hull.lower;

    // Each box is listed in the bins it touches, widened by a millionth of a bin on each
    // side: rounding at a bin's edge cannot hide a box from the search.
    const auto bin_range = [&](const Box<dim> &box) {
      std::array<int, dim> lower, upper;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const int last = static_cast<int>(n_bins[d]) - 1;
          lower[d] =
            std::clamp(static_cast<int>(std::floor((box.lower[d] - origin[d]) / bin_width - 1e-6)),
                       0,
                       last);
          upper[d] =
            std::clamp(static_cast<int>(std::floor((box.upper[d] - origin[d]) / bin_width + 1e-6)),
                       0,
                       last);
        }
      return std::make_pair(lower, upper);
    };
    const auto index = [&](const std::array<int, dim> &bin) {
      std::size_t i = 0;
      for (unsigned int d = dim; d-- > 0;)
        i = i * n_bins[d] + bin[d];
      return i;
    };
    bin_begin.assign(n_all + 1, 0);
    for (const auto &box : boxes)
      {
        const auto [lower, upper] = bin_range(box);
        for_each_bin<dim>(lower, upper, [&](const auto &bin) { ++bin_begin[index(bin) + 1]; });
      }
    for (std::size_t b = 0; b < n_all; ++b)
      bin_begin[b + 1] += bin_begin[b];
    bin_boxes.resize(bin_begin.back());
    std::vector<unsigned int> filled(bin_begin.begin(), bin_begin.end() - 1);
    for (unsigned int k = 0; k < boxes.size(); ++k)
      {
        const auto [lower, upper] = bin_range(boxes[k]);
        for_each_bin<dim>(lower, upper, [&](const auto &bin) {
          bin_boxes[filled[index(bin)]++] = k;
        });
      }
  }

  template <int dim>
  double
  RegionDistance<dim>::distance(const Point<dim> &p) const
  {
    const std::vector<Box<dim>> &boxes = region.boxes;
    if (bin_width == 0)
      return region.distance(p);
    std::array<int, dim> centre;
    int                  last_ring = 0;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const int last = static_cast<int>(n_bins[d]) - 1;
        centre[d] =
          std::clamp(static_cast<int>(std::floor((p[d] - origin[d]) / bin_width)), 0, last);
        last_ring = std::max({last_ring, centre[d], last - centre[d]});
      }
    // After ring r (the bins r bins from the point's bin, the nearest bin of the grid if the
    // point lies outside it), every box not met is at least r bin widths away. A point far
    // from every box would visit more bins than there are boxes: it scans them instead.
    double      nearest = std::numeric_limits<double>::infinity();
    std::size_t visited = 0;
    const auto  visit   = [&](const std::array<int, dim> &bin) {
      std::size_t i = 0;
      for (unsigned int d = dim; d-- > 0;)
        i = i * n_bins[d] + bin[d];
      for (unsigned int b = bin_begin[i]; b < bin_begin[i + 1]; ++b)
        nearest = std::min(nearest, boxes[bin_boxes[b]].distance(p));
      ++visited;
    };
    for (int r = 0; r <= last_ring; ++r)
      {
        if (visited > boxes.size())
          return std::min(nearest, region.distance(p));
        // The ring's faces: bin[d] = centre[d] -+ r, the axes before d strictly inside the
        // ring (their faces are done), the axes after d across it.
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int end = 0; end < 2; ++end)
            {
              const int side = end == 0 ? -r : r;
              if (r == 0 && (d > 0 || end > 0))
                continue;
              std::array<int, dim> lower, upper;
              bool                 empty = false;
              for (unsigned int e = 0; e < dim; ++e)
                {
                  const int inset = e < d ? 1 : 0;
                  lower[e]        = std::max(centre[e] - r + inset, 0);
                  upper[e] = std::min(centre[e] + r - inset, static_cast<int>(n_bins[e]) - 1);
                  if (e == d)
                    lower[e] = upper[e] = centre[e] + side;
                  empty = empty || lower[e] > upper[e] || lower[e] < 0 ||
                          upper[e] >= static_cast<int>(n_bins[e]);
                }
              if (!empty)
                for_each_bin<dim>(lower, upper, visit);
            }
        if (nearest <= r * bin_width)
          return nearest;
      }
    return nearest;
  }

  template <int dim>
  bool
  Region<dim>::contains(const Point<dim> &p, const double tolerance) const
  {
    for (const auto &box : boxes)
      if (box.contains(p, tolerance))
        return true;
    return false;
  }

  template <int dim>
  bool
  Region<dim>::empty() const
  {
    return boxes.empty();
  }

  template <int dim>
  void
  Region<dim>::coalesce(const double tolerance)
  {
    // Along each axis: order the boxes by their extent across it, then by their start along
    // it; neighbours in that order with equal cross extents that touch along the axis merge.
    for (unsigned int axis = 0; axis < dim; ++axis)
      {
        const auto cross_less = [&](const Box<dim> &a, const Box<dim> &b) {
          for (unsigned int d = 0; d < dim; ++d)
            if (d != axis)
              {
                if (std::abs(a.lower[d] - b.lower[d]) > tolerance)
                  return a.lower[d] < b.lower[d];
                if (std::abs(a.upper[d] - b.upper[d]) > tolerance)
                  return a.upper[d] < b.upper[d];
              }
          return false;
        };
        std::sort(boxes.begin(), boxes.end(), [&](const Box<dim> &a, const Box<dim> &b) {
          if (cross_less(a, b))
            return true;
          if (cross_less(b, a))
            return false;
          return a.lower[axis] < b.lower[axis];
        });
        std::vector<Box<dim>> merged;
        for (const Box<dim> &box : boxes)
          if (!merged.empty() && !cross_less(merged.back(), box) &&
              !cross_less(box, merged.back()) &&
              box.lower[axis] <= merged.back().upper[axis] + tolerance)
            merged.back().upper[axis] = std::max(merged.back().upper[axis], box.upper[axis]);
          else
            merged.push_back(box);
        boxes = std::move(merged);
      }
  }

  template <int dim>
  Region<dim>
  Region<dim>::parse(const std::string &text, const std::string &parameter)
  {
    Region<dim> region;
    for (const std::string &box_text : Utilities::split_string_list(text, ';'))
      {
        if (box_text.empty())
          continue;
        const auto corners =
          parse_points<dim>(box_text,
                            2,
                            parameter,
                            "boxes 'lower corner : upper corner' separated by ';'");
        for (unsigned int d = 0; d < dim; ++d)
          if (!(corners[1][d] > corners[0][d]))
            throw_invalid_parameter(parameter,
                                    text,
                                    "boxes whose upper corner lies above the lower corner in "
                                    "every coordinate");
        region.boxes.push_back({corners[0], corners[1]});
      }
    return region;
  }

  template <int dim>
  bool
  PreCrack<dim>::cuts(const Point<dim> &p, const Point<dim> &q) const
  {
    const Tensor<1, dim> d = q - p;
    if (dim == 2)
      {
        // Solve p + s d = origin + r a for s, r in [0, 1].
        const double denominator = d[0] * edge_a[1] - d[1] * edge_a[0];
        if (std::abs(denominator) < 1e-14 * d.norm() * edge_a.norm())
          return false; // parallel
        const Tensor<1, dim> w = origin - p;
        const double         s = (w[0] * edge_a[1] - w[1] * edge_a[0]) / denominator;
        const double         r = (w[0] * d[1] - w[1] * d[0]) / denominator;
        return s >= 0 && s <= 1 && r >= 0 && r <= 1;
      }
    else
      {
        // Intersect the segment with the plane of the parallelogram, then test the
        // parallelogram coordinates of the intersection point.
        Tensor<1, dim> normal;
        if constexpr (dim == 3)
          normal = cross_product_3d(edge_a, edge_b);
        const double denominator = normal * d;
        if (std::abs(denominator) < 1e-14 * normal.norm() * d.norm())
          return false;
        const double s = (normal * (origin - p)) / denominator;
        if (s < 0 || s > 1)
          return false;
        const Tensor<1, dim> w  = p + s * d - origin;
        const double         aa = edge_a * edge_a, bb = edge_b * edge_b, ab = edge_a * edge_b;
        const double         det = aa * bb - ab * ab;
        const double         r   = (bb * (w * edge_a) - ab * (w * edge_b)) / det;
        const double         t   = (aa * (w * edge_b) - ab * (w * edge_a)) / det;
        return r >= 0 && r <= 1 && t >= 0 && t <= 1;
      }
  }

  template <int dim>
  std::vector<PreCrack<dim>>
  PreCrack<dim>::parse_list(const std::string &text, const std::string &parameter)
  {
    std::vector<PreCrack<dim>> cracks;
    for (const std::string &crack_text : Utilities::split_string_list(text, ';'))
      {
        if (crack_text.empty())
          continue;
        const auto points = parse_points<dim>(
          crack_text,
          dim == 2 ? 2 : 3,
          parameter,
          dim == 2 ? "segments 'x0, y0 : x1, y1' separated by ';'" :
                     "parallelograms 'corner : edge vector a : edge vector b' separated by ';'");
        PreCrack<dim> crack;
        crack.origin = points[0];
        if (dim == 2)
          crack.edge_a = points[1] - points[0];
        else
          {
            crack.edge_a = points[1];
            crack.edge_b = points[2];
          }
        cracks.push_back(crack);
      }
    return cracks;
  }

  template std::pair<Point<2>, Point<2>>
  parse_segment<2>(const std::string &, const std::string &);
  template std::pair<Point<3>, Point<3>>
  parse_segment<3>(const std::string &, const std::string &);
  template std::vector<Point<2>>
  parse_point_list<2>(const std::string &, const std::string &);
  template std::vector<Point<3>>
  parse_point_list<3>(const std::string &, const std::string &);
  template struct Box<2>;
  template struct Box<3>;
  template struct Region<2>;
  template struct Region<3>;
  template class RegionDistance<2>;
  template class RegionDistance<3>;
  template struct PreCrack<2>;
  template struct PreCrack<3>;
} // namespace PeriArlequin
