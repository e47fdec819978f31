#include <periarlequin/base/parallel_loops.h>
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

    // The rows on the threads (a point's cell, DoFs and shape values each): every chunk of
    // particles lists its nonzero entries and row lengths, joined in order after.
    struct ChunkRows
    {
      std::vector<Entry>        entries;
      std::vector<unsigned int> lengths;
    };
    std::vector<ChunkRows> chunks(max_fixed_chunks);
    const unsigned int     n_chunks = for_each_fixed_chunk(
      particles.size(),
      [&](const unsigned int c, const unsigned int first, const unsigned int end) {
        ChunkRows                           &rows = chunks[c];
        std::vector<types::global_dof_index> dof_indices;
        std::vector<Entry>                   cell_entries;
        for (unsigned int p = first; p < end; ++p)
          {
            const unsigned int i                         = particles[p];
            const auto &[triangulation_cell, unit_point] = locations[i];
            const typename DoFHandler<dim>::active_cell_iterator cell(
              &dof_handler.get_triangulation(),
              triangulation_cell->level(),
              triangulation_cell->index(),
              &dof_handler);
            const auto &fe = cell->get_fe();
            if (fe.n_dofs_per_cell() == 0)
              {
                const auto         corners = cell->bounding_box().get_boundary_points();
                std::ostringstream message;
                message << "The PD particle at (" << pd_zone.reference_positions()[i]
                        << ") m is coupled to the FE field, but its cell, from (" << corners.first
                        << ") to (" << corners.second
                        << ") m, has its centre in Peridynamics/Region and so no FE unknowns: "
                               "the overlap and the slave layer must lie in FE cells. Put the "
                               "boundary of Peridynamics/Region on faces of the cells.";
                AssertThrow(false, ExcMessage(message.str()));
              }
            // The FE zone's element is dim copies of one scalar element: node j of the scalar
            // element carries the DoF of component c of copy c.
            AssertThrow(fe.n_base_elements() == 1 && fe.element_multiplicity(0) == dim,
                        ExcInternalError());
            const auto &base = fe.base_element(0);
            dof_indices.resize(fe.n_dofs_per_cell());
            cell->get_dof_indices(dof_indices);
            cell_entries.resize(base.n_dofs_per_cell());
            for (unsigned int j = 0; j < base.n_dofs_per_cell(); ++j)
              cell_entries[j].value = base.shape_value(j, unit_point);
            for (unsigned int k = 0; k < dof_indices.size(); ++k)
              {
                const auto [base_and_copy, node] = fe.system_to_base_index(k);
                cell_entries[node].dofs[base_and_copy.second] =
                  static_cast<unsigned int>(partitioner.global_to_local(dof_indices[k]));
              }
            unsigned int length = 0;
            for (const Entry &entry : cell_entries)
              if (entry.value != 0)
                {
                  rows.entries.push_back(entry);
                  ++length;
                }
            rows.lengths.push_back(length);
          }
      });
    row_begin.assign(1, 0);
    row_begin.reserve(particles.size() + 1);
    std::size_t n_entries = 0;
    for (unsigned int c = 0; c < n_chunks; ++c)
      n_entries += chunks[c].entries.size();
    entries.clear();
    entries.reserve(n_entries);
    for (unsigned int c = 0; c < n_chunks; ++c)
      {
        entries.insert(entries.end(), chunks[c].entries.begin(), chunks[c].entries.end());
        for (const unsigned int length : chunks[c].lengths)
          row_begin.push_back(row_begin.back() + length);
      }

    std::vector<typename TransposedRows<dim>::Term> terms;
    terms.reserve(dim * entries.size());
    for (unsigned int r = 0; r < n_rows(); ++r)
      for (const Entry &entry : row(r))
        for (unsigned int d = 0; d < dim; ++d)
          terms.push_back({r, d, entry.dofs[d], entry.value});
    transpose.reinit(terms, partitioner.locally_owned_size() + partitioner.n_ghost_indices());
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
      for (unsigned int d = 0; d < dim; ++d)
        value[d] += entry.value * x.local_element(entry.dofs[d]);
    return value;
  }

  template <int dim>
  void
  InterpolationOperator<dim>::vmult(Values &values, const VectorType &x) const
  {
    values.resize(n_rows());
    for_each_row_range([&](const unsigned int first, const unsigned int end) {
      for (unsigned int r = first; r < end; ++r)
        values[r] = interpolate(x, r);
    });
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
    transpose.add_to(x, values);
    x.compress(VectorOperation::add);
  }

  template class InterpolationOperator<2>;
  template class InterpolationOperator<3>;
} // namespace PeriArlequin
