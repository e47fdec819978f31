#include <periarlequin/coupling/multiplier_space.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

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
                                                    const MPI_Comm communicator)
    : overlap(overlap)
  {
    this->reinit_partitioner(dim * overlap.n_rows(), communicator);
  }

  template <int dim>
  void
  StrictMultiplierSpace<dim>::apply_h(const VectorType &lambda, Values &p)
  {
    p.resize(overlap.n_rows());
    for (unsigned int r = 0; r < overlap.n_rows(); ++r)
      for (unsigned int d = 0; d < dim; ++d)
        p[r][d] = lambda.local_element(dim * r + d);
  }

  template <int dim>
  void
  StrictMultiplierSpace<dim>::apply_transpose_h(const Values &s, VectorType &y)
  {
    for (unsigned int r = 0; r < overlap.n_rows(); ++r)
      for (unsigned int d = 0; d < dim; ++d)
        y.local_element(dim * r + d) = s[r][d];
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
          sum[entry.component] +=
            entry.value * entry.value * fe_weights.local_element(entry.dof);
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
        fe_scratch.local_element(entry.dof) += 1.;
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
    const auto &partitioner = *fe_weights.get_partitioner();
    TrilinosWrappers::SparseMatrix B;
    fe_zone.reinit_matrix(B);
    VectorType second_term;
    fe_zone.initialize_vector(second_term);
    for (unsigned int r = 0; r < overlap.n_rows(); ++r)
      for (const auto &m : overlap.row(r))
        {
          second_term.local_element(m.dof) += m.value * m.value * pd_weights[r];
          for (const auto &J : overlap.row(r))
            if (J.component == m.component)
              B.add(partitioner.local_to_global(m.dof),
                    partitioner.local_to_global(J.dof),
                    m.value * J.value);
        }
    B.compress(VectorOperation::add);
    second_term.compress(VectorOperation::add);
    for (unsigned int k = 0; k < multiplier_dofs.size(); ++k)
      {
        const types::global_dof_index m = partitioner.local_to_global(multiplier_dofs[k]);
        double                        sum = second_term.local_element(multiplier_dofs[k]);
        for (auto entry = B.begin(m); entry != B.end(m); ++entry)
          sum += entry->value() * entry->value() * fe_weights(entry->column());
        diagonal.local_element(k) = sum;
      }
  }

  template class MultiplierSpace<2>;
  template class MultiplierSpace<3>;
  template class StrictMultiplierSpace<2>;
  template class StrictMultiplierSpace<3>;
  template class WeakMultiplierSpace<2>;
  template class WeakMultiplierSpace<3>;
} // namespace PeriArlequin
