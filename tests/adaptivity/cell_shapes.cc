// The cells of a general mesh as pieces of a PD region (an adaptive zone grown on a Gmsh
// mesh): CellShape::distance() and contains(), and the binned search over cells.
// 1. Cells that are boxes: FE cells (2.5 mm) of a grid taken at random (2D: 40 x 40 cells,
//    30 % of them; 3D: 14^3, 15 %), once as cells and once as boxes. At 20,000 random points
//    (inside, near and far from the cells) and at every cell corner, the distance to the cells
//    through the binned search against Region::distance() (the same minimum of the same
//    terms: 0) and against the distance to the boxes (Box::distance, an independent formula:
//    both round coordinates of order 0.1 m, so 1e-14 m).
// 2. Skewed cells with flat faces (parallelograms, parallelepipeds: x = c + A xi, xi in
//    [0, 1]^dim, A random with singular values within [0.5, 2] mm): inside exactly where
//    A^-1 (x - c) lies in the unit cell (distance 0 within 1e-9 of the unit cell's faces
//    excluded), and outside it against the least distance to the faces sampled on a grid (the
//    sampling misses the nearest point by at most half a sample's diagonal: that bound, per
//    cell).
// 3. Cells with curved faces (each vertex moved by up to 8 % of the cell size; the faces of a
//    hexahedron are then not flat): the image of unit coordinates in [0.1, 0.9]^dim under the
//    multilinear map is inside, the image of coordinates 0.15 to 0.4 outside the unit cell is
//    outside (the split faces lie within 2 % of the cell size of the multilinear ones). Two
//    such cells sharing a face: the points next to the shared face on both sides are inside
//    their union (the two cells split the shared face alike: no gap between them).

#include <periarlequin/base/regions.h>

#include <random>

#include "../tests.h"

using namespace PeriArlequinTests;
using namespace PeriArlequin;

namespace
{
  constexpr double cell_size = 2.5e-3;

  /** The multilinear map of @p vertices (deal.II's order) at unit coordinates @p xi. */
  template <int dim>
  Point<dim>
  map_from_unit(const CellShape<dim> &cell, const Point<dim> &xi)
  {
    Point<dim> x;
    for (unsigned int v = 0; v < cell.vertices.size(); ++v)
      {
        double weight = 1;
        for (unsigned int d = 0; d < dim; ++d)
          weight *= (v >> d) & 1 ? xi[d] : 1. - xi[d];
        x += weight * cell.vertices[v];
      }
    return x;
  }

  /** A cell of @p vertices x = @p corner + A xi at the corners xi of the unit cell. */
  template <int dim>
  CellShape<dim>
  affine_cell(const Point<dim> &corner, const Tensor<2, dim> &A)
  {
    CellShape<dim> cell;
    for (unsigned int v = 0; v < cell.vertices.size(); ++v)
      {
        Tensor<1, dim> xi;
        for (unsigned int d = 0; d < dim; ++d)
          xi[d] = (v >> d) & 1;
        cell.vertices[v] = corner + A * xi;
      }
    return cell;
  }

  template <int dim>
  void
  boxes_as_cells(const int n, const double fill, std::mt19937 &random)
  {
    std::uniform_real_distribution<double> unit(0, 1);
    Region<dim>                            as_boxes, as_cells;
    for (unsigned int c = 0; c < std::pow(n, dim); ++c)
      {
        if (unit(random) >= fill)
          continue;
        Tensor<2, dim> A;
        Point<dim>     corner;
        for (unsigned int d = 0, rest = c; d < dim; ++d, rest /= n)
          {
            corner[d] = (rest % n) * cell_size;
            A[d][d]   = cell_size;
          }
        as_cells.cells.push_back(affine_cell(corner, A));
        as_boxes.boxes.push_back(as_cells.cells.back().bounding_box());
      }
    std::vector<Point<dim>> points;
    for (const auto &cell : as_cells.cells)
      points.insert(points.end(), cell.vertices.begin(), cell.vertices.end());
    std::uniform_real_distribution<double> around(-0.5, 1.5);
    for (unsigned int k = 0; k < 20000; ++k)
      {
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = around(random) * n * cell_size;
        points.push_back(p);
      }
    const RegionDistance<dim> search(as_cells);
    double                    differs_from_region = 0, differs_from_boxes = 0;
    unsigned int              inside = 0;
    for (const auto &p : points)
      {
        const double found  = search.distance(p);
        differs_from_region = std::max(differs_from_region, std::abs(found - as_cells.distance(p)));
        differs_from_boxes  = std::max(differs_from_boxes, std::abs(found - as_boxes.distance(p)));
        inside += found == 0;
      }
    const std::string name = std::to_string(dim) + "D cells that are boxes";
    report(name + ": cells", as_cells.cells.size());
    report(name + ": points inside", inside);
    check(name + ": |search - Region::distance| [m]", differs_from_region, 0, 0);
    check_below(name + ": |distance to cells - distance to boxes| [m]", differs_from_boxes, 1e-14);
  }

  /** Least distance from @p p to the faces of the unit cell under x = c + A xi, sampled. */
  template <int dim>
  double
  sampled_distance(const Point<dim>     &p,
                   const Point<dim>     &corner,
                   const Tensor<2, dim> &A,
                   const unsigned int    n_samples)
  {
    double nearest = std::numeric_limits<double>::infinity();
    for (unsigned int axis = 0; axis < dim; ++axis)
      for (const double side : {0., 1.})
        for (unsigned int k = 0; k < std::pow(n_samples + 1, dim - 1); ++k)
          {
            Tensor<1, dim> xi;
            for (unsigned int d = 0, rest = k; d < dim; ++d)
              if (d == axis)
                xi[d] = side;
              else
                {
                  xi[d] = double(rest % (n_samples + 1)) / n_samples;
                  rest /= n_samples + 1;
                }
            nearest = std::min(nearest, p.distance(corner + A * xi));
          }
    return nearest;
  }

  template <int dim>
  void
  skewed_cells(const unsigned int n_cells, const unsigned int n_samples, std::mt19937 &random)
  {
    std::uniform_real_distribution<double> unit(0, 1), around(-0.5, 1.5);
    unsigned int n_inside = 0, n_outside = 0, wrong_inside = 0, wrong_outside = 0;
    double       above_sampled = 0, below_sampled = 0;
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        Tensor<2, dim> A;
        do
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              A[i][j] = (i == j ? 1. : 0.) * cell_size + 0.5 * cell_size * (2 * unit(random) - 1);
        while (!(determinant(A) > 0.2 * std::pow(cell_size, dim)));
        Point<dim> corner;
        for (unsigned int d = 0; d < dim; ++d)
          corner[d] = 0.1 * unit(random);
        const CellShape<dim> cell    = affine_cell(corner, A);
        const Tensor<2, dim> inverse = invert(A);
        // The sampling misses the nearest face point by at most half a sample's longer
        // diagonal, which is at most half the sum of its sides.
        double largest_edge = 0;
        for (unsigned int d = 0; d < dim; ++d)
          {
            Tensor<1, dim> edge;
            for (unsigned int i = 0; i < dim; ++i)
              edge[i] = A[i][d];
            largest_edge = std::max(largest_edge, edge.norm());
          }
        const double sampling = 0.5 * (dim - 1) * largest_edge / n_samples;
        for (unsigned int k = 0; k < 40; ++k)
          {
            Tensor<1, dim> xi;
            for (unsigned int d = 0; d < dim; ++d)
              xi[d] = around(random);
            const Point<dim>     p    = corner + A * xi;
            const Tensor<1, dim> back = inverse * (p - corner);
            bool                 in = true, out = false;
            for (unsigned int d = 0; d < dim; ++d)
              {
                in  = in && back[d] > 1e-9 && back[d] < 1. - 1e-9;
                out = out || back[d] < -1e-9 || back[d] > 1. + 1e-9;
              }
            const double distance = cell.distance(p);
            if (in)
              {
                ++n_inside;
                wrong_inside += distance != 0;
              }
            else if (out)
              {
                ++n_outside;
                const double reference = sampled_distance(p, corner, A, n_samples);
                wrong_outside += distance == 0;
                above_sampled = std::max(above_sampled, distance - reference);
                below_sampled = std::max(below_sampled, (reference - distance) / sampling);
              }
          }
      }
    const std::string name = std::to_string(dim) + "D skewed cells";
    report(name + ": points inside", n_inside);
    report(name + ": points outside", n_outside);
    check(name + ": inside points at a non-zero distance", wrong_inside, 0, 0);
    check(name + ": outside points at distance 0", wrong_outside, 0, 0);
    // The sampled points lie on the faces: the distance is at most the sampled one (up to
    // the rounding of coordinates of order 0.1 m), and at least it less the sampling bound.
    check_below(name + ": distance - sampled distance, largest [m]", above_sampled, 1e-14);
    check_below(name + ": (sampled distance - distance) / sampling bound, largest",
                below_sampled,
                1.);
  }

  template <int dim>
  void
  curved_cells(const unsigned int n_cells, std::mt19937 &random)
  {
    std::uniform_real_distribution<double> unit(0, 1);
    const auto                             perturbed = [&](const Point<dim> &corner) {
      Tensor<2, dim> A;
      for (unsigned int d = 0; d < dim; ++d)
        A[d][d] = cell_size;
      CellShape<dim> cell = affine_cell(corner, A);
      for (auto &vertex : cell.vertices)
        for (unsigned int d = 0; d < dim; ++d)
          vertex[d] += 0.08 * cell_size * (2 * unit(random) - 1);
      return cell;
    };
    unsigned int wrong_inside = 0, wrong_outside = 0, gaps = 0, n_points = 0;
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        // Two cells side by side along x, sharing the face of the first's vertices 1, 3, ...
        CellShape<dim> left = perturbed(Point<dim>()), right;
        Point<dim>     shifted;
        shifted[0] = cell_size;
        right      = perturbed(shifted);
        for (unsigned int v = 0; v < left.vertices.size(); v += 2)
          right.vertices[v] = left.vertices[v + 1];
        Region<dim> both;
        both.cells = {left, right};
        for (unsigned int k = 0; k < 100; ++k)
          {
            Point<dim> xi_inside, xi_outside, xi_face;
            for (unsigned int d = 0; d < dim; ++d)
              {
                xi_inside[d]  = 0.1 + 0.8 * unit(random);
                xi_outside[d] = unit(random);
                xi_face[d]    = 0.1 + 0.8 * unit(random);
              }
            const unsigned int axis = k % dim;
            xi_outside[axis] = k % 2 ? -0.15 - 0.25 * unit(random) : 1.15 + 0.25 * unit(random);
            xi_face[0]       = 0.9 + 0.2 * unit(random);
            wrong_inside += left.distance(map_from_unit(left, xi_inside)) != 0;
            wrong_outside += !(left.distance(map_from_unit(left, xi_outside)) > 0);
            Point<dim> xi_right = xi_face;
            xi_right[0] -= 1.;
            const Point<dim> near_face =
              xi_face[0] < 1. ? map_from_unit(left, xi_face) : map_from_unit(right, xi_right);
            gaps += both.distance(near_face) != 0;
            ++n_points;
          }
      }
    const std::string name = std::to_string(dim) + "D cells with curved faces";
    report(name + ": points of each kind", n_points);
    check(name + ": inner points outside", wrong_inside, 0, 0);
    check(name + ": outer points inside", wrong_outside, 0, 0);
    check(name + ": points next to the shared face outside both", gaps, 0, 0);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    std::mt19937 random(2026);
    boxes_as_cells<2>(40, 0.3, random);
    boxes_as_cells<3>(14, 0.15, random);
    skewed_cells<2>(200, 4000, random);
    skewed_cells<3>(25, 60, random);
    curved_cells<2>(100, random);
    curved_cells<3>(100, random);
  });
}
