#include <periarlequin/pd/lattice.h>

namespace PeriArlequin
{
  template <int dim>
  Lattice<dim>::Lattice(const Point<dim> &lower_corner,
                        const Point<dim> &upper_corner,
                        const double      spacing)
    : origin(lower_corner)
    , dx(spacing)
  {
    for (unsigned int d = 0; d < dim; ++d)
      n_sites[d] =
        static_cast<unsigned int>(std::floor((upper_corner[d] - lower_corner[d]) / dx + 1e-8));
  }

  template <int dim>
  Point<dim>
  Lattice<dim>::upper_corner() const
  {
    Point<dim> upper = origin;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] += n_sites[d] * dx;
    return upper;
  }

  template <int dim>
  types::particle_index
  Lattice<dim>::size() const
  {
    types::particle_index n = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n *= n_sites[d];
    return n;
  }

  template <int dim>
  types::particle_index
  Lattice<dim>::id(const Site &site) const
  {
    types::particle_index id = 0;
    for (int d = dim - 1; d >= 0; --d)
      id = id * n_sites[d] + site[d];
    return id;
  }

  template <int dim>
  typename Lattice<dim>::Site
  Lattice<dim>::site(types::particle_index id) const
  {
    Site site;
    for (unsigned int d = 0; d < dim; ++d)
      {
        site[d] = id % n_sites[d];
        id /= n_sites[d];
      }
    return site;
  }

  template <int dim>
  Point<dim>
  Lattice<dim>::position(const Site &site) const
  {
    Point<dim> p;
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = origin[d] + (site[d] + 0.5) * dx;
    return p;
  }

  template <int dim>
  std::optional<typename Lattice<dim>::Site>
  Lattice<dim>::neighbour(const Site &site, const Offset &offset) const
  {
    Site other;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const long s = static_cast<long>(site[d]) + offset[d];
        if (s < 0 || s >= static_cast<long>(n_sites[d]))
          return std::nullopt;
        other[d] = static_cast<unsigned int>(s);
      }
    return other;
  }

  template <int dim>
  std::vector<std::pair<types::particle_index, double>>
  Lattice<dim>::interpolation_weights(const Point<dim> &x) const
  {
    // Sites sit at cell centres of the lattice: the 2^dim around x and their weights.
    Site                    base;
    Offset                  lower;
    std::array<double, dim> fraction;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double s = (x[d] - origin[d]) / dx - 0.5;
        lower[d]       = static_cast<int>(std::floor(s));
        fraction[d]    = s - lower[d];
        base[d]        = 0;
      }
    std::vector<std::pair<types::particle_index, double>> weights;
    for (unsigned int corner = 0; corner < (1u << dim); ++corner)
      {
        Offset offset;
        double w = 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const bool upper = corner & (1u << d);
            offset[d]        = lower[d] + upper;
            w *= upper ? fraction[d] : 1. - fraction[d];
          }
        const auto site = neighbour(base, offset);
        if (site && w != 0)
          weights.emplace_back(id(*site), w);
      }
    return weights;
  }

  template class Lattice<2>;
  template class Lattice<3>;
} // namespace PeriArlequin
