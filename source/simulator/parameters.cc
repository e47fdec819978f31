#include <periarlequin/simulator.h>
#include <periarlequin/simulator/checkpoint_record.h>

#include <sstream>

namespace PeriArlequin
{
  namespace Parameters
  {
    void
    Run::entries(ParameterEntries &entries)
    {
      entries.add("Dimension",
                  dimension,
                  Patterns::Integer(2, 3),
                  "Space dimension of the run (2: plane stress or plane strain, 3).");
    }

    template <int dim>
    void
    Postprocess<dim>::entries(ParameterEntries &entries)
    {
      entries.add("List of postprocessors",
                  postprocessors,
                  Patterns::MultipleSelection(PostprocessorRegistry<dim>::names()),
                  "Postprocessors that add columns to the energy history (CSV) at every "
                  "recorded step (Output/Energy interval), by registered name:" +
                    PostprocessorRegistry<dim>::documentation() +
                    "\nA postprocessor's own parameters are in the subsection of its name.");
    }

    template <int dim>
    void
    ContactModel<dim>::entries(ParameterEntries &entries)
    {
      entries.add("Model",
                  model,
                  Patterns::Selection("none|" + ContactRegistry<dim>::names()),
                  "Contact of the FE boundary (and, for models that say so, of PD particles) "
                  "with an obstacle, by registered name (none: "
                  "no contact):" +
                    ContactRegistry<dim>::documentation() +
                    "\nA model's own parameters are in the subsection of its name.");
    }

    template struct Postprocess<2>;
    template struct Postprocess<3>;
    template struct ContactModel<2>;
    template struct ContactModel<3>;
  } // namespace Parameters

  template <int dim>
  void
  Simulator<dim>::declare_parameters(ParameterHandler &prm)
  {
    ParameterEntries::declare_here<Parameters::Run>(prm);
    Parameters::Geometry::declare_parameters(prm);
    Parameters::Material::declare_parameters(prm);
    Parameters::FiniteElements::declare_parameters(prm);
    Parameters::Time::declare_parameters(prm);
    Parameters::StaticSolve<dim>::declare_parameters(prm);
    Parameters::Output::declare_parameters(prm);
    Parameters::Checkpoint::declare_parameters(prm);
    Parameters::Peridynamics<dim>::declare_parameters(prm);
    Parameters::Coupling::declare_parameters(prm);
    ProblemData<dim>::declare_parameters(prm);
    prm.enter_subsection("Postprocess");
    ParameterEntries::declare_here<Parameters::Postprocess<dim>>(prm);
    PostprocessorRegistry<dim>::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Contact");
    ParameterEntries::declare_here<Parameters::ContactModel<dim>>(prm);
    ContactRegistry<dim>::declare_parameters(prm);
    prm.leave_subsection();
    PDZoneGrowth<dim>::declare_parameters(prm);
  }

  template <int dim>
  Simulator<dim>::Simulator(ParameterHandler &prm, const MPI_Comm communicator)
    : communicator(communicator)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(communicator) == 0)
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    , triangulation(communicator)
  {
    Parameters::Run run;
    ParameterEntries::parse_here(prm, run, "");
    AssertThrow(run.dimension == dim,
                ExcMessage("The parameters declare Dimension = " + std::to_string(run.dimension) +
                           " but are run by a " + std::to_string(dim) + "D simulator."));
    geometry.parse_parameters(prm, dim);
    material.parse_parameters(prm);
    fe_parameters.parse_parameters(prm);
    time_parameters.parse_parameters(prm);
    static_parameters.parse_parameters(prm);
    if (!static_parameters.released_cracks.empty() &&
        time_parameters.integration != Parameters::Integration::static_then_explicit)
      throw_invalid_parameter("Static solve/Released cracks",
                              static_parameters.released_cracks_text,
                              "empty unless Time/Integration = static then explicit (they are "
                              "released when the static solve is done)");
    if (time_parameters.integration == Parameters::Integration::quasi_static)
      {
        const double step = static_parameters.load_step;
        if (!(step > 0))
          throw_invalid_parameter("Static solve/Load step",
                                  step,
                                  "a value > 0 [s] with Time/Integration = quasi-static (the "
                                  "time between the equilibria)");
        // The increment counter is an unsigned int, and each increment is a static solve.
        const double max_increments = 1e6;
        if (!(time_parameters.end_time / step <= max_increments))
          {
            std::ostringstream allowed;
            allowed << "at most " << max_increments
                    << " quasi-static increments, End time <= " << max_increments * step
                    << " s with Static solve/Load step = " << step << " s";
            throw_invalid_parameter("Time/End time", time_parameters.end_time, allowed.str());
          }
      }
    output_parameters.parse_parameters(prm);
    checkpoint_parameters.parse_parameters(prm);
    physics_parameters = checkpointed_parameters(prm);
    pd_parameters.parse_parameters(prm);
    coupling_parameters.parse_parameters(prm);
    problem_data.parse_parameters(prm);
    if (!pd_parameters.region.empty())
      {
        prm.enter_subsection("Peridynamics");
        pd_material = PDMaterialRegistry<dim>::create(pd_parameters.material_model, prm);
        if (pd_parameters.fracture)
          fracture_criterion =
            FractureCriterionRegistry<dim>::create(pd_parameters.fracture_criterion, prm);
        prm.leave_subsection();
      }
    prm.enter_subsection("Contact");
    Parameters::ContactModel<dim> contact_choice;
    ParameterEntries::parse_here(prm, contact_choice, "Contact/");
    contact_model = contact_choice.model;
    if (contact_model != "none")
      contact = ContactRegistry<dim>::create(contact_model, prm);
    if (contact_model != "none" &&
        time_parameters.integration != Parameters::Integration::explicit_dynamics)
      throw_invalid_parameter("Time/Integration",
                              selection_name(time_parameters.integration,
                                             Parameters::integration_names),
                              "explicit while a contact model is on (Contact/Model = " +
                                contact_model + "): the static solve does not treat contact");
    prm.leave_subsection();
    zone_growth = PDZoneGrowth<dim>::create(prm, coupling_parameters, pd_parameters);
    prm.enter_subsection("Postprocess");
    Parameters::Postprocess<dim> postprocess;
    ParameterEntries::parse_here(prm, postprocess, "Postprocess/");
    for (const auto &name : Utilities::split_string_list(postprocess.postprocessors))
      postprocessors.push_back(PostprocessorRegistry<dim>::create(name, prm));
    prm.leave_subsection();
    if (coupling_parameters.coupled())
      {
        // Quadratic shape functions integrate to zero against alpha next to the alpha = 0
        // edge, so the blended lumped masses of eq. 50 vanish there.
        if (fe_parameters.degree != 1)
          throw_invalid_parameter("Finite elements/Polynomial degree",
                                  fe_parameters.degree,
                                  "1 when the zones are coupled (Coupling/Method = " +
                                    coupling_parameters.method +
                                    "): the alpha-weighted lumped masses of higher degrees "
                                    "vanish at the edge of the overlap");
        prm.enter_subsection("Coupling");
        coupling =
          CouplingRegistry<dim>::create(coupling_parameters.method, prm, coupling_parameters);
        prm.leave_subsection();
        blending = std::make_unique<BlendingField<dim>>(coupling_parameters,
                                                        coupling->blending_profile(),
                                                        pd_parameters.region);
      }
    monitor_region =
      output_parameters.monitor_region.empty() ?
        pd_parameters.region :
        Region<dim>::parse(output_parameters.monitor_region, "Output/Monitor region");
    if (!output_parameters.sample_line.empty())
      {
        const auto [a, b] = parse_segment<dim>(output_parameters.sample_line, "Output/Sample line");
        line_samples      = std::make_unique<LineSamples<dim>>(a,
                                                          b,
                                                          output_parameters,
                                                          pd_parameters.lattice_spacing,
                                                          communicator);
      }
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace PeriArlequin
