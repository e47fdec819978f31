#include <periarlequin/base/parallel_loops.h>
#include <periarlequin/base/vector_reductions.h>
#include <periarlequin/coupling/arlequin_coupling.h>

#include <cmath>

namespace PeriArlequin
{
  template <int dim>
  ArlequinCoupling<dim>::ArlequinCoupling(const Parameters::Coupling &parameters,
                                          const MultiplierMesh        mesh)
    : parameters(parameters)
    , mesh(mesh)
  {}

  template <int dim>
  void
  ArlequinCoupling<dim>::MultiplierGrid::entries(ParameterEntries &entries)
  {
    entries.add("Multiplier spacing",
                spacing,
                Patterns::Double(1),
                "The lambda-mesh, in FE cells h (the largest cell extent around the overlap): "
                "1 puts a multiplier on every FE node of the overlap (H = N); k > 1 on every "
                "node of a Cartesian grid of Q1 hats of spacing k h laid from the lower corner "
                "of the overlap. At k = 2 the constraint leaves the waves of 2 to 4 FE cells, "
                "which the FE mesh cannot propagate, to the fine-scale damping instead of "
                "reflecting them (studies/wave_coupling/README.md) [FE cells].");
    entries.add("Multiplier grid offset",
                offset,
                Patterns::Double(0, 0.999),
                "With a spacing k > 1: the grid's nodes start this fraction of the spacing "
                "before the lower corner of the overlap's PD nodes. The reflection near the "
                "cut-off of the lambda-mesh depends on it (studies/wave_coupling/README.md) [-].");
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::declare_weak_parameters(ParameterHandler &prm)
  {
    ParameterEntries::declare_here<MultiplierGrid>(prm);
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::parse_parameters(ParameterHandler &prm)
  {
    if (mesh == MultiplierMesh::weak)
      ParameterEntries::parse_here(prm, multiplier_grid, "Coupling/weak/");
  }

  template <int dim>
  BlendingProfile
  ArlequinCoupling<dim>::blending_profile() const
  {
    return BlendingProfile::linear;
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::initialize(const BlendingField<dim> &blending,
                                    FEZone<dim>              &fe,
                                    PDZone<dim>              &pd,
                                    const double              dt)
  {
    fe_zone                     = &fe;
    pd_zone                     = &pd;
    time_step                   = dt;
    const MPI_Comm communicator = pd.get_communicator();

    overlap_particles.clear();
    pd_inverse_mass.clear();
    for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
      if (!pd.is_slave(i) && pd.blending_weights()[i] > 0)
        overlap_particles.push_back(i);
    // The overlap is given by boxes or, as a band around the PD region, by its width.
    const bool        band = parameters.overlap_width > 0;
    const std::string overlap_parameter =
      band ? "Coupling/Overlap width" : "Coupling/Overlap region";
    const std::string overlap_value =
      band ? std::to_string(parameters.overlap_width) : parameters.overlap_text;
    if (Utilities::MPI::sum(overlap_particles.size(), communicator) == 0)
      throw_invalid_parameter(overlap_parameter,
                              overlap_value,
                              "an overlap that holds PD nodes (lattice sites with 0 < alpha < "
                              "1): widen it or refine Peridynamics/Lattice spacing");
    overlap.reinit(fe, pd, overlap_particles);
    slaves.initialize(fe, pd);

    fe.initialize_vector(fe_inverse_mass);
    fe.initialize_vector(fe_scratch);
    const auto &mass = fe.lumped_mass();
    for (unsigned int i = 0; i < fe_inverse_mass.locally_owned_size(); ++i)
      fe_inverse_mass.local_element(i) = 1. / mass.local_element(i);
    for (const auto &fixed : fe.get_prescribed_dofs())
      fe_inverse_mass.local_element(fixed.local_index) = 0.;
    fe_inverse_mass.update_ghost_values();
    // Prescribed particles (a displacement boundary layer or region) are moved by no force,
    // as prescribed FE DoFs: zero inverse mass. A particle with some components prescribed
    // counts as prescribed in all (its free components are then not coupled).
    for (const unsigned int i : overlap_particles)
      pd_inverse_mass.push_back(pd.is_prescribed(i) ? 0. : 1. / pd.particle_mass(i));

    if (mesh == MultiplierMesh::strict)
      space = std::make_unique<StrictMultiplierSpace<dim>>(overlap, communicator);
    else if (multiplier_grid.spacing == 1)
      space = std::make_unique<WeakMultiplierSpace<dim>>(overlap, fe);
    else
      {
        std::vector<Point<dim>> positions;
        for (const unsigned int i : overlap_particles)
          positions.push_back(pd.reference_positions()[i]);
        space = std::make_unique<GridMultiplierSpace<dim>>(overlap,
                                                           fe,
                                                           positions,
                                                           multiplier_grid.spacing,
                                                           multiplier_grid.offset);
      }
    space->initialize_vector(lambda);
    space->initialize_vector(rhs);
    if (lambda.size() == 0)
      throw_invalid_parameter(overlap_parameter, overlap_value, "an overlap that holds FE nodes");
    solver = std::make_unique<MultiplierSolver<dim>>(*space,
                                                     overlap,
                                                     fe_inverse_mass,
                                                     pd_inverse_mass,
                                                     dt,
                                                     parameters.multiplier_solver);
    damping.reset();
    if (parameters.damping)
      damping = std::make_unique<FineScaleDamping<dim>>(parameters,
                                                        fe.get_material(),
                                                        blending,
                                                        pd,
                                                        overlap_particles,
                                                        overlap,
                                                        dt);

    set_fe_force_weights(parameters, blending, fe);
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::constraint(const VectorType               &x,
                                    ArrayView<const Tensor<1, dim>> y,
                                    VectorType                     &g) const
  {
    x.update_ghost_values();
    overlap.vmult(overlap_values, x);
    overlap.for_each_row_range([&](const unsigned int first, const unsigned int end) {
      for (unsigned int r = first; r < end; ++r)
        overlap_values[r] -= y[overlap_particles[r]];
    });
    space->apply_transpose_h(overlap_values, g);
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::set_slave_displacements()
  {
    slaves.follow_displacements();
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::add_interface_forces(const double time)
  {
    add_slave_forces(parameters, slaves, time, *fe_zone);
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::apply_damping()
  {
    if (damping)
      damping->apply(fe_zone->get_state(), *pd_zone);
  }

  template <int dim>
  double
  ArlequinCoupling<dim>::stable_time_step(const double undamped_step) const
  {
    return damping ? damping->stable_time_step(undamped_step) : undamped_step;
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::enforce_constraint()
  {
    constraint(fe_zone->get_state().velocity, pd_zone->get_state().velocities(), rhs);
    solver->solve(lambda, rhs);

    // Constraint forces -G lambda = -N^T H lambda on FE, +H lambda on PD.
    space->apply_h(lambda, overlap_values);
    overlap.Tvmult(fe_scratch, overlap_values);
    const double dt = time_step;
    for_each_subrange(fe_scratch.locally_owned_size(),
                      [&](const unsigned int first, const unsigned int end) {
                        for (unsigned int i = first; i < end; ++i)
                          {
                            const double correction =
                              fe_inverse_mass.local_element(i) * fe_scratch.local_element(i);
                            fe_zone->correct_motion(i, -(dt * correction), -correction);
                          }
                      });
    overlap.for_each_row_range([&](const unsigned int first, const unsigned int end) {
      for (unsigned int r = first; r < end; ++r)
        {
          const unsigned int   i          = overlap_particles[r];
          const Tensor<1, dim> correction = pd_inverse_mass[r] * overlap_values[r];
          pd_zone->correct_motion(i, dt * correction, correction);
        }
    });
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::set_slave_velocities()
  {
    slaves.follow_velocities();
  }

  template <int dim>
  std::pair<double, double>
  ArlequinCoupling<dim>::constraint_residuals() const
  {
    const auto &state = fe_zone->get_state();
    VectorType  g;
    space->initialize_vector(g);
    constraint(state.displacement, pd_zone->get_state().displacements(), g);
    const double displacement_residual = l2_norm_in_fixed_chunks(g);
    constraint(state.velocity, pd_zone->get_state().velocities(), g);
    return {displacement_residual, l2_norm_in_fixed_chunks(g)};
  }

  template <int dim>
  types::global_dof_index
  ArlequinCoupling<dim>::n_multipliers() const
  {
    return lambda.size();
  }

  template <int dim>
  std::pair<types::global_dof_index, types::global_dof_index>
  ArlequinCoupling<dim>::n_coupled_particles() const
  {
    return {Utilities::MPI::sum(static_cast<types::global_dof_index>(overlap_particles.size()),
                                lambda.get_mpi_communicator()),
            slaves.n_global_slaves()};
  }

  template <int dim>
  unsigned int
  ArlequinCoupling<dim>::last_solver_iterations() const
  {
    return solver->last_iterations();
  }

  template <int dim>
  std::string
  ArlequinCoupling<dim>::conjugate_gradient_obstacle() const
  {
    if (parameters.blending == Parameters::Blending::energy)
      return "";
    return "Coupling/Blending = " +
           selection_name(parameters.blending, Parameters::blending_names) +
           ": its forces derive from no energy (the coupled stiffness is not symmetric)";
  }

  template <int dim>
  void
  ArlequinCoupling<dim>::solve_multipliers_exactly(const bool exact)
  {
    solver->solve_exactly(exact);
  }

  template <int dim>
  MultiplierSolver<dim> &
  ArlequinCoupling<dim>::multiplier_solver()
  {
    return *solver;
  }

  template <int dim>
  const typename ArlequinCoupling<dim>::VectorType &
  ArlequinCoupling<dim>::multipliers() const
  {
    return lambda;
  }

  template class ArlequinCoupling<2>;
  template class ArlequinCoupling<3>;

  namespace
  {
    template <int dim>
    bool
    register_arlequin_couplings()
    {
      using Mesh         = typename ArlequinCoupling<dim>::MultiplierMesh;
      const auto creator = [](const Mesh mesh) {
        return [mesh](const Parameters::Coupling &parameters) {
          return std::unique_ptr<Coupling<dim>>(new ArlequinCoupling<dim>(parameters, mesh));
        };
      };
      return CouplingRegistry<dim>::register_plugin(
               "strict",
               "Arlequin, a Lagrange multiplier on every PD node of the overlap (H = I).",
               creator(Mesh::strict)) &&
             CouplingRegistry<dim>::register_plugin(
               "weak",
               "Arlequin, a multiplier on every FE node of the overlap (H = N) or on the "
               "nodes of a coarser grid (Coupling/weak/Multiplier mesh spacing).",
               creator(Mesh::weak),
               &ArlequinCoupling<dim>::declare_weak_parameters);
    }

    const bool arlequin_couplings_registered =
      register_arlequin_couplings<2>() && register_arlequin_couplings<3>();
  } // namespace
} // namespace PeriArlequin
