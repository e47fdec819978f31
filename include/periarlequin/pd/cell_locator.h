#ifndef periarlequin_pd_cell_locator_h
#define periarlequin_pd_cell_locator_h

// Which cell of a general (non-box) mesh holds a lattice site: the PD zone asks it when it
// assigns sites to cells (PDZone::owns_site()) and when it leaves out the sites of a family
// that fall outside the mesh (a hole, a notch).

#include <deal.II/base/bounding_box.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <cmath>
#include <optional>
#include <unordered_map>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  namespace internal
  {
    /**
     * The unit coordinates of @p x in @p cell if the cell holds it (closed, within
     * @p tolerance in unit coordinates), else nothing.
     */
    template <int dim>
    std::optional<Point<dim>>
    unit_point_in(const Mapping<dim>                                      &mapping,
                  const typename Triangulation<dim>::active_cell_iterator &cell,
                  const Point<dim>                                        &x,
                  const double                                             tolerance)
    {
      if (!cell->bounding_box().point_inside(x, tolerance * cell->diameter()))
        return {};
      try
        {
          const Point<dim> unit = mapping.transform_real_to_unit_cell(cell, x);
          if (GeometryInfo<dim>::is_inside_unit_cell(unit, tolerance))
            return unit;
        }
      catch (const typename Mapping<dim>::ExcTransformationFailed &)
        {}
      return {};
    }

    /**
     * Which cells of the whole local mesh (artificial ones too: without manifolds they cover
     * the domain exactly) hold a point: a hash grid of their bounding boxes.
     */
    template <int dim>
    class CellLocator
    {
    public:
      CellLocator(const Triangulation<dim> &triangulation, const Mapping<dim> &mapping)
        : mapping(mapping)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          bin_size = std::max(bin_size, cell->diameter());
        for (const auto &cell : triangulation.active_cell_iterators())
          {
            const auto [lower, upper]   = cell->bounding_box().get_boundary_points();
            const auto            first = bin(lower), last = bin(upper);
            std::array<long, dim> b;
            const auto            visit = [&](const auto &self, const unsigned int d) -> void {
              if (d == dim)
                {
                  bins[b].push_back(cell);
                  return;
                }
              for (b[d] = first[d]; b[d] <= last[d]; ++b[d])
                self(self, d + 1);
            };
            visit(visit, 0);
          }
      }

      bool
      holds(const Point<dim> &x) const
      {
        const auto found = bins.find(bin(x));
        if (found == bins.end())
          return false;
        for (const auto &cell : found->second)
          if (unit_point_in<dim>(mapping, cell, x, 1e-10))
            return true;
        return false;
      }

    private:
      std::array<long, dim>
      bin(const Point<dim> &x) const
      {
        std::array<long, dim> b;
        for (unsigned int d = 0; d < dim; ++d)
          b[d] = static_cast<long>(std::floor(x[d] / bin_size));
        return b;
      }

      struct BinHash
      {
        std::size_t
        operator()(const std::array<long, dim> &b) const
        {
          std::size_t h = 0;
          for (const long c : b)
            h = h * 1000003u + static_cast<std::size_t>(c);
          return h;
        }
      };

      const Mapping<dim> &mapping;
      double              bin_size = 0;
      std::unordered_map<std::array<long, dim>,
                         std::vector<typename Triangulation<dim>::active_cell_iterator>,
                         BinHash>
        bins;
    };
  } // namespace internal
} // namespace PeriArlequin

#endif
