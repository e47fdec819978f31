#include <periarlequin/coupling/arlequin_coupling.h>

#include <cmath>
#include <sstream>

namespace PeriArlequin
{
  template <int dim>
  ArlequinCoupling<dim>::ArlequinCoupling(const Parameters::Coupling &parameters,
                                          const BlendingField<dim>   &blending,
                                          const Parameters::Material &material,
                                          FEZone<dim>                &fe_zone,
                                          PDZone<dim>                &pd_zone)
    : parameters(parameters)
    , blending(blending)
    , material(material)
    , fe_zone(fe_zone)
    , pd_zone(pd_zone)
    , communicator(fe_zone.get_dof_handler().get_communicator())
  {}

  template <int dim>
  void
  ArlequinCoupling<dim>::setup(const double dt)
  {
    using Parameters::CouplingMethod;
    time_step              = dt;
    const auto &dof_handler = fe_zone.get_dof_handler();
    fe_zone.initialize_vector(fe_scratch);
    fe_zone.initialize_vector(fe_scratch_2);
    fe_zone.initialize_vector(inverse_mass);
    const auto &partitioner = *fe_scratch.get_partitioner();

    // Interpolation rows of the overlap PD nodes (0 < alpha < 1) and of the slaves.
    const auto cells = pd_zone.owned_particle_cells();
    std::vector<types::global_dof_index> dof_indices;
    row_begin = {0};
    for (unsigned int i = 0; i < pd_zone.n_owned; ++i)
      {
        const double alpha   = pd_zone.alpha[i];
        const bool   slave   = pd_zone.is_slave[i];
        const bool   overlap = parameters.method != CouplingMethod::bad && alpha > 0 && alpha < 1;
        if (!slave && !overlap)
          continue;
        const typename DoFHandler<dim>::active_cell_iterator cell(
          &dof_handler.get_triangulation(), cells[i]->level(), cells[i]->index(), &dof_handler);
        const auto &fe = cell->get_fe();
        if (fe.n_dofs_per_cell() == 0)
          {
            std::ostringstream where;
            where << pd_zone.reference_position[i];
            AssertThrow(false,
                        ExcMessage("The PD particle at " + where.str() +
                                   " is coupled to the FE field but its cell has no FE "
                                   "unknowns: the overlap and the slave layer must lie in FE "
                                   "cells (cells whose centre is outside Peridynamics/Region)."));
          }
        const Point<dim> lower = cell->vertex(0);
        const Point<dim> upper = cell->vertex(GeometryInfo<dim>::vertices_per_cell - 1);
        Point<dim>       unit;
        for (unsigned int d = 0; d < dim; ++d)
          unit[d] = (pd_zone.reference_position[i][d] - lower[d]) / (upper[d] - lower[d]);
        dof_indices.resize(fe.n_dofs_per_cell());
        cell->get_dof_indices(dof_indices);
        for (unsigned int k = 0; k < dof_indices.size(); ++k)
          {
            const double value = fe.shape_value(k, unit);
            if (value != 0)
              entries.push_back({static_cast<unsigned int>(
                                   partitioner.global_to_local(dof_indices[k])),
                                 fe.system_to_component_index(k).first,
                                 value});
          }
        (slave ? slave_rows : overlap_rows).push_back(row_particle.size());
        row_particle.push_back(i);
        row_begin.push_back(entries.size());
      }

    std::vector<unsigned int> support_dofs, components;
    std::vector<Point<dim>>   points;
    fe_zone.support_points(support_dofs, points, components);
    alpha_at_dofs.assign(fe_scratch.locally_owned_size(), 1.);
    for (unsigned int k = 0; k < support_dofs.size(); ++k)
      alpha_at_dofs[support_dofs[k]] = blending.value(points[k]);

    if (parameters.method == CouplingMethod::bad)
      {
        // FE DoFs of the PD-side half of the overlap follow the PD field.
        for (unsigned int k = 0; k < support_dofs.size(); ++k)
          if (blending.in_overlap(points[k]) && blending.value(points[k]) == 0)
            fe_slaves.push_back(
              {support_dofs[k], components[k], pd_zone.lattice_interpolation(points[k])});
        AssertThrow(Utilities::MPI::sum(fe_slaves.size(), communicator) > 0 &&
                      Utilities::MPI::sum(slave_rows.size(), communicator) > 0,
                    ExcMessage("Invalid input: parameter 'Coupling/Overlap region' = '" +
                               parameters.overlap_text +
                               "'; allowed: an overlap whose halves hold FE nodes (PD side) "
                               "and PD particles (FE side) for the bad coupling."));
      }
    else if (Utilities::MPI::sum(overlap_rows.size(), communicator) == 0)
      throw_invalid_parameter("Coupling/Overlap region",
                              parameters.overlap_text,
                              "an overlap that holds PD nodes (lattice sites with 0 < alpha < "
                              "1): widen it or refine Peridynamics/Lattice spacing");

    const auto &mass = fe_zone.lumped_mass();
    for (unsigned int i = 0; i < inverse_mass.locally_owned_size(); ++i)
      inverse_mass.local_element(i) = 1. / mass.local_element(i);
    for (const auto &fixed : fe_zone.get_prescribed_dofs())
      inverse_mass.local_element(fixed.local_index) = 0.;
    for (const auto &slave : fe_slaves)
      inverse_mass.local_element(slave.dof) = 0.;

    if (parameters.method == CouplingMethod::weak)
      {
        // Multipliers on the FE DoFs whose shape functions reach an overlap PD node.
        fe_scratch = 0.;
        for (const unsigned int k : overlap_rows)
          for (unsigned int e = row_begin[k]; e < row_begin[k + 1]; ++e)
            fe_scratch.local_element(entries[e].dof) += std::abs(entries[e].value);
        fe_scratch.compress(VectorOperation::add);
        for (unsigned int i = 0; i < fe_scratch.locally_owned_size(); ++i)
          if (fe_scratch.local_element(i) > 0)
            multiplier_dofs.push_back(i);
        if (Utilities::MPI::sum(multiplier_dofs.size(), communicator) == 0)
          throw_invalid_parameter("Coupling/Overlap region",
                                  parameters.overlap_text,
                                  "an overlap that holds FE nodes");
      }

    const double wave_speed = parameters.damping_wave_speed > 0 ?
                                parameters.damping_wave_speed :
                                material.longitudinal_wave_speed(dim);
    double largest = 0;
    damping_coefficient.clear();
    for (const unsigned int k : overlap_rows)
      {
        const unsigned int i     = row_particle[k];
        const double       alpha = pd_zone.alpha[i];
        const double       width = parameters.damping_overlap_width > 0 ?
                                     parameters.damping_overlap_width :
                                     blending.overlap_width(pd_zone.reference_position[i]);
        damping_coefficient.push_back(
          parameters.damping ? parameters.damping_constant * wave_speed * alpha * alpha / width :
                               0.);
        largest = std::max(largest, damping_coefficient.back());
      }
    largest = Utilities::MPI::max(largest, communicator);
    if (largest * dt >= 1.)
      {
        std::ostringstream allowed;
        allowed << "a value for which C v_w alpha^2 / L_B x dt < 1 (here " << largest * dt
                << "): explicit damping over-damps and turns unstable beyond; lower C or the "
                   "time step";
        throw_invalid_parameter("Coupling/Damping constant",
                                parameters.damping_constant,
                                allowed.str());
      }

    overlap_values.resize(overlap_rows.size());
    overlap_values_2.resize(overlap_rows.size());
    const unsigned int n_rows = parameters.method == CouplingMethod::strict ?
                                  dim * overlap_rows.size() :
                                  multiplier_dofs.size();
    for (auto *v : {&diagonal, &lambda, &rhs, &residual, &direction, &a_direction, &preconditioned})
      v->assign(n_rows, 0.);
    if (parameters.method != CouplingMethod::bad)
      {
        // The paper's diagonal: the row sums of A (all entries of A are >= 0 for FE_Q1).
        std::vector<double> ones(n_rows, 1.);
        apply_a(ones, diagonal);
        for (const double d : diagonal)
          AssertThrow(d > 0,
                      ExcMessage("A row sum of the multiplier matrix A is not positive: the "
                                 "diagonal solver needs non-negative shape functions (FE degree "
                                 "1); use 'Coupling/Multiplier solver = cg'."));
      }

    if (parameters.blending == Parameters::Blending::force)
      fe_zone.set_nodal_force_weights(alpha_at_dofs);
    if (parameters.blending == Parameters::Blending::energy)
      fe_zone.set_interface_force([this](VectorType &force) { add_slave_forces(force); });
  }

  template <int dim>
  Tensor<1, dim>
  ArlequinCoupling<dim>::interpolate(const VectorType &x, const unsigned int row) const
  {
    Tensor<1, dim> value;
    for (unsigned int e = row_begin[row]; e < row_begin[row + 1]; ++e)
      value[entries[e].component] += entries[e].value * x.local_element(entries[e].dof);
    return value;
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::scatter_overlap(const Values &values, VectorType &result) const
  {
    result = 0.;
    for (unsigned int r = 0; r < overlap_rows.size(); ++r)
      {
        const unsigned int k = overlap_rows[r];
        for (unsigned int e = row_begin[k]; e < row_begin[k + 1]; ++e)
          result.local_element(entries[e].dof) +=
            entries[e].value * values[r][entries[e].component];
      }
    result.compress(VectorOperation::add);
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::apply_h(const std::vector<double> &x, Values &p)
  {
    if (parameters.method == Parameters::CouplingMethod::strict)
      {
        for (unsigned int r = 0; r < overlap_rows.size(); ++r)
          for (unsigned int d = 0; d < dim; ++d)
            p[r][d] = x[dim * r + d];
        return;
      }
    fe_scratch_2 = 0.;
    for (unsigned int m = 0; m < multiplier_dofs.size(); ++m)
      fe_scratch_2.local_element(multiplier_dofs[m]) = x[m];
    fe_scratch_2.update_ghost_values();
    for (unsigned int r = 0; r < overlap_rows.size(); ++r)
      p[r] = interpolate(fe_scratch_2, overlap_rows[r]);
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::apply_transpose_h(const Values &s, std::vector<double> &y)
  {
    if (parameters.method == Parameters::CouplingMethod::strict)
      {
        for (unsigned int r = 0; r < overlap_rows.size(); ++r)
          for (unsigned int d = 0; d < dim; ++d)
            y[dim * r + d] = s[r][d];
        return;
      }
    scatter_overlap(s, fe_scratch_2);
    for (unsigned int m = 0; m < multiplier_dofs.size(); ++m)
      y[m] = fe_scratch_2.local_element(multiplier_dofs[m]);
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::apply_a(const std::vector<double> &x, std::vector<double> &y)
  {
    apply_h(x, overlap_values);
    scatter_overlap(overlap_values, fe_scratch);
    for (unsigned int i = 0; i < fe_scratch.locally_owned_size(); ++i)
      fe_scratch.local_element(i) *= inverse_mass.local_element(i);
    fe_scratch.update_ghost_values();
    for (unsigned int r = 0; r < overlap_rows.size(); ++r)
      {
        const unsigned int k = overlap_rows[r];
        overlap_values_2[r]  = interpolate(fe_scratch, k) +
                              overlap_values[r] / pd_zone.particle_mass(row_particle[k]);
      }
    apply_transpose_h(overlap_values_2, y);
    for (double &value : y)
      value *= time_step;
  }

  template <int dim>
  double
  ArlequinCoupling<dim>::dot(const std::vector<double> &a, const std::vector<double> &b) const
  {
    double sum = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      sum += a[i] * b[i];
    return Utilities::MPI::sum(sum, communicator);
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::set_slave_displacements()
  {
    VectorType &displacement = fe_zone.get_state().displacement;
    if (parameters.method == Parameters::CouplingMethod::bad)
      {
        pd_zone.update_ghost_displacements();
        for (const auto &slave : fe_slaves)
          {
            double value = 0;
            for (const auto &[j, w] : slave.weights)
              value += w * pd_zone.displacement[j][slave.component];
            displacement.local_element(slave.dof) = value;
          }
      }
    displacement.update_ghost_values();
    for (const unsigned int k : slave_rows)
      pd_zone.displacement[row_particle[k]] = interpolate(displacement, k);
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::add_slave_forces(VectorType &force)
  {
    fe_scratch = 0.;
    for (const unsigned int k : slave_rows)
      {
        const Tensor<1, dim> f = pd_zone.blended_force(row_particle[k]);
        for (unsigned int e = row_begin[k]; e < row_begin[k + 1]; ++e)
          fe_scratch.local_element(entries[e].dof) += entries[e].value * f[entries[e].component];
      }
    fe_scratch.compress(VectorOperation::add);
    force.add(1., fe_scratch);
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::apply_damping()
  {
    if (!parameters.damping)
      return;
    const VectorType &velocity = fe_zone.get_state().velocity;
    velocity.update_ghost_values();
    for (unsigned int r = 0; r < overlap_rows.size(); ++r)
      {
        const unsigned int k = overlap_rows[r], i = row_particle[k];
        pd_zone.acceleration[i] -=
          damping_coefficient[r] * (pd_zone.velocity[i] - interpolate(velocity, k));
      }
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::enforce_constraint()
  {
    if (parameters.method == Parameters::CouplingMethod::bad)
      return;
    VectorType &velocity     = fe_zone.get_state().velocity;
    VectorType &acceleration = fe_zone.get_state().acceleration;
    velocity.update_ghost_values();
    for (unsigned int r = 0; r < overlap_rows.size(); ++r)
      {
        const unsigned int k = overlap_rows[r];
        overlap_values[r]    = interpolate(velocity, k) - pd_zone.velocity[row_particle[k]];
      }
    apply_transpose_h(overlap_values, rhs);
    for (unsigned int m = 0; m < rhs.size(); ++m)
      lambda[m] = rhs[m] / diagonal[m];
    iterations = 0;
    if (parameters.multiplier_solver == Parameters::MultiplierSolver::cg)
      {
        // Jacobi-preconditioned CG, started from the diagonal solution.
        const double target = 1e-12 * std::sqrt(dot(rhs, rhs));
        apply_a(lambda, a_direction);
        for (unsigned int m = 0; m < rhs.size(); ++m)
          {
            residual[m]       = rhs[m] - a_direction[m];
            preconditioned[m] = residual[m] / diagonal[m];
          }
        direction     = preconditioned;
        double rz     = dot(residual, preconditioned);
        double r_norm = std::sqrt(dot(residual, residual));
        while (r_norm > target)
          {
            AssertThrow(++iterations <= 1000,
                        ExcMessage("The multiplier CG solve did not reach a relative residual "
                                   "of 1e-12 in 1000 iterations."));
            apply_a(direction, a_direction);
            const double step = rz / dot(direction, a_direction);
            for (unsigned int m = 0; m < rhs.size(); ++m)
              {
                lambda[m] += step * direction[m];
                residual[m] -= step * a_direction[m];
                preconditioned[m] = residual[m] / diagonal[m];
              }
            const double rz_new = dot(residual, preconditioned);
            for (unsigned int m = 0; m < rhs.size(); ++m)
              direction[m] = preconditioned[m] + (rz_new / rz) * direction[m];
            rz     = rz_new;
            r_norm = std::sqrt(dot(residual, residual));
          }
      }

    // Constraint forces -G lambda on FE, +H lambda on PD.
    const double dt = time_step;
    apply_h(lambda, overlap_values);
    scatter_overlap(overlap_values, fe_scratch);
    for (unsigned int i = 0; i < fe_scratch.locally_owned_size(); ++i)
      {
        const double correction = inverse_mass.local_element(i) * fe_scratch.local_element(i);
        velocity.local_element(i) -= dt * correction;
        acceleration.local_element(i) -= correction;
      }
    for (unsigned int r = 0; r < overlap_rows.size(); ++r)
      {
        const unsigned int   i          = row_particle[overlap_rows[r]];
        const Tensor<1, dim> correction = overlap_values[r] / pd_zone.particle_mass(i);
        pd_zone.velocity[i] += dt * correction;
        pd_zone.acceleration[i] += correction;
      }
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::set_slave_velocities()
  {
    VectorType &velocity     = fe_zone.get_state().velocity;
    VectorType &acceleration = fe_zone.get_state().acceleration;
    if (parameters.method == Parameters::CouplingMethod::bad)
      {
        pd_motion_buffer.resize(2 * dim * pd_zone.reference_position.size());
        for (unsigned int i = 0; i < pd_zone.n_owned; ++i)
          for (unsigned int d = 0; d < dim; ++d)
            {
              pd_motion_buffer[2 * dim * i + d]       = pd_zone.velocity[i][d];
              pd_motion_buffer[2 * dim * i + dim + d] = pd_zone.acceleration[i][d];
            }
        pd_zone.update_ghosts(pd_motion_buffer, 2 * dim);
        for (const auto &slave : fe_slaves)
          {
            double v = 0, a = 0;
            for (const auto &[j, w] : slave.weights)
              {
                v += w * pd_motion_buffer[2 * dim * j + slave.component];
                a += w * pd_motion_buffer[2 * dim * j + dim + slave.component];
              }
            velocity.local_element(slave.dof)     = v;
            acceleration.local_element(slave.dof) = a;
          }
      }
    velocity.update_ghost_values();
    acceleration.update_ghost_values();
    for (const unsigned int k : slave_rows)
      {
        const unsigned int i    = row_particle[k];
        pd_zone.velocity[i]     = interpolate(velocity, k);
        pd_zone.acceleration[i] = interpolate(acceleration, k);
      }
  }

  template <int dim>
  std::pair<double, double>
  ArlequinCoupling<dim>::constraint_residuals()
  {
    const VectorType &displacement = fe_zone.get_state().displacement;
    const VectorType &velocity     = fe_zone.get_state().velocity;
    if (parameters.method == Parameters::CouplingMethod::bad)
      return {0., 0.};
    std::pair<double, double> norms;
    for (const bool rate : {false, true})
      {
        const VectorType &field = rate ? velocity : displacement;
        field.update_ghost_values();
        for (unsigned int r = 0; r < overlap_rows.size(); ++r)
          {
            const unsigned int k = overlap_rows[r], i = row_particle[k];
            overlap_values[r] =
              interpolate(field, k) - (rate ? pd_zone.velocity[i] : pd_zone.displacement[i]);
          }
        apply_transpose_h(overlap_values, residual);
        (rate ? norms.second : norms.first) = std::sqrt(dot(residual, residual));
      }
    return norms;
  }

  template <int dim>
  types::global_dof_index
  ArlequinCoupling<dim>::n_multipliers() const
  {
    return Utilities::MPI::sum(static_cast<types::global_dof_index>(lambda.size()), communicator);
  }

  template <int dim>
  std::pair<types::global_dof_index, types::global_dof_index>
  ArlequinCoupling<dim>::n_coupled_particles() const
  {
    return {Utilities::MPI::sum(static_cast<types::global_dof_index>(overlap_rows.size()),
                                communicator),
            Utilities::MPI::sum(static_cast<types::global_dof_index>(slave_rows.size()),
                                communicator)};
  }

  template <int dim>
  unsigned int
  ArlequinCoupling<dim>::last_iterations() const
  {
    return iterations;
  }

  template class ArlequinCoupling<2>;
  template class ArlequinCoupling<3>;
} // namespace PeriArlequin
