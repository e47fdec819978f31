#include <deal.II/base/mpi.h>

#include <periarlequin/postprocess/crack_diagnostics.h>
#include <periarlequin/simulator.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <queue>
#include <sstream>
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
        const auto centre = cell_of(points[i]);
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

      const std::vector<Point<dim>>                           &points;
      const double                                             radius;
      std::unordered_map<std::uint64_t, std::vector<unsigned int>> grid;
    };
  } // namespace

  template <int dim>
  void
  CrackTracker<dim>::update(const double time, const std::vector<CrackedParticle> &cracked)
  {
    const unsigned int record = n_records++;
    const unsigned int n      = cracked.size();
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
    double broken = 0;
    for (std::size_t n = 0; n < bonds.neighbor.size(); ++n)
      if (bonds.state[n] == BondFamilies<dim>::broken)
        {
          const auto &entry = bonds.stencil[bonds.stencil_index[n]];
          broken += (bonds.neighbor_is_owned(n) ? 1. : 0.5) * entry.length * entry.volume;
        }
    return Utilities::MPI::sum(broken, communicator) / per_unit_area;
  }

  template <int dim>
  void
  CrackDiagnostics<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("cracks");
    prm.declare_entry("Damage threshold",
                      "0.35",
                      Patterns::Double(0, 1),
                      "Damage from which a particle counts as cracked [-]. A particle next to "
                      "the faces of a straight crack has a damage near 0.5.");
    prm.declare_entry("Link distance",
                      "2",
                      Patterns::Double(1),
                      "Cracked particles at most this far apart belong to one crack "
                      "[lattice spacings].");
    prm.declare_entry("Branch separation",
                      "2",
                      Patterns::Double(0),
                      "A tip is the particle farthest along its crack within this distance; "
                      "two branches are told apart once their tips are farther apart [horizons].");
    prm.declare_entry("Speed window",
                      "5",
                      Patterns::Integer(1),
                      "Tip speeds are least-squares slopes of the path length over this many "
                      "recorded intervals (Output/Energy interval steps each) [-].");
    prm.declare_entry("Reported branches",
                      "4",
                      Patterns::Integer(1, 64),
                      "Branches given columns in the history, in the order they appeared [-].");
    prm.leave_subsection();
  }

  template <int dim>
  void
  CrackDiagnostics<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("cracks");
    damage_threshold  = prm.get_double("Damage threshold");
    link_distance     = prm.get_double("Link distance");
    branch_separation = prm.get_double("Branch separation");
    speed_window      = prm.get_integer("Speed window");
    reported_branches = prm.get_integer("Reported branches");
    prm.leave_subsection();
  }

  template <int dim>
  void
  CrackDiagnostics<dim>::execute(const Simulator<dim> &simulator, EnergyHistory &history)
  {
    const PDZone<dim> *pd = simulator.get_pd_zone();
    AssertThrow(pd != nullptr,
                ExcMessage("Invalid input: 'Postprocess/List of postprocessors' names 'cracks' "
                           "but the case has no PD zone (Peridynamics/Region is empty)."));
    const auto  &parameters = pd->get_parameters();
    const MPI_Comm communicator = pd->get_communicator();
    if (!tracker)
      tracker = std::make_unique<CrackTracker<dim>>(link_distance * parameters.lattice_spacing,
                                                    branch_separation * parameters.horizon());

    // Gathered as (id, position, damage) rows of doubles: ids are lattice site numbers,
    // exact in a double.
    using Cracked = typename CrackTracker<dim>::CrackedParticle;
    std::vector<double>       local;
    const std::vector<double> damage = pd->get_bonds().damage();
    const auto                ids    = pd->particle_ids();
    const auto                x      = pd->reference_positions();
    for (unsigned int i = 0; i < pd->n_owned_particles(); ++i)
      if (damage[i] > 0 && !pd->is_slave(i))
        {
          local.push_back(ids[i]);
          for (unsigned int d = 0; d < dim; ++d)
            local.push_back(x[i][d]);
          local.push_back(damage[i]);
        }
    damaged.clear();
    for (const auto &part : Utilities::MPI::all_gather(communicator, local))
      for (std::size_t k = 0; k < part.size(); k += dim + 2)
        {
          Cracked particle{static_cast<types::particle_index>(part[k]), Point<dim>()};
          for (unsigned int d = 0; d < dim; ++d)
            particle.position[d] = part[k + 1 + d];
          damaged.emplace_back(particle, part[k + dim + 1]);
        }
    std::sort(damaged.begin(), damaged.end(), [](const auto &a, const auto &b) {
      return a.first.id < b.first.id;
    });
    std::vector<Cracked> cracked;
    for (const auto &[particle, d] : damaged)
      if (d >= damage_threshold)
        cracked.push_back(particle);
    tracker->update(simulator.get_time(), cracked);

    const double area = broken_bond_area(pd->get_bonds(), parameters.lattice_spacing, communicator);
    if (simulator.get_step_number() == 0)
      initial_area = area;
    history.add_value("branches", tracker->n_active_branches());
    history.add_value("crack_extension", tracker->crack_extension());
    history.add_value("crack_area", area - initial_area);
    history.add_value("broken_bond_energy", parameters.energy_release_rate * (area - initial_area));
    const auto        &branches = tracker->get_branches();
    const double       nan      = std::numeric_limits<double>::quiet_NaN();
    const char        *axes[3]  = {"x", "y", "z"};
    for (unsigned int b = 0; b < reported_branches; ++b)
      {
        const bool         shown  = b < branches.size() && branches[b].active;
        const std::string  prefix = "branch_" + std::to_string(b) + "_";
        for (unsigned int d = 0; d < dim; ++d)
          history.add_value(prefix + axes[d], shown ? branches[b].tips.back()[d] : nan);
        history.add_value(prefix + "path_length", shown ? branches[b].path_lengths.back() : nan);
        history.add_value(prefix + "speed", shown ? branches[b].speed(speed_window) : nan);
      }

    const unsigned int interval = simulator.get_output_parameters().output_interval;
    const unsigned int step     = simulator.get_step_number();
    if (interval > 0 && (step % interval == 0 || step == simulator.get_n_steps()))
      write_damage_map(simulator);
  }

  template <int dim>
  void
  CrackDiagnostics<dim>::write_damage_map(const Simulator<dim> &simulator) const
  {
    if (Utilities::MPI::this_mpi_process(simulator.get_pd_zone()->get_communicator()) != 0)
      return;
    const auto        &output = simulator.get_output_parameters();
    std::ostringstream name;
    name << output.directory << "/" << output.base_name << "_damage_" << std::setw(6)
         << std::setfill('0') << simulator.get_step_number() << ".csv";
    std::ofstream file(name.str());
    AssertThrow(file, ExcMessage("Cannot write " + name.str()));
    const Box<dim> &domain = simulator.get_pd_zone()->get_domain();
    file << "# t = " << std::setprecision(10) << simulator.get_time() << " s; domain";
    for (const Point<dim> &corner : {domain.lower, domain.upper})
      for (unsigned int d = 0; d < dim; ++d)
        file << ' ' << corner[d];
    file << '\n';
    file << (dim == 2 ? "x,y,damage\n" : "x,y,z,damage\n") << std::setprecision(8);
    for (const auto &[particle, d] : damaged)
      {
        for (unsigned int c = 0; c < dim; ++c)
          file << particle.position[c] << ',';
        file << d << '\n';
      }
  }

  template class CrackTracker<2>;
  template class CrackTracker<3>;
  template double
  broken_bond_area(const BondFamilies<2> &, const double, const MPI_Comm);
  template double
  broken_bond_area(const BondFamilies<3> &, const double, const MPI_Comm);
  template class CrackDiagnostics<2>;
  template class CrackDiagnostics<3>;

  PERIARLEQUIN_REGISTER_POSTPROCESSOR(
    CrackDiagnostics,
    "cracks",
    "branches, tip position, path length and speed of each branch, crack area and the "
    "energy of the broken bonds; damage maps as CSV with the ParaView output")
} // namespace PeriArlequin
