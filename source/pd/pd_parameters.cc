#include <periarlequin/pd/fracture_criterion.h>
#include <periarlequin/pd/material_model.h>
#include <periarlequin/pd/pd_parameters.h>

namespace PeriArlequin
{
  namespace Parameters
  {
    template <int dim>
    double
    Peridynamics<dim>::horizon() const
    {
      return horizon_factor * lattice_spacing;
    }

    template <int dim>
    void
    Peridynamics<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Peridynamics");
      prm.declare_entry("Region",
                        "",
                        Patterns::Anything(),
                        "Union of boxes filled with PD particles, 'x0, y0 : x1, y1 ; ...' "
                        "(lower : upper corner) [m]. Empty: no PD zone. Cells whose centre lies "
                        "in the region carry no FE unknowns.");
      prm.declare_entry("Lattice spacing",
                        "0.0025",
                        Patterns::Double(),
                        "Spacing dx of the regular particle lattice, > 0 [m]. The lattice is "
                        "anchored at the lower corner of the domain; a particle sits at every "
                        "lattice cell centre inside the region.");
      prm.declare_entry("Horizon factor",
                        "3.015",
                        Patterns::Double(),
                        "m = delta / dx, the horizon in lattice spacings, >= 1 [-].");
      prm.declare_entry("Material model",
                        "LPS",
                        Patterns::Selection(PDMaterialRegistry<dim>::names()),
                        "The PD material model, by its registered name:" +
                          PDMaterialRegistry<dim>::documentation() +
                          "\nA model's own parameters are in the subsection of its name.");
      PDMaterialRegistry<dim>::declare_parameters(prm);
      prm.declare_entry("Fracture",
                        "false",
                        Patterns::Bool(),
                        "Break bonds irreversibly, as the fracture criterion says.");
      prm.declare_entry("Fracture criterion",
                        "critical stretch",
                        Patterns::Selection(FractureCriterionRegistry<dim>::names()),
                        "When a bond breaks, by registered name:" +
                          FractureCriterionRegistry<dim>::documentation() +
                          "\nA criterion's own parameters are in the subsection of its name.");
      FractureCriterionRegistry<dim>::declare_parameters(prm);
      prm.declare_entry("Critical energy release rate",
                        "0",
                        Patterns::Double(),
                        "G0 [J/m^2], > 0 when Fracture is on; gives the critical stretch "
                        "through the material model's formula.");
      prm.declare_entry("Critical stretch",
                        "0",
                        Patterns::Double(0),
                        "If > 0, the critical bond stretch [-] itself, overriding G0.");
      prm.declare_entry("Pre-cracks",
                        "",
                        Patterns::Anything(),
                        "Cracks that cut bonds at the start, separated by ';': segments "
                        "'x0, y0 : x1, y1' in 2D, parallelograms 'corner : edge a : edge b' "
                        "in 3D [m].");
      prm.declare_entry("No-fail region",
                        "",
                        Patterns::Anything(),
                        "Boxes 'lower : upper ; ...' [m] in which bonds never break (a bond "
                        "with either end inside).");
      for (unsigned int r = 0; r < n_prescribed_regions; ++r)
        {
          prm.enter_subsection("Prescribed region " + std::to_string(r));
          prm.declare_entry("Region",
                            "",
                            Patterns::Anything(),
                            "Boxes 'lower : upper ; ...' [m] whose particles have a prescribed "
                            "motion (a fictitious boundary layer). Empty: unused.");
          prm.declare_entry("Type",
                            "displacement",
                            selection_pattern(prescribed_quantity_names),
                            "Whether Function gives the displacement [m] or the velocity [m/s].");
          declare_component_selection<dim>(prm, "Prescribed components.");
          declare_vector_function<dim>(prm,
                                       "Function",
                                       "Prescribed displacement [m] or velocity [m/s].");
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    template <int dim>
    void
    Peridynamics<dim>::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Peridynamics");
      region              = Region<dim>::parse(prm.get("Region"), "Peridynamics/Region");
      lattice_spacing     = prm.get_double("Lattice spacing");
      horizon_factor      = prm.get_double("Horizon factor");
      material_model      = prm.get("Material model");
      fracture            = prm.get_bool("Fracture");
      fracture_criterion  = prm.get("Fracture criterion");
      energy_release_rate = prm.get_double("Critical energy release rate");
      critical_stretch    = prm.get_double("Critical stretch");
      pre_cracks = PreCrack<dim>::parse_list(prm.get("Pre-cracks"), "Peridynamics/Pre-cracks");
      no_fail_region =
        Region<dim>::parse(prm.get("No-fail region"), "Peridynamics/No-fail region");
      for (unsigned int r = 0; r < n_prescribed_regions; ++r)
        {
          const std::string path = "Peridynamics/Prescribed region " + std::to_string(r) + "/";
          prm.enter_subsection("Prescribed region " + std::to_string(r));
          auto &p               = prescribed[r];
          p.region              = Region<dim>::parse(prm.get("Region"), path + "Region");
          p.prescribes_velocity = selection_value(prm.get("Type"), prescribed_quantity_names);
          p.components          = parse_component_selection<dim>(prm);
          p.function   = std::make_unique<Functions::ParsedFunction<dim>>(dim);
          parse_vector_function(prm, path, "Function", *p.function);
          prm.leave_subsection();
        }
      prm.leave_subsection();

      if (region.empty())
        return;
      if (!(lattice_spacing > 0))
        throw_invalid_parameter("Peridynamics/Lattice spacing",
                                lattice_spacing,
                                "a value > 0 [m]");
      if (!(horizon_factor >= 1))
        throw_invalid_parameter("Peridynamics/Horizon factor",
                                horizon_factor,
                                "a value >= 1 (the horizon spans at least one lattice spacing)");
    }
  } // namespace Parameters
  namespace Parameters
  {
    template struct Peridynamics<2>;
    template struct Peridynamics<3>;
  } // namespace Parameters
} // namespace PeriArlequin
