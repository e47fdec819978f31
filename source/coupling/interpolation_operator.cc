#include <periarlequin/coupling/interpolation_operator.h>

#include <deal.II/fe/fe.h>

#include <sstream>

namespace PeriArlequin
{
  template <int dim>
  void
  InterpolationOperator<dim>::reinit(const FEZone<dim>               &fe_zone,
                                     const PDZone<dim>               &pd_zone,
                                     const std::vector<unsigned int> &particles)
  {
    const auto &dof_handler = fe_zone.get_dof_handler();
    VectorType  layout;
    fe_zone.initialize_vector(layout);
    const auto &partitioner = *layout.get_partitioner();
    const auto  locations   = pd_zone.owned_particle_locations();

    row_begin.clear();
    row_begin.reserve(particles.size() + 1);
    row_begin.push_back(0);
    entries.clear();
    entries.reserve(particles.size() * dof_handler.get_fe_collection().max_dofs_per_cell());
    std::vector<types::global_dof_index> dof_indices;
    // The shape functions of a vector element are those of its base elements: each base
    // function is evaluated once a particle, not once per component.
    std::vector<std::vector<double>> base_values;
    for (const unsigned int i : particles)
      {
        const auto &[triangulation_cell, unit_point] = locations[i];
        const typename DoFHandler<dim>::active_cell_iterator cell(&dof_handler.get_triangulation(),
                                                                  triangulation_cell->level(),
                                                                  triangulation_cell->index(),
                                                                  &dof_handler);
        const auto                                          &fe = cell->get_fe();
        if (fe.n_dofs_per_cell() == 0)
          {
            std::ostringstream where;
            where << pd_zone.reference_positions()[i];
            AssertThrow(false,
                        ExcMessage("The PD particle at " + where.str() +
                                   " is coupled to the FE field but its cell has no FE "
                                   "unknowns: the overlap and the slave layer must lie in FE "
                                   "cells (cells whose centre is outside Peridynamics/Region)."));
          }
        dof_indices.resize(fe.n_dofs_per_cell());
        cell->get_dof_indices(dof_indices);
        base_values.resize(fe.n_base_elements());
        for (unsigned int b = 0; b < fe.n_base_elements(); ++b)
          {
            const auto &base = fe.base_element(b);
            base_values[b].resize(base.n_dofs_per_cell());
            for (unsigned int j = 0; j < base.n_dofs_per_cell(); ++j)
              base_values[b][j] = base.shape_value(j, unit_point);
          }
        for (unsigned int k = 0; k < dof_indices.size(); ++k)
          {
            const auto [base_and_copy, base_dof] = fe.system_to_base_index(k);
            const double value                   = base_values[base_and_copy.first][base_dof];
            if (value != 0)
              entries.push_back(
                {static_cast<unsigned int>(partitioner.global_to_local(dof_indices[k])),
                 fe.system_to_component_index(k).first,
                 value});
          }
        row_begin.push_back(entries.size());
      }
  }

  template <int dim>
  unsigned int
  InterpolationOperator<dim>::n_rows() const
  {
    return row_begin.size() - 1;
  }

  template <int dim>
  ArrayView<const typename InterpolationOperator<dim>::Entry>
  InterpolationOperator<dim>::row(const unsigned int r) const
  {
    return ArrayView<const Entry>(entries.data() + row_begin[r], row_begin[r + 1] - row_begin[r]);
  }

  template <int dim>
  Tensor<1, dim>
  InterpolationOperator<dim>::interpolate(const VectorType &x, const unsigned int r) const
  {
    Tensor<1, dim> value;
    for (const Entry &entry : row(r))
      value[entry.component] += entry.value * x.local_element(entry.dof);
    return value;
  }

  template <int dim>
  void
  InterpolationOperator<dim>::vmult(Values &values, const VectorType &x) const
  {
    values.resize(n_rows());
    for (unsigned int r = 0; r < n_rows(); ++r)
      values[r] = interpolate(x, r);
  }

  template <int dim>
  void
  InterpolationOperator<dim>::Tvmult(VectorType &x, const Values &values) const
  {
    x = 0.;
    Tvmult_add(x, values);
  }

  template <int dim>
  void
  InterpolationOperator<dim>::Tvmult_add(VectorType &x, const Values &values) const
  {
    for (unsigned int r = 0; r < n_rows(); ++r)
      for (const Entry &entry : row(r))
        x.local_element(entry.dof) += entry.value * values[r][entry.component];
    x.compress(VectorOperation::add);
  }

  template class InterpolationOperator<2>;
  template class InterpolationOperator<3>;
} // namespace PeriArlequin
