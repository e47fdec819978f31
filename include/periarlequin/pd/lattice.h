#ifndef periarlequin_pd_lattice_h
#define periarlequin_pd_lattice_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/particles/property_pool.h>

#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The regular lattice of PD sites: spacing dx, anchored at the lower corner of the domain,
   * a site at the centre of every lattice cell inside the domain. A site's id is its
   * lexicographic index (x fastest) and is the particle id of the particle there, so ids,
   * and the decisions taken in their order, do not depend on the partition.
   */
  template <int dim>
  class Lattice
  {
  public:
    using Site   = std::array<unsigned int, dim>;
    using Offset = std::array<int, dim>;

    Lattice(const Point<dim> &lower_corner, const Point<dim> &upper_corner, const double spacing);

    /** The id of @p site. */
    types::particle_index
    id(const Site &site) const;

    /** The site of id @p id. */
    Site
    site(types::particle_index id) const;

    /** The centre of the lattice cell of @p site. */
    Point<dim>
    position(const Site &site) const;

    /** The site at @p offset from @p site, if it lies in the lattice. */
    std::optional<Site>
    neighbour(const Site &site, const Offset &offset) const;

    /**
     * Visit every site whose position lies in the half-open box [@p lower, @p upper): the
     * sites of an axis-aligned cell, each site in exactly one cell.
     */
    template <typename Visitor>
    void
    for_each_site_in(const Point<dim> &lower, const Point<dim> &upper, const Visitor &visit) const;

    /**
     * The sites around @p x and their multilinear interpolation weights (the 2^dim corners
     * of the lattice-site cell that holds x; corners outside the lattice or of zero weight
     * left out, the weights not renormalised).
     */
    std::vector<std::pair<types::particle_index, double>>
    interpolation_weights(const Point<dim> &x) const;

    /**
     * The upper corner of the lattice's cells: the domain's, less the strip along an upper
     * face that a whole lattice cell does not fill (where dx does not divide the domain).
     */
    Point<dim>
    upper_corner() const;

    /** The number of sites: the particles of pure PD on a box domain. */
    types::particle_index
    size() const;

  private:
    Point<dim> origin;
    double     dx;
    Site       n_sites;
  };


  template <int dim>
  template <typename Visitor>
  void
  Lattice<dim>::for_each_site_in(const Point<dim> &lower,
                                 const Point<dim> &upper,
                                 const Visitor    &visit) const
  {
    std::array<std::pair<unsigned int, unsigned int>, dim> range;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double first = std::ceil((lower[d] - origin[d]) / dx - 0.5);
        const double end   = std::ceil((upper[d] - origin[d]) / dx - 0.5);
        range[d]           = {static_cast<unsigned int>(std::max(first, 0.)),
                              static_cast<unsigned int>(
                      std::min(std::max(end, 0.), static_cast<double>(n_sites[d])))};
      }
    Site       site;
    const auto loop = [&](const auto &self, const unsigned int d) -> void {
      if (d == dim)
        return visit(site);
      for (site[d] = range[d].first; site[d] < range[d].second; ++site[d])
        self(self, d + 1);
    };
    loop(loop, 0);
  }
} // namespace PeriArlequin

#endif
