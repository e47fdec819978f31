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

  namespace
  {
    /**
     * Call @p visit(simplex) for each simplex of the cell's surface: its edges in 2D, in 3D
     * the triangles that join each face's centre to the face's edges.
     */
    template <int dim, typename Visitor>
    void
    for_each_surface_simplex(const CellShape<dim> &cell, const Visitor &visit)
    {
      for (unsigned int f = 0; f < GeometryInfo<dim>::faces_per_cell; ++f)
        {
          std::array<Point<dim>, GeometryInfo<dim>::vertices_per_face> v;
          for (unsigned int i = 0; i < v.size(); ++i)
            v[i] = cell.vertices[GeometryInfo<dim>::face_to_cell_vertices(f, i)];
          if constexpr (dim == 2)
            visit(std::array<Point<dim>, dim>{{v[0], v[1]}});
          else
            {
              Point<dim> centre;
              for (const Point<dim> &vertex : v)
                centre += 0.25 * vertex;
              // The face's vertices in deal.II's order, around the face.
              constexpr std::array<unsigned int, 4> around = {{0, 1, 3, 2}};
              for (unsigned int k = 0; k < 4; ++k)
                visit(std::array<Point<dim>, dim>{{centre, v[around[k]], v[around[(k + 1) % 4]]}});
            }
        }
    }

    /** Distance from @p p to a segment (2D) or a triangle (3D). */
    template <int dim>
    double
    distance_to_simplex(const Point<dim> &p, const std::array<Point<dim>, dim> &s)
    {
      if constexpr (dim == 2)
        {
          const Tensor<1, dim> edge = s[1] - s[0];
          const double         t    = std::clamp(((p - s[0]) * edge) / edge.norm_square(), 0., 1.);
          return p.distance(s[0] + t * edge);
        }
      else
        {
          // The nearest point by the region of the triangle's plane that holds p's projection:
          // a vertex, an edge or the inside (barycentric coordinates from dot products).
          const Tensor<1, dim> ab = s[1] - s[0], ac = s[2] - s[0];
          const Tensor<1, dim> ap = p - s[0], bp = p - s[1], cp = p - s[2];
          const double         d1 = ab * ap, d2 = ac * ap, d3 = ab * bp, d4 = ac * bp;
          const double         d5 = ab * cp, d6 = ac * cp;
          if (d1 <= 0 && d2 <= 0)
            return p.distance(s[0]);
          if (d3 >= 0 && d4 <= d3)
            return p.distance(s[1]);
          if (d6 >= 0 && d5 <= d6)
            return p.distance(s[2]);
          const double vc = d1 * d4 - d3 * d2;
          if (vc <= 0 && d1 >= 0 && d3 <= 0)
            return p.distance(s[0] + d1 / (d1 - d3) * ab);
          const double vb = d5 * d2 - d1 * d6;
          if (vb <= 0 && d2 >= 0 && d6 <= 0)
            return p.distance(s[0] + d2 / (d2 - d6) * ac);
          const double va = d3 * d6 - d5 * d4;
          if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
            return p.distance(s[1] + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (s[2] - s[1]));
          const double sum = va + vb + vc;
          return p.distance(s[0] + (vb / sum) * ab + (vc / sum) * ac);
        }
    }
  } // namespace

  template <int dim>
  double
  CellShape<dim>::distance(const Point<dim> &p) const
  {
    Point<dim> centre;
    for (const Point<dim> &vertex : vertices)
      centre += (1. / vertices.size()) * vertex;
    // Inside when p lies in a simplex of the centre and a surface simplex; else the nearest
    // surface simplex.
    bool   inside  = false;
    double nearest = std::numeric_limits<double>::infinity();
    for_each_surface_simplex(*this, [&](const std::array<Point<dim>, dim> &s) {
      if (inside)
        return;
      Tensor<2, dim> edges;
      for (unsigned int k = 0; k < dim; ++k)
        for (unsigned int d = 0; d < dim; ++d)
          edges[d][k] = s[k][d] - centre[d];
      const Tensor<1, dim> coordinates = invert(edges) * (p - centre);
      double               sum         = 0;
      bool                 in          = true;
      for (unsigned int k = 0; k < dim; ++k)
        {
          in = in && coordinates[k] >= 0;
          sum += coordinates[k];
        }
      inside  = in && sum <= 1;
      nearest = std::min(nearest, distance_to_simplex<dim>(p, s));
    });
    return inside ? 0. : nearest;
  }

  template <int dim>
  bool
  CellShape<dim>::contains(const Point<dim> &p, const double tolerance) const
  {
    return bounding_box().contains(p, tolerance) && distance(p) <= tolerance;
  }

  template <int dim>
  Box<dim>
  CellShape<dim>::bounding_box() const
  {
    Box<dim> box{vertices[0], vertices[0]};
    for (const Point<dim> &vertex : vertices)
      for (unsigned int d = 0; d < dim; ++d)
        {
          box.lower[d] = std::min(box.lower[d], vertex[d]);
          box.upper[d] = std::max(box.upper[d], vertex[d]);
        }
    return box;
  }

  template <int dim>
  std::size_t
  Region<dim>::n_pieces() const
  {
    return boxes.size() + cells.size();
  }

  template <int dim>
  std::vector<Box<dim>>
  Region<dim>::piece_bounds() const
  {
    std::vector<Box<dim>> bounds = boxes;
    for (const auto &cell : cells)
      bounds.push_back(cell.bounding_box());
    return bounds;
  }

  template <int dim>
  double
  Region<dim>::piece_distance(const std::size_t k, const Point<dim> &p) const
  {
    return k < boxes.size() ? boxes[k].distance(p) : cells[k - boxes.size()].distance(p);
  }

  template <int dim>
  void
  Region<dim>::add(const Region<dim> &other)
  {
    boxes.insert(boxes.end(), other.boxes.begin(), other.boxes.end());
    cells.insert(cells.end(), other.cells.begin(), other.cells.end());
  }

  template <int dim>
  double
  Region<dim>::distance(const Point<dim> &p) const
  {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < n_pieces() && nearest > 0; ++k)
      nearest = std::min(nearest, piece_distance(k, p));
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
    , n_pieces(source.n_pieces())
  {
    // A few pieces are scanned; so is a region without extent.
    if (n_pieces <= 8)
      return;
    const std::vector<Box<dim>> bounds = region.piece_bounds();
    Box<dim>                    hull   = bounds[0];
    for (const auto &box : bounds)
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
    // About four bins a piece (a flat hull: along its longest side), at most sixteen.
    const double n_bounds = bounds.size();
    bin_width = std::max(std::pow(volume / (4. * n_bounds), 1. / dim), longest / (4. * n_bounds));
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
        if (n_all > 16 * bounds.size())
          bin_width *= 2;
      }
    while (n_all > 16 * bounds.size());
    origin = hull.lower;

    // Each piece is listed in the bins its bounds touch, widened by a millionth of a bin on
    // each side: rounding at a bin's edge cannot hide a piece from the search.
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
    for (const auto &box : bounds)
      {
        const auto [lower, upper] = bin_range(box);
        for_each_bin<dim>(lower, upper, [&](const auto &bin) { ++bin_begin[index(bin) + 1]; });
      }
    for (std::size_t b = 0; b < n_all; ++b)
      bin_begin[b + 1] += bin_begin[b];
    bin_pieces.resize(bin_begin.back());
    std::vector<unsigned int> filled(bin_begin.begin(), bin_begin.end() - 1);
    for (unsigned int k = 0; k < bounds.size(); ++k)
      {
        const auto [lower, upper] = bin_range(bounds[k]);
        for_each_bin<dim>(lower, upper, [&](const auto &bin) {
          bin_pieces[filled[index(bin)]++] = k;
        });
      }
  }

  template <int dim>
  double
  RegionDistance<dim>::distance(const Point<dim> &p, const double cap) const
  {
    if (bin_width == 0)
      return region.distance(p);
    std::array<int, dim> centre;
    int                  last_ring = 0;
    // The gap to the grid, which holds every piece, bounds the distance from below.
    double gap_squared = 0;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const int    last    = static_cast<int>(n_bins[d]) - 1;
        const double from    = p[d] - origin[d];
        centre[d]            = std::clamp(static_cast<int>(std::floor(from / bin_width)), 0, last);
        last_ring            = std::max({last_ring, centre[d], last - centre[d]});
        const double outside = std::max({-from, from - n_bins[d] * bin_width, 0.});
        gap_squared += outside * outside;
      }
    if (gap_squared >= cap * cap)
      return std::sqrt(gap_squared);
    // After ring r (the bins r bins from the point's bin, the nearest bin of the grid if the
    // point lies outside it), every piece not met is at least r bin widths away. A point far
    // from every piece would visit more bins than there are pieces: it scans them instead.
    double      nearest = std::numeric_limits<double>::infinity();
    std::size_t visited = 0;
    const auto  visit   = [&](const std::array<int, dim> &bin) {
      std::size_t i = 0;
      for (unsigned int d = dim; d-- > 0;)
        i = i * n_bins[d] + bin[d];
      // Inside a piece nothing is nearer (most particles of a zone lie inside one).
      for (unsigned int b = bin_begin[i]; b < bin_begin[i + 1] && nearest > 0; ++b)
        nearest = std::min(nearest, region.piece_distance(bin_pieces[b], p));
      ++visited;
    };
    for (int r = 0; r <= last_ring; ++r)
      {
        if (visited > n_pieces)
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
        // Every piece not met is at least r bin widths away: at or beyond the cap, so is the
        // answer (nearest, if below r bin widths, was returned above).
        if (nearest <= r * bin_width || r * bin_width >= cap)
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
    for (const auto &cell : cells)
      if (cell.contains(p, tolerance))
        return true;
    return false;
  }

  template <int dim>
  bool
  Region<dim>::empty() const
  {
    return boxes.empty() && cells.empty();
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
  template struct CellShape<2>;
  template struct CellShape<3>;
  template struct Region<2>;
  template struct Region<3>;
  template class RegionDistance<2>;
  template class RegionDistance<3>;
  template struct PreCrack<2>;
  template struct PreCrack<3>;
} // namespace PeriArlequin
