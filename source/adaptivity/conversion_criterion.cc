#include <periarlequin/adaptivity/conversion_criterion.h>
#include <periarlequin/base/gather.h>
#include <periarlequin/base/parameters.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace PeriArlequin
{
  namespace
  {
    /**
     * The smallest axis-aligned box around a cell: the cell itself on a box mesh; on a general
     * mesh a little more, so a point near the cell is never missed (a point near the box but
     * not the cell counts as near: a growth converts a little more, never less).
     */
    template <int dim, typename CellIterator>
    Box<dim>
    cell_box(const CellIterator &cell)
    {
      Box<dim> box{cell->vertex(0), cell->vertex(0)};
      for (const unsigned int v : cell->vertex_indices())
        for (unsigned int d = 0; d < dim; ++d)
          {
            box.lower[d] = std::min(box.lower[d], cell->vertex(v)[d]);
            box.upper[d] = std::max(box.upper[d], cell->vertex(v)[d]);
          }
      return box;
    }
  } // namespace

  namespace internal
  {
    template <int dim>
    PointBins<dim>::PointBins(const std::vector<Point<dim>> &points, const double distance)
      : distance(distance)
      , bounds{Point<dim>(), Point<dim>()}
      , binned(points.size())
    {
      n_bins.fill(1);
      bin_start.assign(2, 0);
      if (points.empty())
        return;
      bounds = Box<dim>{points[0], points[0]};
      for (const Point<dim> &p : points)
        for (unsigned int d = 0; d < dim; ++d)
          {
            bounds.lower[d] = std::min(bounds.lower[d], p[d]);
            bounds.upper[d] = std::max(bounds.upper[d], p[d]);
          }
      double volume = 1;
      for (unsigned int d = 0; d < dim; ++d)
        volume *= bounds.upper[d] - bounds.lower[d] + distance;
      const double widest = std::max(distance, std::pow(volume / (4. * points.size()), 1. / dim));
      bin                 = widest > 0 ? widest : 1.;
      std::size_t n_all_bins = 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          n_bins[d] = static_cast<unsigned int>((bounds.upper[d] - bounds.lower[d]) / bin) + 1;
          n_all_bins *= n_bins[d];
        }
      const auto bin_of = [&](const Point<dim> &p) {
        std::size_t index = 0;
        for (int d = dim - 1; d >= 0; --d)
          index = index * n_bins[d] + std::min<unsigned int>(static_cast<unsigned int>(std::floor(
                                                               (p[d] - bounds.lower[d]) / bin)),
                                                             n_bins[d] - 1);
        return index;
      };
      bin_start.assign(n_all_bins + 1, 0);
      for (const Point<dim> &p : points)
        ++bin_start[bin_of(p) + 1];
      for (std::size_t b = 0; b < n_all_bins; ++b)
        bin_start[b + 1] += bin_start[b];
      std::vector<std::size_t> next(bin_start.begin(), bin_start.end() - 1);
      for (const Point<dim> &p : points)
        binned[next[bin_of(p)]++] = p;
    }

    template <int dim>
    template <typename Visitor>
    bool
    PointBins<dim>::visit_near(const Box<dim> &box, const Visitor &visit) const
    {
      if (binned.empty())
        return false;
      const auto bin_along = [&](const double x, const unsigned int d) {
        return static_cast<int>(std::floor((x - bounds.lower[d]) / bin));
      };
      std::array<int, dim> first, last;
      for (unsigned int d = 0; d < dim; ++d)
        {
          first[d] = std::max(bin_along(box.lower[d] - distance, d), 0);
          last[d] =
            std::min(bin_along(box.upper[d] + distance, d), static_cast<int>(n_bins[d]) - 1);
          if (first[d] > last[d])
            return false;
        }
      // Every bin of the block [first, last], the first axis fastest.
      std::array<int, dim> b = first;
      while (true)
        {
          std::size_t index = 0;
          for (int d = dim - 1; d >= 0; --d)
            index = index * n_bins[d] + b[d];
          for (std::size_t k = bin_start[index]; k < bin_start[index + 1]; ++k)
            if (box.distance(binned[k]) < distance && visit(binned[k]))
              return true;
          unsigned int d = 0;
          while (d < dim && b[d] == last[d])
            b[d] = first[d], ++d;
          if (d == dim)
            return false;
          ++b[d];
        }
    }

    template <int dim>
    bool
    PointBins<dim>::any_near(const Box<dim> &box) const
    {
      return visit_near(box, [](const Point<dim> &) { return true; });
    }

    template <int dim>
    void
    mark_cells_near(const FEZone<dim>             &fe_zone,
                    const std::vector<Point<dim>> &points,
                    const double                   distance,
                    std::vector<bool>             &convert)
    {
      if (points.empty())
        return;
      const PointBins<dim> bins(points, distance);
      for (const auto &cell : fe_zone.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0 &&
            bins.any_near(cell_box<dim>(cell)))
          convert[cell->active_cell_index()] = true;
    }

    template <int dim>
    std::vector<Point<dim>>
    gather_points(const std::vector<Point<dim>> &local, const MPI_Comm communicator)
    {
      std::vector<double> mine(dim * local.size());
      for (unsigned int i = 0; i < local.size(); ++i)
        for (unsigned int d = 0; d < dim; ++d)
          mine[dim * i + d] = local[i][d];
      const std::vector<double> all = gather_values(mine, communicator);
      std::vector<Point<dim>>   points(all.size() / dim);
      for (unsigned int i = 0; i < points.size(); ++i)
        for (unsigned int d = 0; d < dim; ++d)
          points[i][d] = all[dim * i + d];
      return points;
    }

    template class PointBins<2>;
    template class PointBins<3>;
    template void
    mark_cells_near(const FEZone<2> &,
                    const std::vector<Point<2>> &,
                    const double,
                    std::vector<bool> &);
    template void
    mark_cells_near(const FEZone<3> &,
                    const std::vector<Point<3>> &,
                    const double,
                    std::vector<bool> &);
    template std::vector<Point<2>>
    gather_points(const std::vector<Point<2>> &, const MPI_Comm);
    template std::vector<Point<3>>
    gather_points(const std::vector<Point<3>> &, const MPI_Comm);
  } // namespace internal

  template <int dim>
  void
  ConversionCriterion<dim>::parse_parameters(ParameterHandler &)
  {}

  template <int dim>
  void
  ConversionCriterion<dim>::initialize(const FEZone<dim> &,
                                       const PDZone<dim> &,
                                       const GrowthContext &)
  {}

  template <int dim>
  void
  DamageProximityCriterion<dim>::entries(ParameterEntries &entries)
  {
    entries.add("Distance",
                distance,
                Patterns::Double(0),
                "FE cells closer than this to a damaged particle become PD. 0 (the default): "
                "automatic, the trigger distance (two bond reaches, 2 (delta + dx/2), plus the "
                "distance a longitudinal wave runs in a step) plus the distance a crack can "
                "run between two checks at the shear-wave speed (c_s dt Check interval). A "
                "value given must reach the trigger distance; a smaller margin over it makes "
                "growths more frequent, a larger one the zone larger [m].");
    entries.add("Damage threshold",
                damage_threshold,
                Patterns::Double(0, 1),
                "A particle counts as damaged when its damage (broken share of its bond "
                "volume) exceeds this [-].");
  }

  template <int dim>
  void
  DamageProximityCriterion<dim>::declare_parameters(ParameterHandler &prm)
  {
    ParameterEntries::declare_here<DamageProximityCriterion<dim>>(prm);
  }

  template <int dim>
  void
  DamageProximityCriterion<dim>::parse_parameters(ParameterHandler &prm)
  {
    ParameterEntries::parse_here(prm, *this, "Adaptive PD zone/damage distance/");
  }

  template <int dim>
  void
  DamageProximityCriterion<dim>::initialize(const FEZone<dim> &,
                                            const PDZone<dim>   &pd_zone,
                                            const GrowthContext &context)
  {
    AssertThrow(pd_zone.get_parameters().fracture,
                ExcMessage("Invalid input: parameter 'Adaptive PD zone/Conversion criterion' = "
                           "'damage distance'; allowed: a criterion that needs no damage "
                           "(strain), since 'Peridynamics/Fracture' is off."));
    if (distance == 0)
      distance = context.conversion_distance();
    else if (distance < context.trigger_distance)
      {
        std::ostringstream allowed;
        allowed << "0 (automatic: " << context.conversion_distance()
                << " m here) or at least the trigger distance, two bond reaches 2 (delta + "
                   "dx/2) plus a longitudinal wave's run in a step, "
                << context.trigger_distance
                << " m: damage closer to the overlap than two bond reaches stops a coupled run";
        throw_invalid_parameter("Adaptive PD zone/damage distance/Distance",
                                distance,
                                allowed.str());
      }
  }

  template <int dim>
  void
  DamageProximityCriterion<dim>::mark_cells(const FEZone<dim> &fe_zone,
                                            const PDZone<dim> &pd_zone,
                                            std::vector<bool> &convert) const
  {
    const auto              x = pd_zone.reference_positions();
    std::vector<Point<dim>> damaged;
    for (const auto &[i, damage] : pd_zone.get_bonds().damaged_particles())
      if (damage > damage_threshold)
        damaged.push_back(x[i]);
    damaged = internal::gather_points(damaged, pd_zone.get_communicator());
    internal::mark_cells_near(fe_zone, damaged, distance, convert);
  }

  template <int dim>
  void
  StrainCriterion<dim>::entries(ParameterEntries &entries)
  {
    entries.add("Strain",
                strain_threshold,
                Patterns::Double(0),
                "FE cells whose largest principal strain at a Gauss point reaches this become "
                "PD; 0: use Fraction of critical stretch [-].");
    entries.add("Fraction of critical stretch",
                stretch_fraction,
                Patterns::Double(0),
                "With Strain = 0, the threshold is this fraction of the critical stretch of "
                "Peridynamics/Fracture criterion [-].");
    entries.add("Buffer",
                buffer,
                Patterns::Double(0),
                "FE cells within this distance of a cell over the threshold become PD with it. "
                "0 (the default): the growth's trigger distance, two bond reaches and a "
                "wave's run in a step, the least room a crack needs to start inside the zone "
                "without reaching the overlap at once [m].");
  }

  template <int dim>
  void
  StrainCriterion<dim>::declare_parameters(ParameterHandler &prm)
  {
    ParameterEntries::declare_here<StrainCriterion<dim>>(prm);
  }

  template <int dim>
  void
  StrainCriterion<dim>::parse_parameters(ParameterHandler &prm)
  {
    ParameterEntries::parse_here(prm, *this, "Adaptive PD zone/strain/");
  }

  template <int dim>
  void
  StrainCriterion<dim>::initialize(const FEZone<dim> &,
                                   const PDZone<dim>   &pd_zone,
                                   const GrowthContext &context)
  {
    if (buffer == 0)
      buffer = context.trigger_distance;
    loaded_boundaries = context.loaded_boundaries;
    if (strain_threshold > 0)
      return;
    strain_threshold = stretch_fraction * pd_zone.get_critical_stretch();
    if (!(strain_threshold > 0))
      throw_invalid_parameter("Adaptive PD zone/strain/Strain",
                              0,
                              "a positive strain, unless the fracture criterion has a critical "
                              "stretch (Peridynamics/Fracture criterion = critical stretch) "
                              "and Fraction of critical stretch is positive");
  }

  template <int dim>
  void
  StrainCriterion<dim>::mark_cells(const FEZone<dim> &fe_zone,
                                   const PDZone<dim> &pd_zone,
                                   std::vector<bool> &convert) const
  {
    const unsigned int        degree = fe_zone.get_dof_handler().get_fe(0).degree;
    const std::vector<double> strain = fe_zone.largest_principal_strains(QGauss<dim>(degree + 1));
    std::vector<bool>         flagged(convert.size(), false);
    std::vector<Point<dim>>   strained;
    for (const auto &cell : fe_zone.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && strain[cell->active_cell_index()] >= strain_threshold)
        {
          flagged[cell->active_cell_index()] = true;
          strained.push_back(cell->center());
        }
    if (buffer > 0)
      {
        // Measured from the flagged cells' centres: half a cell is added to the buffer.
        strained = internal::gather_points(strained, pd_zone.get_communicator());
        const double half_cell =
          0.5 * fe_zone.get_dof_handler().begin_active()->diameter() / std::sqrt(dim);
        internal::mark_cells_near(fe_zone, strained, buffer + half_cell, flagged);
      }
    const auto on_loaded_boundary = [&](const auto &cell) {
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && loaded_boundaries.count(face->boundary_id()) > 0)
          return true;
      return false;
    };
    for (const auto &cell : fe_zone.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && flagged[cell->active_cell_index()] &&
          !on_loaded_boundary(cell))
        convert[cell->active_cell_index()] = true;
  }

  template <int dim>
  void
  CellCentreCriterion<dim>::mark_cells(const FEZone<dim> &fe_zone,
                                       const PDZone<dim> &,
                                       std::vector<bool> &convert) const
  {
    for (const auto &cell : fe_zone.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        convert[cell->active_cell_index()] = converts(cell->center());
  }

  template class ConversionCriterion<2>;
  template class ConversionCriterion<3>;
  template class CellCentreCriterion<2>;
  template class CellCentreCriterion<3>;
  template class DamageProximityCriterion<2>;
  template class DamageProximityCriterion<3>;
  template class StrainCriterion<2>;
  template class StrainCriterion<3>;
  template class PluginRegistry<ConversionCriterion<2>>;
  template class PluginRegistry<ConversionCriterion<3>>;

  PERIARLEQUIN_REGISTER_CONVERSION_CRITERION(DamageProximityCriterion,
                                             "damage distance",
                                             "FE cells within a distance of a damaged particle "
                                             "become PD")
  PERIARLEQUIN_REGISTER_CONVERSION_CRITERION(StrainCriterion,
                                             "strain",
                                             "FE cells whose largest principal strain reaches a "
                                             "threshold (and their neighbours) become PD")
} // namespace PeriArlequin
