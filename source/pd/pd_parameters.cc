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
    double
    Peridynamics<dim>::coupled_particle_reach() const
    {
      return 2. * (horizon() + 0.5 * lattice_spacing) * (1. + 1e-10);
    }

    template <int dim>
    void
    PrescribedParticleRegion<dim>::entries(ParameterEntries &entries)
    {
      entries.add_parsed<Region<dim>>("Region",
                                      region,
                                      "",
                                      &Region<dim>::parse,
                                      "Boxes 'lower : upper ; ...' [m] whose particles have a "
                                      "prescribed motion (a fictitious boundary layer). Empty: "
                                      "unused.");
      entries.add("Type",
                  prescribes_velocity,
                  prescribed_quantity_names,
                  "Whether Function gives the displacement [m] or the velocity [m/s].");
      entries.add_components("Components", components, dim, "Prescribed components.");
    }

    void
    ParticleContact::entries(ParameterEntries &entries)
    {
      entries.add("Enable",
                  enabled,
                  Patterns::Bool(),
                  "Push apart PD particles that come closer than the contact distance and are "
                  "not joined by an intact bond: crack faces closing, fragments, separate "
                  "bodies. Acts between particles outside the overlap (alpha = 0).");
      entries.add("Distance factor",
                  distance_factor,
                  Patterns::Double(),
                  "Contact distance d_c over the lattice spacing, in (0, 1) [-]: below 1 so that "
                  "neighbours at rest do not touch; a pair closer than d_c repels.");
      entries.add("Stiffness factor",
                  stiffness_factor,
                  Patterns::Double(),
                  "Pair stiffness k over E dx^(dim-2), > 0 [-]: the force between two particles "
                  "at distance r < d_c is k (d_c - r) [N, per unit thickness in 2D]. With 1 a "
                  "touching pair is as stiff as a column of the material dx long and dx^(dim-1) "
                  "in section. The estimated stable step accounts for it: at 0.3 it is about "
                  "0.7 of the step without contact (0.86 at 0.1, 0.48 at 1); softer contact "
                  "lets faces overlap more, by sigma dx / k under a stress sigma.");
    }

    template <int dim>
    void
    Peridynamics<dim>::entries(ParameterEntries &entries)
    {
      entries.add_parsed<Region<dim>>("Region",
                                      region,
                                      "",
                                      &Region<dim>::parse,
                                      "Union of boxes filled with PD particles, 'x0, y0 : x1, "
                                      "y1 ; ...' (lower : upper corner) [m]. Empty: no PD "
                                      "zone. Cells whose centre lies in the region carry no FE "
                                      "unknowns.");
      entries.add("Lattice spacing",
                  lattice_spacing,
                  Patterns::Double(),
                  "Spacing dx of the regular particle lattice, > 0 [m]. The lattice is anchored "
                  "at the lower corner of the domain; a particle sits at every lattice cell "
                  "centre inside the region.");
      entries.add("Horizon factor",
                  horizon_factor,
                  Patterns::Double(),
                  "m = delta / dx, the horizon in lattice spacings, >= 1 [-].");
      entries.add("Material model",
                  material_model,
                  Patterns::Selection(PDMaterialRegistry<dim>::names()),
                  "The PD material model, by its registered name:" +
                    PDMaterialRegistry<dim>::documentation() +
                    "\nA model's own parameters are in the subsection of its name.");
      entries.add("Force kernel",
                  force_kernel,
                  Patterns::Selection("automatic|stencil|bond list"),
                  "How the material model visits the bonds: 'stencil' loops over lattice "
                  "offsets and contiguous runs of particles (no neighbour lists; vectorised; "
                  "the LPS model), 'bond list' over per-particle neighbour lists (any model), "
                  "'automatic' takes the stencil unless a rank's box of lattice sites holds more "
                  "than 4 sites per particle it holds. The results agree to round-off.");
      entries.add("Fracture",
                  fracture,
                  Patterns::Bool(),
                  "Break bonds irreversibly, as the fracture criterion says.");
      entries.add("Fracture criterion",
                  fracture_criterion,
                  Patterns::Selection(FractureCriterionRegistry<dim>::names()),
                  "When a bond breaks, by registered name:" +
                    FractureCriterionRegistry<dim>::documentation() +
                    "\nA criterion's own parameters are in the subsection of its name.");
      entries.add("Critical energy release rate",
                  energy_release_rate,
                  Patterns::Double(),
                  "G0 [J/m^2], > 0 when Fracture is on; gives the critical stretch through the "
                  "material model's formula.");
      entries.add("Critical stretch",
                  critical_stretch,
                  Patterns::Double(0),
                  "If > 0, the critical bond stretch [-] itself, overriding G0.");
      entries.add_parsed<std::vector<PreCrack<dim>>>(
        "Pre-cracks",
        pre_cracks,
        "",
        &PreCrack<dim>::parse_list,
        "Cracks that cut bonds at the start, separated by ';': segments 'x0, y0 : x1, y1' in "
        "2D, parallelograms 'corner : edge a : edge b' in 3D [m].");
      entries.add_parsed<Region<dim>>("No-fail region",
                                      no_fail_region,
                                      "",
                                      &Region<dim>::parse,
                                      "Boxes 'lower : upper ; ...' [m] in which bonds never "
                                      "break (a bond with either end inside). A sudden "
                                      "traction can break the first layers of its face in PD (a "
                                      "surface effect of the lattice); a box a horizon deep "
                                      "along the face keeps them, which a coupled run whose "
                                      "band reaches that face needs.");
      entries.add("Unbreakable traction layer",
                  unbreakable_traction_layer,
                  Patterns::Bool(),
                  "Bonds with an end in the layer of particles that carries a traction (the "
                  "sites within dx of the face, loaded by the force density t / dx) never "
                  "break. That layer passes the load on through fewer bonds than the bulk "
                  "has across a plane and strains them beyond the continuum's: a sudden 4 MPa "
                  "on glass breaks them (2D at dx = 0.625 mm, 3D at 0.7 mm) where the bulk "
                  "stays at a third of the critical stretch, damage of the lattice, not a "
                  "crack, which stops a coupled run whose band reaches that face. false: they "
                  "break as every bond.");
    }

    template <int dim>
    void
    Peridynamics<dim>::declare_parameters(ParameterHandler &prm)
    {
      ParameterEntries::declare<Peridynamics<dim>>(prm, "Peridynamics");
      prm.enter_subsection("Peridynamics");
      PDMaterialRegistry<dim>::declare_parameters(prm);
      FractureCriterionRegistry<dim>::declare_parameters(prm);
      for (unsigned int r = 0; r < n_prescribed_regions; ++r)
        {
          const std::string name = "Prescribed region " + std::to_string(r);
          ParameterEntries::declare<PrescribedParticleRegion<dim>>(prm, name);
          prm.enter_subsection(name);
          declare_vector_function<dim>(prm,
                                       "Function",
                                       "Prescribed displacement [m] or velocity [m/s].");
          prm.leave_subsection();
        }
      ParameterEntries::declare<ParticleContact>(prm, "Particle contact");
      prm.leave_subsection();
    }

    template <int dim>
    void
    Peridynamics<dim>::parse_parameters(ParameterHandler &prm)
    {
      ParameterEntries::parse(prm, "Peridynamics", *this);
      prm.enter_subsection("Peridynamics");
      for (unsigned int r = 0; r < n_prescribed_regions; ++r)
        {
          const std::string name = "Prescribed region " + std::to_string(r);
          auto             &p    = prescribed[r];
          ParameterEntries::parse(prm, name, p, "Peridynamics/");
          prm.enter_subsection(name);
          p.function = std::make_unique<Functions::ParsedFunction<dim>>(dim);
          parse_vector_function(prm, "Peridynamics/" + name + "/", "Function", *p.function);
          prm.leave_subsection();
        }
      ParameterEntries::parse(prm, "Particle contact", contact, "Peridynamics/");
      prm.leave_subsection();

      if (region.empty())
        return;
      if (!(lattice_spacing > 0))
        throw_invalid_parameter("Peridynamics/Lattice spacing", lattice_spacing, "a value > 0 [m]");
      if (!(horizon_factor >= 1))
        throw_invalid_parameter("Peridynamics/Horizon factor",
                                horizon_factor,
                                "a value >= 1 (the horizon spans at least one lattice spacing)");
      if (contact.enabled)
        {
          if (!(contact.distance_factor > 0 && contact.distance_factor < 1))
            throw_invalid_parameter("Peridynamics/Particle contact/Distance factor",
                                    contact.distance_factor,
                                    "a value in (0, 1): at 1 or more, lattice neighbours at rest "
                                    "would already push apart");
          if (!(contact.stiffness_factor > 0 && contact.stiffness_factor <= 1e3))
            throw_invalid_parameter("Peridynamics/Particle contact/Stiffness factor",
                                    contact.stiffness_factor,
                                    "a value in (0, 1000]");
        }
    }
  } // namespace Parameters
  namespace Parameters
  {
    template struct PrescribedParticleRegion<2>;
    template struct PrescribedParticleRegion<3>;
    template struct Peridynamics<2>;
    template struct Peridynamics<3>;
  } // namespace Parameters
} // namespace PeriArlequin
