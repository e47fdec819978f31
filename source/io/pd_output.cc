#include <periarlequin/io/pd_output.h>

#include <deal.II/particles/data_out.h>

namespace PeriArlequin
{
  template <int dim>
  PDOutput<dim>::PDOutput(PDZone<dim> &pd_zone, const Parameters::Output &parameters)
    : pd_zone(pd_zone)
    , parameters(parameters)
    , series(parameters.directory + "/" + parameters.base_name + "_pd.pvd",
             pd_zone.get_communicator())
  {}

  template <int dim>
  void
  PDOutput<dim>::write(const unsigned int step, const double time)
  {
    const auto names = pd_zone.store_output_properties();
    std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation(
      names.size(),
      DataComponentInterpretation::component_is_scalar);
    for (unsigned int k = 0; k < 2 * dim; ++k)
      interpretation[k] = DataComponentInterpretation::component_is_part_of_vector;

    Particles::DataOut<dim> data_out;
    data_out.build_patches(pd_zone.get_particle_handler(), names, interpretation);
    data_out.set_flags(vtk_flags(parameters, time, step));
    series.add(time,
               data_out.write_vtu_with_pvtu_record(parameters.directory + "/",
                                                   parameters.base_name + "_pd",
                                                   step,
                                                   pd_zone.get_communicator(),
                                                   6));
  }

  template <int dim>
  PVDSeries &
  PDOutput<dim>::get_series()
  {
    return series;
  }

  template class PDOutput<2>;
  template class PDOutput<3>;
} // namespace PeriArlequin
