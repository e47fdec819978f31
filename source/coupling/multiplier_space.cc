#include <periarlequin/base/parameters.h>
#include <periarlequin/coupling/multiplier_space.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace PeriArlequin
{
  template <int dim>
  void
  MultiplierSpace<dim>::initialize_vector(VectorType &lambda) const
  {
    lambda.reinit(partitioner);
  }

  template <int dim>
  void
  MultiplierSpace<dim>::reinit_partitioner(const unsigned int n_owned, const MPI_Comm communicator)
  {
    partitioner = std::make_shared<Utilities::MPI::Partitioner>(n_owned, 0, communicator);
  }

  template <int dim>
  StrictMultiplierSpace<dim>::StrictMultiplierSpace(const InterpolationOperator<dim> &overlap,
                                                    const MPI_Comm                    communicator)
    : overlap(overlap)
  {
    this->reinit_partitioner(dim * overlap.n_rows(), communicator);
  }

  template <int dim>
  void
  StrictMultiplierSpace<dim>::apply_h(const VectorType &lambda, Values &p)
  {
    p.resize(overlap.n_rows());
    overlap.for_each_row_range([&](const unsigned int first, const unsigned int end) {
      for (unsigned int r = first; r < end; ++r)
        for (unsigned int d = 0; d < dim; ++d)
          p[r][d] = lambda.local_element(dim * r + d);
    });
  }

  template <int dim>
  void
  StrictMultiplierSpace<dim>::apply_transpose_h(const Values &s, VectorType &y)
  {
    overlap.for_each_row_range([&](const unsigned int first, const unsigned int end) {
      for (unsigned int r = first; r < end; ++r)
        for (unsigned int d = 0; d < dim; ++d)
          y.local_element(dim * r + d) = s[r][d];
    });
  }

  template <int dim>
  void
  StrictMultiplierSpace<dim>::diagonal_of_projection(const VectorType          &fe_weights,
                                                     const std::vector<double> &pd_weights,
                                                     VectorType                &diagonal) const
  {
    // Row (I, d): sum_J N_IJ^2 W_J over the DoFs of component d, plus P_I.
    for (unsigned int r = 0; r < overlap.n_rows(); ++r)
      {
        Tensor<1, dim> sum;
        for (const auto &entry : overlap.row(r))
          for (unsigned int d = 0; d < dim; ++d)
            sum[d] += entry.value * entry.value * fe_weights.local_element(entry.dofs[d]);
        for (unsigned int d = 0; d < dim; ++d)
          diagonal.local_element(dim * r + d) = sum[d] + pd_weights[r];
      }
  }

  template <int dim>
  WeakMultiplierSpace<dim>::WeakMultiplierSpace(const InterpolationOperator<dim> &overlap,
                                                const FEZone<dim>                &fe_zone)
    : overlap(overlap)
    , fe_zone(fe_zone)
  {
    fe_zone.initialize_vector(fe_scratch);
    fe_scratch = 0.;
    for (unsigned int r = 0; r < overlap.n_rows(); ++r)
      for (const auto &entry : overlap.row(r))
        for (const unsigned int dof : entry.dofs)
          fe_scratch.local_element(dof) += 1.;
    fe_scratch.compress(VectorOperation::add);
    for (unsigned int i = 0; i < fe_scratch.locally_owned_size(); ++i)
      if (fe_scratch.local_element(i) > 0)
        multiplier_dofs.push_back(i);
    this->reinit_partitioner(multiplier_dofs.size(), fe_scratch.get_mpi_communicator());
  }

  template <int dim>
  void
  WeakMultiplierSpace<dim>::apply_h(const VectorType &lambda, Values &p)
  {
    fe_scratch = 0.;
    for (unsigned int m = 0; m < multiplier_dofs.size(); ++m)
      fe_scratch.local_element(multiplier_dofs[m]) = lambda.local_element(m);
    fe_scratch.update_ghost_values();
    overlap.vmult(p, fe_scratch);
  }

  template <int dim>
  void
  WeakMultiplierSpace<dim>::apply_transpose_h(const Values &s, VectorType &y)
  {
    overlap.Tvmult(fe_scratch, s);
    for (unsigned int m = 0; m < multiplier_dofs.size(); ++m)
      y.local_element(m) = fe_scratch.local_element(multiplier_dofs[m]);
  }

  template <int dim>
  void
  WeakMultiplierSpace<dim>::diagonal_of_projection(const VectorType          &fe_weights,
                                                   const std::vector<double> &pd_weights,
                                                   VectorType                &diagonal) const
  {
    // B = N^T N couples DoFs of a common cell: the FE zone's pattern holds it.
    const auto                    &partitioner = *fe_weights.get_partitioner();
    TrilinosWrappers::SparseMatrix B;
    fe_zone.reinit_matrix(B);
    VectorType second_term;
    fe_zone.initialize_vector(second_term);
    for (unsigned int r = 0; r < overlap.n_rows(); ++r)
      for (const auto &m : overlap.row(r))
        for (unsigned int d = 0; d < dim; ++d)
          {
            second_term.local_element(m.dofs[d]) += m.value * m.value * pd_weights[r];
            for (const auto &J : overlap.row(r))
              B.add(partitioner.local_to_global(m.dofs[d]),
                    partitioner.local_to_global(J.dofs[d]),
                    m.value * J.value);
          }
    B.compress(VectorOperation::add);
    second_term.compress(VectorOperation::add);
    for (unsigned int k = 0; k < multiplier_dofs.size(); ++k)
      {
        const types::global_dof_index m   = partitioner.local_to_global(multiplier_dofs[k]);
        double                        sum = second_term.local_element(multiplier_dofs[k]);
        for (auto entry = B.begin(m); entry != B.end(m); ++entry)
          sum += entry->value() * entry->value() * fe_weights(entry->column());
        diagonal.local_element(k) = sum;
      }
  }

  template <int dim>
  GridMultiplierSpace<dim>::GridMultiplierSpace(const InterpolationOperator<dim> &overlap,
                                                const FEZone<dim>                &fe_zone,
                                                const std::vector<Point<dim>>    &positions,
                                                const double                      spacing_in_cells,
                                                const double                      offset)
    : overlap(overlap)
    , fe_zone(fe_zone)
  {
    const MPI_Comm     communicator = fe_zone.get_dof_handler().get_communicator();
    const unsigned int n_ranks      = Utilities::MPI::n_mpi_processes(communicator);
    const unsigned int rank         = Utilities::MPI::this_mpi_process(communicator);

    // The grid: from the lower corner of all overlap nodes, enough cells to hold them.
    std::array<double, dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = std::numeric_limits<double>::max();
        upper[d] = std::numeric_limits<double>::lowest();
        for (const auto &x : positions)
          {
            lower[d] = std::min(lower[d], x[d]);
            upper[d] = std::max(upper[d], x[d]);
          }
        lower[d] = Utilities::MPI::min(lower[d], communicator);
        upper[d] = Utilities::MPI::max(upper[d], communicator);
      }
    // The largest FE cell extent among the cells that reach the overlap nodes' box.
    double cell_extent = 0;
    for (const auto &cell : fe_zone.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0)
        {
          const BoundingBox<dim> box  = cell->bounding_box();
          bool                   near = true;
          for (unsigned int d = 0; d < dim; ++d)
            near = near && box.upper_bound(d) >= lower[d] && box.lower_bound(d) <= upper[d];
          if (near)
            for (unsigned int d = 0; d < dim; ++d)
              cell_extent = std::max(cell_extent, box.side_length(d));
        }
    cell_extent          = Utilities::MPI::max(cell_extent, communicator);
    const double spacing = spacing_in_cells * cell_extent;
    for (unsigned int d = 0; d < dim; ++d)
      lower[d] -= offset * spacing;

    std::array<types::global_dof_index, dim> n_cells, n_nodes;
    for (unsigned int d = 0; d < dim; ++d)
      {
        n_cells[d] =
          std::max<types::global_dof_index>(1,
                                            static_cast<types::global_dof_index>(
                                              std::ceil((upper[d] - lower[d]) / spacing - 1e-9)));
        n_nodes[d] = n_cells[d] + 1;
      }

    // Each overlap node's hats: the corners of its grid cell, by lexicographic grid index.
    std::vector<types::global_dof_index> row_nodes;
    std::vector<double>                  row_values;
    for (const auto &x : positions)
      {
        std::array<types::global_dof_index, dim> cell;
        std::array<double, dim>                  local;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double scaled = (x[d] - lower[d]) / spacing;
            cell[d] =
              std::min<types::global_dof_index>(static_cast<types::global_dof_index>(scaled),
                                                n_cells[d] - 1);
            local[d] = scaled - cell[d];
          }
        for (unsigned int corner = 0; corner < (1u << dim); ++corner)
          {
            double                  value = 1;
            types::global_dof_index index = 0, stride = 1;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const bool upper_corner = (corner >> d) & 1u;
                value *= upper_corner ? local[d] : 1. - local[d];
                index += (cell[d] + (upper_corner ? 1 : 0)) * stride;
                stride *= n_nodes[d];
              }
            if (value > 0)
              {
                row_nodes.push_back(index);
                row_values.push_back(value);
              }
          }
        row_begin.push_back(row_nodes.size());
      }

    // The grid nodes that any rank reaches, numbered in lexicographic order and owned in
    // contiguous, equal ranges.
    std::vector<types::global_dof_index> reached = row_nodes;
    std::sort(reached.begin(), reached.end());
    reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
    std::vector<types::global_dof_index> nodes;
    for (const auto &part : Utilities::MPI::all_gather(communicator, reached))
      nodes.insert(nodes.end(), part.begin(), part.end());
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    const types::global_dof_index n_global = nodes.size();
    const types::global_dof_index first    = n_global * rank / n_ranks;
    const types::global_dof_index end      = n_global * (rank + 1) / n_ranks;
    this->reinit_partitioner(dim * (end - first), communicator);

    const auto number = [&nodes](const types::global_dof_index lexicographic) {
      return static_cast<types::global_dof_index>(
        std::lower_bound(nodes.begin(), nodes.end(), lexicographic) - nodes.begin());
    };
    IndexSet owned(dim * n_global), ghosts(dim * n_global);
    owned.add_range(dim * first, dim * end);
    for (const auto lexicographic : reached)
      {
        const types::global_dof_index k = number(lexicographic);
        if (k < first || k >= end)
          ghosts.add_range(dim * k, dim * (k + 1));
      }
    ghosted.reinit(owned, ghosts, communicator);
    const auto &ghosted_partitioner = *ghosted.get_partitioner();
    for (unsigned int e = 0; e < row_nodes.size(); ++e)
      entries.push_back(
        {ghosted_partitioner.global_to_local(dim * number(row_nodes[e])), row_values[e]});
    std::vector<typename TransposedRows<dim>::Term> terms;
    for (unsigned int r = 0; r + 1 < row_begin.size(); ++r)
      for (unsigned int e = row_begin[r]; e < row_begin[r + 1]; ++e)
        for (unsigned int d = 0; d < dim; ++d)
          terms.push_back({r, d, entries[e].node + d, entries[e].value});
    transpose.reinit(terms,
                     ghosted_partitioner.locally_owned_size() +
                       ghosted_partitioner.n_ghost_indices());

    // Colours: nodes of one colour are stride cells apart in some direction, farther than
    // twice the reach of a multiplier (its hat, H, and the FE cells there, h <= H).
    const unsigned int stride = 3 + static_cast<unsigned int>(std::ceil(2. / spacing_in_cells));
    n_colours                 = Utilities::pow(stride, dim);
    for (types::global_dof_index k = first; k < end; ++k)
      {
        types::global_dof_index rest   = nodes[k];
        unsigned int            colour = 0, factor = 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            colour += (rest % n_nodes[d]) % stride * factor;
            rest /= n_nodes[d];
            factor *= stride;
          }
        colours.push_back(colour);
      }
  }

  template <int dim>
  void
  GridMultiplierSpace<dim>::evaluate(const VectorType &lambda, Values &p) const
  {
    for (unsigned int m = 0; m < lambda.locally_owned_size(); ++m)
      ghosted.local_element(m) = lambda.local_element(m);
    ghosted.update_ghost_values();
    p.assign(row_begin.size() - 1, Tensor<1, dim>());
    overlap.for_each_row_range([&](const unsigned int first, const unsigned int end) {
      for (unsigned int r = first; r < end; ++r)
        for (unsigned int e = row_begin[r]; e < row_begin[r + 1]; ++e)
          for (unsigned int d = 0; d < dim; ++d)
            p[r][d] += entries[e].value * ghosted.local_element(entries[e].node + d);
    });
  }

  template <int dim>
  void
  GridMultiplierSpace<dim>::evaluate_transpose(const Values &s, VectorType &y) const
  {
    ghosted = 0.;
    transpose.add_to(ghosted, s);
    ghosted.compress(VectorOperation::add);
    for (unsigned int m = 0; m < y.locally_owned_size(); ++m)
      y.local_element(m) = ghosted.local_element(m);
  }

  template <int dim>
  void
  GridMultiplierSpace<dim>::apply_h(const VectorType &lambda, Values &p)
  {
    evaluate(lambda, p);
  }

  template <int dim>
  void
  GridMultiplierSpace<dim>::apply_transpose_h(const Values &s, VectorType &y)
  {
    evaluate_transpose(s, y);
  }

  template <int dim>
  void
  GridMultiplierSpace<dim>::diagonal_of_projection(const VectorType          &fe_weights,
                                                   const std::vector<double> &pd_weights,
                                                   VectorType                &diagonal) const
  {
    VectorType indicator, product;
    this->initialize_vector(indicator);
    this->initialize_vector(product);
    VectorType fe_values;
    fe_zone.initialize_vector(fe_values);
    Values at_nodes, weighted;
    diagonal = 0.;
    for (unsigned int colour = 0; colour < n_colours; ++colour)
      {
        for (unsigned int k = 0; k < colours.size(); ++k)
          for (unsigned int d = 0; d < dim; ++d)
            indicator.local_element(dim * k + d) = colours[k] == colour ? 1. : 0.;
        // (H^T (N W N^T + P) H) indicator, as MultiplierSolver applies A.
        evaluate(indicator, at_nodes);
        overlap.Tvmult(fe_values, at_nodes);
        fe_values.scale(fe_weights);
        fe_values.update_ghost_values();
        overlap.vmult(weighted, fe_values);
        for (unsigned int r = 0; r < weighted.size(); ++r)
          weighted[r] += pd_weights[r] * at_nodes[r];
        evaluate_transpose(weighted, product);
        for (unsigned int k = 0; k < colours.size(); ++k)
          if (colours[k] == colour)
            for (unsigned int d = 0; d < dim; ++d)
              diagonal.local_element(dim * k + d) = product.local_element(dim * k + d);
      }
  }

  template class MultiplierSpace<2>;
  template class MultiplierSpace<3>;
  template class StrictMultiplierSpace<2>;
  template class StrictMultiplierSpace<3>;
  template class WeakMultiplierSpace<2>;
  template class WeakMultiplierSpace<3>;
  template class GridMultiplierSpace<2>;
  template class GridMultiplierSpace<3>;
} // namespace PeriArlequin
