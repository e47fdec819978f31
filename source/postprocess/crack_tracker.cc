#include <periarlequin/pd/bond_families.h>
#include <periarlequin/postprocess/crack_diagnostics.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <unordered_map>

namespace PeriArlequin
{
  template <int dim>
  double
  CrackTracker<dim>::Branch::speed(const unsigned int window) const
  {
    const std::size_t n     = times.size();
    const std::size_t first = n > window ? n - window - 1 : 0;
    if (n - first < 2)
      return 0.;
    double t_mean = 0, s_mean = 0;
    for (std::size_t k = first; k < n; ++k)
      {
        t_mean += times[k];
        s_mean += path_lengths[k];
      }
    t_mean /= (n - first);
    s_mean /= (n - first);
    double covariance = 0, variance = 0;
    for (std::size_t k = first; k < n; ++k)
      {
        covariance += (times[k] - t_mean) * (path_lengths[k] - s_mean);
        variance += (times[k] - t_mean) * (times[k] - t_mean);
      }
    return variance > 0 ? covariance / variance : 0.;
  }

  template <int dim>
  CrackTracker<dim>::CrackTracker(const double link_distance, const double branch_separation)
    : link_distance(link_distance)
    , branch_separation(branch_separation)
  {}

  namespace
  {
    /** Pairs of points at most @p radius apart, found through a hash grid of that size. */
    template <int dim>
    class NeighbourSearch
    {
    public:
      NeighbourSearch(const std::vector<Point<dim>> &points, const double radius)
        : points(points)
        , radius(radius)
      {
        for (unsigned int i = 0; i < points.size(); ++i)
          grid[key(cell_of(points[i]))].push_back(i);
      }

      /** Call @p visit(j, distance) for every other point within the radius of point @p i. */
      template <typename Visitor>
      void
      for_each_neighbour(const unsigned int i, const Visitor &visit) const
      {
        const auto centre    = cell_of(points[i]);
        const int  n_offsets = static_cast<int>(std::pow(3, dim));
        for (int o = 0; o < n_offsets; ++o)
          {
            std::array<long, dim> cell = centre;
            for (int d = 0, rest = o; d < dim; ++d, rest /= 3)
              cell[d] += rest % 3 - 1;
            const auto found = grid.find(key(cell));
            if (found == grid.end())
              continue;
            for (const unsigned int j : found->second)
              {
                const double distance = points[i].distance(points[j]);
                if (j != i && distance <= radius)
                  visit(j, distance);
              }
          }
      }

    private:
      std::array<long, dim>
      cell_of(const Point<dim> &x) const
      {
        std::array<long, dim> cell;
        for (unsigned int d = 0; d < dim; ++d)
          cell[d] = static_cast<long>(std::floor(x[d] / radius));
        return cell;
      }

      static std::uint64_t
      key(const std::array<long, dim> &cell)
      {
        std::uint64_t h = 0;
        for (unsigned int d = 0; d < dim; ++d)
          h = h * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(cell[d] + (1L << 30));
        return h;
      }

      const std::vector<Point<dim>>                               &points;
      const double                                                 radius;
      std::unordered_map<std::uint64_t, std::vector<unsigned int>> grid;
    };
  } // namespace

  template <int dim>
  void
  CrackTracker<dim>::update(const double time, const std::vector<CrackedParticle> &cracked)
  {
    const unsigned int        record = n_records++;
    const unsigned int        n      = cracked.size();
    std::vector<Point<dim>>   x(n);
    std::vector<unsigned int> first(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        x[i]     = cracked[i].position;
        first[i] = first_cracked.emplace(cracked[i].id, record).first->second;
      }
    const NeighbourSearch<dim> links(x, link_distance);

    // Connected cracks, and the record that first saw each.
    std::vector<unsigned int> crack(n, numbers::invalid_unsigned_int), crack_origin;
    for (unsigned int seed = 0; seed < n; ++seed)
      if (crack[seed] == numbers::invalid_unsigned_int)
        {
          const unsigned int c = crack_origin.size();
          crack_origin.push_back(first[seed]);
          std::vector<unsigned int> stack = {seed};
          crack[seed]                     = c;
          while (!stack.empty())
            {
              const unsigned int i = stack.back();
              stack.pop_back();
              crack_origin[c] = std::min(crack_origin[c], first[i]);
              links.for_each_neighbour(i, [&](const unsigned int j, double) {
                if (crack[j] == numbers::invalid_unsigned_int)
                  {
                    crack[j] = c;
                    stack.push_back(j);
                  }
              });
            }
        }

    // Distances along links from the origins (Dijkstra), with the predecessor of each.
    std::vector<double>       path(n, std::numeric_limits<double>::infinity());
    std::vector<unsigned int> previous(n, numbers::invalid_unsigned_int);
    using Entry = std::pair<double, unsigned int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for (unsigned int i = 0; i < n; ++i)
      if (first[i] == crack_origin[crack[i]])
        {
          path[i] = 0;
          queue.emplace(0., i);
        }
    while (!queue.empty())
      {
        const auto [length, i] = queue.top();
        queue.pop();
        if (length > path[i])
          continue;
        links.for_each_neighbour(i, [&](const unsigned int j, const double distance) {
          if (length + distance < path[j])
            {
              path[j]     = length + distance;
              previous[j] = i;
              queue.emplace(path[j], j);
            }
        });
      }
    // Links zigzag on a lattice (7 % longer than the line at 30 degrees): the path length of
    // a tip is that of the polyline through the points of its chain a branch separation
    // apart along it.
    const auto path_length = [&](const unsigned int tip) {
      double       length = 0;
      unsigned int corner = tip;
      for (unsigned int i = tip; previous[i] != numbers::invalid_unsigned_int; i = previous[i])
        if (path[corner] - path[previous[i]] >= branch_separation ||
            previous[previous[i]] == numbers::invalid_unsigned_int)
          {
            length += x[corner].distance(x[previous[i]]);
            corner = previous[i];
          }
      return length;
    };

    // Tips: the farthest along within the branch separation.
    const NeighbourSearch<dim> around(x, branch_separation);
    std::vector<unsigned int>  tips;
    unsigned int               farthest_particle = numbers::invalid_unsigned_int;
    for (unsigned int i = 0; i < n; ++i)
      {
        if (path[i] > 0 && (farthest_particle == numbers::invalid_unsigned_int ||
                            path[i] > path[farthest_particle]))
          farthest_particle = i;
        if (!(path[i] > branch_separation))
          continue;
        bool farthest = true;
        around.for_each_neighbour(i, [&](const unsigned int j, double) {
          if (path[j] > path[i] || (path[j] == path[i] && cracked[j].id > cracked[i].id))
            farthest = false;
        });
        if (farthest)
          tips.push_back(i);
      }
    extension =
      farthest_particle == numbers::invalid_unsigned_int ? 0. : path_length(farthest_particle);

    // Match the tips to the branches of the last record, nearest pairs first.
    std::vector<std::tuple<double, unsigned int, unsigned int>> pairs;
    for (unsigned int b = 0; b < branches.size(); ++b)
      if (branches[b].active)
        for (unsigned int t = 0; t < tips.size(); ++t)
          pairs.emplace_back(branches[b].tips.back().distance(x[tips[t]]), b, t);
    std::sort(pairs.begin(), pairs.end());
    std::vector<bool> branch_matched(branches.size(), false), tip_matched(tips.size(), false);
    const auto        extend_branch = [&](Branch &branch, const unsigned int t) {
      branch.times.push_back(time);
      branch.tips.push_back(x[tips[t]]);
      branch.path_lengths.push_back(path_length(tips[t]));
    };
    for (const auto &[distance, b, t] : pairs)
      if (!branch_matched[b] && !tip_matched[t])
        {
          branch_matched[b] = tip_matched[t] = true;
          extend_branch(branches[b], t);
        }
    for (unsigned int b = 0; b < branch_matched.size(); ++b)
      branches[b].active = branch_matched[b];
    for (unsigned int t = 0; t < tips.size(); ++t)
      if (!tip_matched[t])
        {
          branches.emplace_back();
          extend_branch(branches.back(), t);
        }
  }

  template <int dim>
  const std::vector<typename CrackTracker<dim>::Branch> &
  CrackTracker<dim>::get_branches() const
  {
    return branches;
  }

  template <int dim>
  unsigned int
  CrackTracker<dim>::n_active_branches() const
  {
    return std::count_if(branches.begin(), branches.end(), [](const Branch &b) {
      return b.active;
    });
  }

  template <int dim>
  double
  CrackTracker<dim>::crack_extension() const
  {
    return extension;
  }

  template <int dim>
  CrackInitiation<dim>::CrackInitiation(const Point<dim>            &tip,
                                        const double                 direction,
                                        const double                 horizon,
                                        const std::array<double, 2> &fit_range)
    : tip(tip)
    , horizon(horizon)
    , fit_range(fit_range)
  {
    this->direction[0] = std::cos(direction);
    this->direction[1] = std::sin(direction);
  }

  template <int dim>
  double
  CrackInitiation<dim>::distance_from_tip(const Point<dim> &x) const
  {
    return std::hypot(x[0] - tip[0], x[1] - tip[1]);
  }

  template <int dim>
  void
  CrackInitiation<dim>::update(const double                        time,
                               const std::vector<CrackedParticle> &cracked,
                               const unsigned long long            broken_near_tip)
  {
    if (first_record)
      {
        first_record            = false;
        initial_broken_near_tip = broken_near_tip;
        for (const auto &particle : cracked)
          initially_cracked.insert(particle.id);
        return;
      }
    if (std::isnan(initiation) && broken_near_tip > initial_broken_near_tip)
      initiation = time;

    // Second moment about the tip of the new cracked particles in the fit range.
    const double          ahead = std::cos(2. * numbers::PI / 3.);
    SymmetricTensor<2, 2> moment;
    Tensor<1, 2>          sum;
    n_fitted = 0;
    for (const auto &particle : cracked)
      {
        if (initially_cracked.count(particle.id) > 0)
          continue;
        const Tensor<1, 2> d({particle.position[0] - tip[0], particle.position[1] - tip[1]});
        const double       r = d.norm();
        if (r == 0 || d * direction < ahead * r)
          continue;
        if (std::isnan(growth) && r >= horizon * (1. - 1e-12))
          growth = time;
        if (r < fit_range[0] || r > fit_range[1])
          continue;
        moment += symmetrize(outer_product(d, d));
        sum += d;
        ++n_fitted;
      }
    angle = std::numeric_limits<double>::quiet_NaN();
    if (n_fitted < 3)
      return;
    // The principal axis of the larger eigenvalue, turned to point away from the tip.
    const double phi = 0.5 * std::atan2(2. * moment[0][1], moment[0][0] - moment[1][1]);
    Tensor<1, 2> axis({std::cos(phi), std::sin(phi)});
    if (axis * sum < 0)
      axis *= -1.;
    angle = std::atan2(direction[0] * axis[1] - direction[1] * axis[0], direction * axis);
  }

  template <int dim>
  double
  CrackInitiation<dim>::initiation_time() const
  {
    return initiation;
  }

  template <int dim>
  double
  CrackInitiation<dim>::growth_time() const
  {
    return growth;
  }

  template <int dim>
  double
  CrackInitiation<dim>::kink_angle() const
  {
    return angle;
  }

  template <int dim>
  unsigned int
  CrackInitiation<dim>::n_fitted_particles() const
  {
    return n_fitted;
  }

  template <int dim>
  double
  broken_bond_area(const BondFamilies<dim> &bonds,
                   const double             lattice_spacing,
                   const MPI_Comm           communicator)
  {
    // Bonds of offset xi cross a lattice plane normal to axis 0 at xi_0 / dx^dim per unit
    // area (those with xi_0 > 0).
    double per_unit_area = 0;
    for (const auto &entry : bonds.stencil)
      if (entry.xi[0] > 0)
        per_unit_area += entry.xi[0] * entry.length * entry.volume;
    per_unit_area /= std::pow(lattice_spacing, dim);

    // A bond to a ghost is stored on both ranks that own one of its ends: half on each.
    const double broken =
      bonds.template sum_over_broken_bonds<double>([&](const unsigned int i, const std::size_t n) {
        const auto &entry = bonds.stencil[bonds.stencil_index[n]];
        return (bonds.neighbor_is_owned(i, n) ? 1. : 0.5) * entry.length * entry.volume;
      });
    return Utilities::MPI::sum(broken, communicator) / per_unit_area;
  }

  template class CrackTracker<2>;
  template class CrackTracker<3>;
  template class CrackInitiation<2>;
  template class CrackInitiation<3>;
  template double
  broken_bond_area(const BondFamilies<2> &, const double, const MPI_Comm);
  template double
  broken_bond_area(const BondFamilies<3> &, const double, const MPI_Comm);
} // namespace PeriArlequin
