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
  template struct PreCrack<2>;
  template struct PreCrack<3>;
} // namespace PeriArlequin
