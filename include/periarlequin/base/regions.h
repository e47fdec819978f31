#ifndef periarlequin_base_regions_h
#define periarlequin_base_regions_h

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/point.h>

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /** An axis-aligned box [lower, upper]. */
  template <int dim>
  struct Box
  {
    Point<dim> lower;
    Point<dim> upper;

    bool
    contains(const Point<dim> &p, const double tolerance = 0.) const;

    /** Euclidean distance from @p p to the box (0 inside). */
    double
    distance(const Point<dim> &p) const;

    /** Per-axis gaps between this box and @p other (0 where they overlap in that axis). */
    Tensor<1, dim>
    gap(const Box<dim> &other) const;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &lower &upper;
    }
  };

  /**
   * The shape of a mesh cell with straight edges (a quadrilateral, a hexahedron), given by its
   * vertices in deal.II's order: a PD region grown on a general mesh is a union of cells, which
   * boxes cannot describe. Its inside is the union of the simplices that join the cell's
   * centre to its faces, a face of a hexahedron split into four triangles about the face's
   * centre, so two cells split the face they share alike, flat or not, and leave no gap.
   */
  template <int dim>
  struct CellShape
  {
    std::array<Point<dim>, GeometryInfo<dim>::vertices_per_cell> vertices;

    /** Is @p p inside, or within @p tolerance [m] of the cell? */
    bool
    contains(const Point<dim> &p, const double tolerance = 0.) const;

    /** Euclidean distance from @p p to the cell (0 inside). */
    double
    distance(const Point<dim> &p) const;

    /** The smallest box that holds the cell. */
    Box<dim>
    bounding_box() const;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &vertices;
    }
  };

  /**
   * A union of boxes, and of mesh cells where the region grew on a general mesh. Boxes are written
   * in a parameter file as "x0, y0 : x1, y1 ; x0, y0 : x1, y1" (lower and upper corner of each box,
   * boxes separated by ';'). Empty text is the empty set.
   */
  template <int dim>
  struct Region
  {
    std::vector<Box<dim>> boxes;
    /** Cells of a general mesh that joined the region (none on a box mesh). */
    std::vector<CellShape<dim>> cells;

    bool
    contains(const Point<dim> &p, const double tolerance = 0.) const;
    bool
    empty() const;

    /** Euclidean distance from @p p to the nearest box or cell (0 inside; infinity if empty). */
    double
    distance(const Point<dim> &p) const;

    /** The boxes and the cells, counted as pieces. */
    std::size_t
    n_pieces() const;

    /** The bounds of every piece: the boxes, then the cells' bounding boxes. */
    std::vector<Box<dim>>
    piece_bounds() const;

    /** Distance from @p p to piece @p k (in the order of piece_bounds()). */
    double
    piece_distance(const std::size_t k, const Point<dim> &p) const;

    /** Add the boxes and cells of @p other (the union). */
    void
    add(const Region<dim> &other);

    /**
     * Merge boxes that share a whole face (within @p tolerance [m]), axis by axis, so that a
     * region grown cell by cell keeps few boxes and distance() stays cheap. The union is
     * unchanged.
     */
    void
    coalesce(const double tolerance);

    /** The boxes and cells, for a checkpoint. */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &boxes &cells;
    }

    /** Parse the text of @p parameter (named in errors) into a region. */
    static Region<dim>
    parse(const std::string &text, const std::string &parameter);
  };

  /**
   * Distances to a region of many pieces (a zone grown cell by cell keeps hundreds) at the cost
   * of the pieces near the point: the pieces' bounds are binned on a uniform grid over their
   * hull, and a query visits rings of bins around the point until no piece left unvisited can
   * be nearer (a piece is no nearer than its bounds). The result is Region::distance(), to the
   * bit: the same minimum of the same terms.
   */
  template <int dim>
  class RegionDistance
  {
  public:
    /** The distance to the empty region: infinity everywhere. */
    RegionDistance() = default;

    explicit RegionDistance(const Region<dim> &region);

    /**
     * Euclidean distance from @p p to the nearest box or cell (0 inside; infinity if empty).
     * With @p cap, a distance of @p cap or more may come back as any number >= @p cap: the
     * search stops there, so points far from the region (most of an FE mesh around a small PD
     * zone, asked for a blending weight) cost a few bins; distances below @p cap are exact.
     */
    double
    distance(const Point<dim> &p, const double cap = std::numeric_limits<double>::infinity()) const;

  private:
    /** The region (its pieces are scanned where the grid does not help). */
    Region<dim> region;
    /** Its number of pieces. */
    std::size_t n_pieces = 0;
    /** The grid: its lower corner, bin width and bins per axis (none for a few boxes). */
    Point<dim>                    origin;
    double                        bin_width = 0;
    std::array<unsigned int, dim> n_bins{};
    /** The pieces touching bin b are bin_pieces[bin_begin[b], bin_begin[b + 1]). */
    std::vector<unsigned int> bin_begin;
    std::vector<unsigned int> bin_pieces;
  };

  /** Parse a segment "x0, y0 : x1, y1" (its two end points) from the text of @p parameter. */
  template <int dim>
  std::pair<Point<dim>, Point<dim>>
  parse_segment(const std::string &text, const std::string &parameter);

  /** Parse points "x0, y0 : x1, y1 : ..." (one or more) from the text of @p parameter. */
  template <int dim>
  std::vector<Point<dim>>
  parse_point_list(const std::string &text, const std::string &parameter);

  /**
   * A pre-crack: a segment in 2D ("x0, y0 : x1, y1"), a parallelogram in 3D given by a corner
   * and two edge vectors ("x0, y0, z0 : ax, ay, az : bx, by, bz"). Bonds whose reference
   * segment crosses it are cut at the start.
   */
  template <int dim>
  struct PreCrack
  {
    Point<dim>     origin;
    Tensor<1, dim> edge_a;
    Tensor<1, dim> edge_b; // unused in 2D

    /** Does the segment from @p p to @p q cross the crack? */
    bool
    cuts(const Point<dim> &p, const Point<dim> &q) const;

    /** Parse a ';'-separated list of cracks from the text of @p parameter. */
    static std::vector<PreCrack<dim>>
    parse_list(const std::string &text, const std::string &parameter);
  };
} // namespace PeriArlequin

#endif
