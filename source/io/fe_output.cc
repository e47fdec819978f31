#include <periarlequin/io/fe_output.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <fstream>

namespace PeriArlequin
{
  namespace
  {
    /**
     * Cauchy stress sigma = lambda_eff tr(eps) I + 2 mu eps and its von Mises value, which in
     * 2D includes the out-of-plane stress (0 in plane stress, lambda tr(eps) in plane strain).
     */
    template <int dim>
    class StressPostprocessor : public DataPostprocessor<dim>
    {
    public:
      explicit StressPostprocessor(const Parameters::Material &material)
        : lambda(material.effective_lambda(dim))
        , mu(material.shear_modulus())
        , out_of_plane_factor(dim == 2 &&
                                  material.planar_model == Parameters::PlanarModel::plane_strain ?
                                material.effective_lambda(dim) :
                                0.)
      {}

      void
      evaluate_vector_field(const DataPostprocessorInputs::Vector<dim> &inputs,
                            std::vector<Vector<double>>                &computed) const override
      {
        for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
          {
            Tensor<2, dim> gradient;
            for (unsigned int c = 0; c < dim; ++c)
              gradient[c] = inputs.solution_gradients[q][c];
            const SymmetricTensor<2, dim> strain = symmetrize(gradient);
            const SymmetricTensor<2, dim> stress =
              lambda * trace(strain) * unit_symmetric_tensor<dim>() + 2. * mu * strain;
            unsigned int k = 0;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i; j < dim; ++j)
                computed[q](k++) = stress[i][j];
            SymmetricTensor<2, 3> stress_3d;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i; j < dim; ++j)
                stress_3d[i][j] = stress[i][j];
            if (dim == 2)
              stress_3d[2][2] = out_of_plane_factor * trace(strain);
            const SymmetricTensor<2, 3> s = deviator(stress_3d);
            computed[q](k)                = std::sqrt(1.5 * scalar_product(s, s));
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        const char               axis[] = {'x', 'y', 'z'};
        std::vector<std::string> names;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            names.push_back(std::string("stress_") + axis[i] + axis[j]);
        names.push_back("von_mises_stress");
        return names;
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_gradients;
      }

    private:
      const double lambda;
      const double mu;
      const double out_of_plane_factor;
    };
  } // namespace

  template <int dim>
  FEOutput<dim>::FEOutput(const FEZone<dim> &fe_zone, const Parameters::Output &parameters)
    : fe_zone(fe_zone)
    , parameters(parameters)
    , series(parameters.directory + "/" + parameters.base_name + "_fe.pvd",
             fe_zone.get_dof_handler().get_communicator())
  {}

  template <int dim>
  void
  FEOutput<dim>::write(const unsigned int                                step,
                       const double                                      time,
                       const LinearAlgebra::distributed::Vector<double> &displacement,
                       const LinearAlgebra::distributed::Vector<double> &velocity)
  {
    displacement.update_ghost_values();
    velocity.update_ghost_values();

    const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector_field(
      dim,
      DataComponentInterpretation::component_is_part_of_vector);
    const StressPostprocessor<dim> stress(fe_zone.get_material());

    DataOut<dim> data_out;
    data_out.attach_dof_handler(fe_zone.get_dof_handler());
    data_out.add_data_vector(displacement,
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim>::type_dof_data,
                             vector_field);
    data_out.add_data_vector(velocity,
                             std::vector<std::string>(dim, "velocity"),
                             DataOut<dim>::type_dof_data,
                             vector_field);
    data_out.add_data_vector(displacement, stress);
    data_out.build_patches();
    data_out.set_flags(vtk_flags(parameters, time, step));

    const MPI_Comm    communicator = fe_zone.get_dof_handler().get_communicator();
    const std::string name         = data_out.write_vtu_with_pvtu_record(parameters.directory + "/",
                                                                 parameters.base_name + "_fe",
                                                                 step,
                                                                 communicator,
                                                                 6);
    series.add(time, name);
    displacement.zero_out_ghost_values();
    velocity.zero_out_ghost_values();
  }

  template <int dim>
  PVDSeries &
  FEOutput<dim>::get_series()
  {
    return series;
  }

  template class FEOutput<2>;
  template class FEOutput<3>;
} // namespace PeriArlequin
