#include <periarlequin/fe/fe_zone.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <map>

namespace PeriArlequin
{
  template <int dim>
  FEZone<dim>::FEZone(const parallel::distributed::Triangulation<dim> &triangulation,
                      const Parameters::FiniteElements                &fe_parameters,
                      const Parameters::Material                      &material)
    : triangulation(triangulation)
    , material(material)
    , communicator(triangulation.get_communicator())
    , dof_handler(triangulation)
  {
    fe_collection.push_back(FESystem<dim>(FE_Q<dim>(fe_parameters.degree), dim));
    fe_collection.push_back(FESystem<dim>(FE_Nothing<dim>(), dim));
    for (unsigned int i = 0; i < fe_collection.size(); ++i)
      {
        cell_quadrature.push_back(QGauss<dim>(fe_parameters.degree + 1));
        face_quadrature.push_back(QGauss<dim - 1>(fe_parameters.degree + 1));
      }
  }

  template <int dim>
  void
  FEZone<dim>::setup(const WeightFunction &mass_weight_function,
                     const WeightFunction &stiffness_weight_function,
                     const CellPredicate  &in_fe_zone)
  {
    mass_weight      = mass_weight_function;
    stiffness_weight = stiffness_weight_function;
    fe_cells         = in_fe_zone;
    distribute_and_assemble();
  }

  template <int dim>
  void
  FEZone<dim>::distribute_and_assemble()
  {
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        cell->set_active_fe_index(fe_cells(cell) ? 0 : 1);
    dof_handler.distribute_dofs(fe_collection);
    locally_owned_dofs    = dof_handler.locally_owned_dofs();
    locally_relevant_dofs = DoFTools::extract_locally_relevant_dofs(dof_handler);
    owned_dof_component.assign(locally_owned_dofs.n_elements(), 0);
    std::vector<types::global_dof_index> dof_indices;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          dof_indices.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dof_indices);
          for (unsigned int i = 0; i < dof_indices.size(); ++i)
            if (locally_owned_dofs.is_element(dof_indices[i]))
              owned_dof_component[locally_owned_dofs.index_within_set(dof_indices[i])] =
                cell->get_fe().system_to_component_index(i).first;
        }
    initialize_vector(mass);
    assemble_mass_and_stiffness();
  }

  template <int dim>
  std::vector<typename FEZone<dim>::VectorType *>
  FEZone<dim>::carried_vectors()
  {
    // The internal force too, so that the strain energy of a step that repartitioned is that
    // of its force pass.
    return {&state.displacement,
            &state.velocity,
            &state.acceleration,
            &applied_force,
            &internal_force};
  }

  template <int dim>
  void
  FEZone<dim>::restrict_to(const CellPredicate &in_fe_zone)
  {
    // The DoF indices, before and after, of the owned cells that stay FE: every owned DoF
    // after the change lies on one of them, and every DoF of theirs was locally relevant
    // before, so the old ghosted vectors hold the values to keep.
    const std::vector<VectorType *> kept       = carried_vectors();
    const std::vector<VectorType>   old_values = [&] {
      // Sized first: a copy of a vector holds its owned values only, so copies that a
      // growing std::vector made would lose the ghost values updated before.
      std::vector<VectorType> copies(kept.size());
      for (unsigned int k = 0; k < kept.size(); ++k)
        {
          copies[k] = *kept[k];
          copies[k].update_ghost_values();
        }
      return copies;
    }();
    std::vector<std::vector<types::global_dof_index>> old_indices(triangulation.n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0 && in_fe_zone(cell))
        {
          old_indices[cell->active_cell_index()].resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(old_indices[cell->active_cell_index()]);
        }

    fe_cells = in_fe_zone;
    distribute_and_assemble();

    for (VectorType *v : kept)
      initialize_vector(*v);
    std::vector<types::global_dof_index> new_indices;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0)
        {
          const auto &old = old_indices[cell->active_cell_index()];
          AssertThrow(old.size() == cell->get_fe().n_dofs_per_cell(),
                      ExcMessage("FEZone::restrict_to(): a cell that was not FE became FE."));
          new_indices.resize(old.size());
          cell->get_dof_indices(new_indices);
          for (unsigned int i = 0; i < old.size(); ++i)
            if (locally_owned_dofs.is_element(new_indices[i]))
              for (unsigned int k = 0; k < kept.size(); ++k)
                (*kept[k])(new_indices[i]) = old_values[k](old[i]);
        }
    reset_after_dof_change();
  }

  template <int dim>
  std::vector<const typename FEZone<dim>::VectorType *>
  FEZone<dim>::ghosted_carried_vectors()
  {
    std::vector<const VectorType *> carried;
    for (VectorType *v : carried_vectors())
      {
        v->update_ghost_values();
        carried.push_back(v);
      }
    solution_transfer =
      std::make_unique<parallel::distributed::SolutionTransfer<dim, VectorType>>(dof_handler);
    return carried;
  }

  template <int dim>
  void
  FEZone<dim>::prepare_for_repartition()
  {
    // ghosted_carried_vectors() makes solution_transfer: call it first.
    const std::vector<const VectorType *> carried = ghosted_carried_vectors();
    solution_transfer->prepare_for_coarsening_and_refinement(carried);
  }

  template <int dim>
  void
  FEZone<dim>::prepare_for_serialization()
  {
    const std::vector<const VectorType *> carried = ghosted_carried_vectors();
    solution_transfer->prepare_for_serialization(carried);
  }

  template <int dim>
  void
  FEZone<dim>::deserialize()
  {
    std::vector<VectorType *> carried = carried_vectors();
    for (VectorType *v : carried)
      initialize_vector(*v);
    parallel::distributed::SolutionTransfer<dim, VectorType> transfer(dof_handler);
    transfer.deserialize(carried);
    reset_after_dof_change();
  }

  template <int dim>
  void
  FEZone<dim>::set_external_work(const double work_so_far)
  {
    work = work_so_far;
  }

  template <int dim>
  void
  FEZone<dim>::unpack_after_repartition()
  {
    Assert(solution_transfer, ExcMessage("Call prepare_for_repartition() first."));
    distribute_and_assemble();
    std::vector<VectorType *> carried = carried_vectors();
    for (VectorType *v : carried)
      initialize_vector(*v);
    solution_transfer->interpolate(carried);
    solution_transfer.reset();
    reset_after_dof_change();
  }

  template <int dim>
  void
  FEZone<dim>::reset_after_dof_change()
  {
    for (VectorType *v : {&previous_applied_force, &previous_displacement, &interface_force})
      initialize_vector(*v);
    for (VectorType *v : {&state.displacement, &state.velocity, &state.acceleration})
      v->update_ghost_values();
    find_prescribed_dofs(*problem_data);
    nodal_force_weights.clear();
  }

  template <int dim>
  void
  FEZone<dim>::find_prescribed_dofs(const ProblemData<dim> &data)
  {
    prescribed = prescribed_dofs(data);
    // Their motion is evaluated by impose_prescribed_motion(); until then (a run resumed from
    // a checkpoint, DoFs renumbered) they are at rest, not given another numbering's values.
    prescribed_velocity.assign(prescribed.size(), 0.);
    prescribed_acceleration.assign(prescribed.size(), 0.);
    is_prescribed_dof.assign(locally_owned_dofs.n_elements(), false);
    for (const auto &dof : prescribed)
      is_prescribed_dof[dof.local_index] = true;
  }

  template <int dim>
  void
  FEZone<dim>::assemble_mass_and_stiffness()
  {
    const double lambda = material.effective_lambda(dim);
    const double mu     = material.shear_modulus();
    const double rho    = material.density;

    const hp::MappingCollection<dim>     mappings(mapping);
    hp::FEValues<dim>                    hp_fe_values(mappings,
                                   fe_collection,
                                   cell_quadrature,
                                   update_values | update_gradients | update_quadrature_points |
                                     update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_mass;
    std::vector<types::global_dof_index> dof_indices;
    std::vector<SymmetricTensor<2, dim>> strain;
    std::vector<double>                  divergence;
    AffineConstraints<double>            no_constraints;
    no_constraints.close();
    TrilinosWrappers::SparseMatrix stiffness;
    reinit_matrix(stiffness);

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned() || cell->get_fe().n_dofs_per_cell() == 0)
          continue;
        hp_fe_values.reinit(cell);
        const FEValues<dim> &fe_values     = hp_fe_values.get_present_fe_values();
        const unsigned int   dofs_per_cell = fe_values.dofs_per_cell;
        cell_matrix.reinit(dofs_per_cell, dofs_per_cell);
        cell_mass.reinit(dofs_per_cell);
        strain.resize(dofs_per_cell);
        divergence.resize(dofs_per_cell);

        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const Point<dim> &x      = fe_values.quadrature_point(q);
            const double      weight = stiffness_weight(x) * fe_values.JxW(q);
            const double      m      = rho * mass_weight(x) * fe_values.JxW(q);
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                strain[i]     = fe_values[displacement].symmetric_gradient(i, q);
                divergence[i] = trace(strain[i]);
                // Row sum of the consistent mass: FE_Q shape functions sum to one.
                cell_mass(i) += fe_values.shape_value(i, q) * m;
              }
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              for (unsigned int j = 0; j <= i; ++j)
                cell_matrix(i, j) +=
                  (lambda * divergence[i] * divergence[j] + 2. * mu * (strain[i] * strain[j])) *
                  weight;
          }
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          for (unsigned int j = i + 1; j < dofs_per_cell; ++j)
            cell_matrix(i, j) = cell_matrix(j, i);

        dof_indices.resize(dofs_per_cell);
        cell->get_dof_indices(dof_indices);
        no_constraints.distribute_local_to_global(cell_matrix,
                                                  cell_mass,
                                                  dof_indices,
                                                  stiffness,
                                                  mass);
      }
    stiffness.compress(VectorOperation::add);
    mass.compress(VectorOperation::add);
    stiffness_matrix.reinit(stiffness, *mass.get_partitioner());

    for (unsigned int i = 0; i < mass.locally_owned_size(); ++i)
      AssertThrow(mass.local_element(i) > 0,
                  ExcMessage("An FE degree of freedom has a non-positive lumped mass (" +
                             std::to_string(mass.local_element(i)) +
                             "): the blending weight alpha must be positive somewhere on the "
                             "support of every FE node."));
  }

  template <int dim>
  void
  FEZone<dim>::support_points(std::vector<unsigned int> &local_dofs,
                              std::vector<Point<dim>>   &points,
                              std::vector<unsigned int> &components) const
  {
    // By owned index, so in the order of the global DoF numbers; a DoF seen from several
    // cells takes the last one's point, as before.
    const unsigned int                   n_owned = locally_owned_dofs.n_elements();
    std::vector<Point<dim>>              located(n_owned);
    std::vector<int>                     component(n_owned, -1);
    std::vector<types::global_dof_index> dof_indices;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned() || cell->get_fe().n_dofs_per_cell() == 0)
          continue;
        const auto &unit = cell->get_fe().get_unit_support_points();
        dof_indices.resize(cell->get_fe().n_dofs_per_cell());
        cell->get_dof_indices(dof_indices);
        // The components of a node share its support point: mapped once.
        Point<dim> real;
        for (unsigned int i = 0; i < dof_indices.size(); ++i)
          {
            if (i == 0 || unit[i] != unit[i - 1])
              real = mapping.transform_unit_to_real_cell(cell, unit[i]);
            if (locally_owned_dofs.is_element(dof_indices[i]))
              {
                const unsigned int local = locally_owned_dofs.index_within_set(dof_indices[i]);
                located[local]           = real;
                component[local]         = cell->get_fe().system_to_component_index(i).first;
              }
          }
      }
    local_dofs.clear();
    points.clear();
    components.clear();
    for (unsigned int local = 0; local < n_owned; ++local)
      if (component[local] >= 0)
        {
          local_dofs.push_back(local);
          points.push_back(located[local]);
          components.push_back(component[local]);
        }
  }

  template <int dim>
  std::optional<typename FEZone<dim>::PointLocation>
  FEZone<dim>::locate(const Point<dim> &point) const
  {
    const double tolerance = 1e-10;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned() || cell->get_fe().n_dofs_per_cell() == 0 ||
            !cell->bounding_box().point_inside(point, tolerance * cell->diameter()))
          continue;
        try
          {
            const Point<dim> unit = mapping.transform_real_to_unit_cell(cell, point);
            if (GeometryInfo<dim>::is_inside_unit_cell(unit, tolerance))
              return PointLocation(cell, unit);
          }
        catch (const typename Mapping<dim>::ExcTransformationFailed &)
          {}
      }
    return {};
  }

  template <int dim>
  Tensor<1, dim>
  FEZone<dim>::point_value(const VectorType &ghosted, const PointLocation &location) const
  {
    const auto &[cell, unit]                = location;
    const auto                          &fe = cell->get_fe();
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    cell->get_dof_indices(dof_indices);
    Tensor<1, dim> value;
    for (unsigned int i = 0; i < dof_indices.size(); ++i)
      {
        const unsigned int c = fe.system_to_component_index(i).first;
        value[c] += fe.shape_value_component(i, unit, c) * ghosted(dof_indices[i]);
      }
    return value;
  }

  template <int dim>
  void
  FEZone<dim>::initialize_vector(VectorType &vector) const
  {
    vector.reinit(locally_owned_dofs, locally_relevant_dofs, communicator);
  }

  template <int dim>
  void
  FEZone<dim>::reinit_matrix(TrilinosWrappers::SparseMatrix &matrix) const
  {
    TrilinosWrappers::SparsityPattern sparsity(locally_owned_dofs,
                                               locally_owned_dofs,
                                               locally_relevant_dofs,
                                               communicator);
    DoFTools::make_sparsity_pattern(dof_handler, sparsity);
    sparsity.compress();
    matrix.reinit(sparsity);
  }

  template <int dim>
  void
  FEZone<dim>::compute_internal_force(const VectorType &displacement, VectorType &force) const
  {
    stiffness_matrix.vmult(force, displacement);
  }

  template <int dim>
  void
  FEZone<dim>::compute_external_force(const ProblemData<dim> &data,
                                      const double            time,
                                      VectorType             &force) const
  {
    force = 0.;
    if (!data.has_body_force && !data.has_tractions())
      return;

    const UpdateFlags flags = update_values | update_quadrature_points | update_JxW_values;
    const hp::MappingCollection<dim> mappings(mapping);
    hp::FEValues<dim>                hp_fe_values(mappings, fe_collection, cell_quadrature, flags);
    hp::FEFaceValues<dim> hp_face_values(mappings, fe_collection, face_quadrature, flags);
    Vector<double>        cell_force;
    Vector<double>        load(dim);
    std::vector<types::global_dof_index> dof_indices;
    auto                                &body_force = data.body_force;
    body_force.set_time(time);

    // Loads are blended like the mass, alpha at the quadrature points (the PD zone takes
    // 1 - alpha), so that a body force accelerates the blended body rigidly. Under force
    // blending the tractions take the nodal weight alpha_I of the internal forces instead:
    // a node where the PD region's edge meets a loaded face (alpha_I = 0, no internal force)
    // cannot pass a share of the traction on to the body, and accelerated without bound.
    const bool nodal_tractions = !nodal_force_weights.empty() && data.has_tractions();
    VectorType traction;
    if (nodal_tractions)
      initialize_vector(traction);
    Vector<double> cell_traction;
    const auto     add_load = [&](const FEValuesBase<dim> &values,
                              Function<dim>           &function,
                              const bool               weighted,
                              Vector<double>          &cell_load) {
      for (const unsigned int q : values.quadrature_point_indices())
        {
          const Point<dim> &x = values.quadrature_point(q);
          function.vector_value(x, load);
          const double JxW = (weighted ? mass_weight(x) : 1.) * values.JxW(q);
          for (unsigned int i = 0; i < values.dofs_per_cell; ++i)
            {
              const unsigned int c = values.get_fe().system_to_component_index(i).first;
              cell_load(i) += load(c) * values.shape_value(i, q) * JxW;
            }
        }
    };

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned() || cell->get_fe().n_dofs_per_cell() == 0)
          continue;
        cell_force.reinit(cell->get_fe().n_dofs_per_cell());
        cell_traction.reinit(cell_force.size());
        if (data.has_body_force)
          {
            hp_fe_values.reinit(cell);
            add_load(hp_fe_values.get_present_fe_values(), body_force, true, cell_force);
          }
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f) && cell->face(f)->boundary_id() < ProblemData<dim>::n_boundaries)
            {
              const auto &condition = data.boundary_conditions[cell->face(f)->boundary_id()];
              if (condition.type != BoundaryType::traction)
                continue;
              condition.function->set_time(time);
              hp_face_values.reinit(cell, f);
              add_load(hp_face_values.get_present_fe_values(),
                       *condition.function,
                       !nodal_tractions,
                       nodal_tractions ? cell_traction : cell_force);
            }
        dof_indices.resize(cell_force.size());
        cell->get_dof_indices(dof_indices);
        for (unsigned int i = 0; i < dof_indices.size(); ++i)
          {
            force(dof_indices[i]) += cell_force(i);
            if (nodal_tractions)
              traction(dof_indices[i]) += cell_traction(i);
          }
      }
    force.compress(VectorOperation::add);
    if (nodal_tractions)
      {
        traction.compress(VectorOperation::add);
        for (unsigned int i = 0; i < force.locally_owned_size(); ++i)
          force.local_element(i) += nodal_force_weights[i] * traction.local_element(i);
      }
  }

  template <int dim>
  void
  FEZone<dim>::interpolate(const Function<dim> &function, VectorType &vector) const
  {
    VectorTools::interpolate(dof_handler, function, vector);
  }

  template <int dim>
  std::vector<typename FEZone<dim>::PrescribedDoF>
  FEZone<dim>::prescribed_dofs(const ProblemData<dim> &data) const
  {
    std::map<types::global_dof_index, PrescribedDoF> found;
    std::vector<types::global_dof_index>             dof_indices;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned() || cell->get_fe().n_dofs_per_cell() == 0 ||
            !cell->at_boundary())
          continue;
        const FiniteElement<dim> &fe = cell->get_fe();
        dof_indices.resize(fe.n_dofs_per_cell());
        cell->get_dof_indices(dof_indices);
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->at_boundary(f))
              continue;
            // Boundary ids past those of Boundary conditions (a mesh file's) are free.
            const unsigned int id = cell->face(f)->boundary_id();
            if (id >= ProblemData<dim>::n_boundaries)
              continue;
            const auto &condition = data.boundary_conditions[id];
            if (condition.type != BoundaryType::displacement)
              continue;
            // Face f of the reference cell lies at x_{f/2} = f%2.
            const unsigned int direction = f / 2;
            const double       side      = f % 2;
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              {
                const Point<dim>  &unit      = fe.get_unit_support_points()[i];
                const unsigned int component = fe.system_to_component_index(i).first;
                if (std::abs(unit[direction] - side) > 1e-12 || !condition.components[component] ||
                    !locally_owned_dofs.is_element(dof_indices[i]))
                  continue;
                found[dof_indices[i]] = {static_cast<unsigned int>(
                                           locally_owned_dofs.index_within_set(dof_indices[i])),
                                         component,
                                         id,
                                         mapping.transform_unit_to_real_cell(cell, unit)};
              }
          }
      }
    std::vector<PrescribedDoF> result;
    for (const auto &entry : found)
      {
        PrescribedDoF dof = entry.second;
        dof.separable     = dynamic_cast<const SeparableField<dim> *>(
          data.boundary_conditions[dof.boundary_id].function.get());
        if (dof.separable)
          dof.spatial_value = dof.separable->spatial_field(dof.location)[dof.component];
        result.push_back(dof);
      }
    return result;
  }

  namespace
  {
    /**
     * Pseudo-random signs hashed from a point and a component: a start vector for power
     * iterations that is rich in the highest (checkerboard) modes and the same whatever the
     * partition of the mesh.
     */
    template <int dim>
    class HashedSigns : public Function<dim>
    {
    public:
      HashedSigns()
        : Function<dim>(dim)
      {}

      double
      value(const Point<dim> &p, const unsigned int component) const override
      {
        double h = 4.1414 * component;
        for (unsigned int d = 0; d < dim; ++d)
          h += (12.9898 + 65.2 * d) * p[d] / (1. + std::abs(p[d]));
        h = std::sin(h * 437.585453) * 43758.5453;
        return h - std::floor(h) < 0.5 ? -1. : 1.;
      }
    };
  } // namespace

  template <int dim>
  double
  FEZone<dim>::estimate_stable_time_step(const unsigned int max_iterations) const
  {
    VectorType x, y, z, inverse_sqrt_mass;
    initialize_vector(x);
    initialize_vector(y);
    initialize_vector(z);
    initialize_vector(inverse_sqrt_mass);
    for (unsigned int i = 0; i < mass.locally_owned_size(); ++i)
      inverse_sqrt_mass.local_element(i) = 1. / std::sqrt(mass.local_element(i));

    interpolate(HashedSigns<dim>(), x);
    x /= x.l2_norm();
    double eigenvalue = 0.;
    for (unsigned int it = 0; it < max_iterations; ++it)
      {
        // y = M^-1/2 K M^-1/2 x with |x| = 1; the Rayleigh quotient x.y rises to lambda_max.
        z = x;
        z.scale(inverse_sqrt_mass);
        stiffness_matrix.vmult(y, z);
        y.scale(inverse_sqrt_mass);
        const double rayleigh  = x * y;
        const bool   converged = std::abs(rayleigh - eigenvalue) <= 1e-6 * rayleigh;
        eigenvalue             = rayleigh;
        x                      = y;
        x /= x.l2_norm();
        if (converged)
          break;
      }
    AssertThrow(eigenvalue > 0,
                ExcMessage("The stable time step estimate found no positive eigenvalue of "
                           "M^-1 K: the FE zone has no stiffness."));
    return 2. / std::sqrt(eigenvalue);
  }

  template <int dim>
  const DoFHandler<dim> &
  FEZone<dim>::get_dof_handler() const
  {
    return dof_handler;
  }

  template <int dim>
  void
  FEZone<dim>::add_lumped_mass(const VectorType &extra)
  {
    mass.add(1., extra);
  }

  template <int dim>
  const typename FEZone<dim>::VectorType &
  FEZone<dim>::lumped_mass() const
  {
    return mass;
  }

  template <int dim>
  const Parameters::Material &
  FEZone<dim>::get_material() const
  {
    return material;
  }

  template <int dim>
  types::global_dof_index
  FEZone<dim>::n_dofs() const
  {
    return dof_handler.n_dofs();
  }

  template class FEZone<2>;
  template class FEZone<3>;
} // namespace PeriArlequin
