#ifndef periarlequin_pd_pd_parameters_h
#define periarlequin_pd_pd_parameters_h

#include <periarlequin/base/problem_data.h>
#include <periarlequin/base/regions.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/fe/component_mask.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  namespace Parameters
  {
    /** Does a prescribed region's Function give the velocity (or the displacement)? */
    inline const SelectionNames<bool> prescribed_quantity_names = {{"displacement", false},
                                                                   {"velocity", true}};

    /** A particle region whose displacement or velocity is prescribed. */
    template <int dim>
    struct PrescribedParticleRegion
    {
      Region<dim>                                     region;
      bool                                            prescribes_velocity = false;
      ComponentMask                                   components;
      std::unique_ptr<Functions::ParsedFunction<dim>> function;

      /** Region, Type and Components (Function has a helper shared with the FE zone). */
      void
      entries(ParameterEntries &entries);
    };

    /**
     * Short-range repulsion between PD particles that no intact bond joins (crack faces,
     * fragments, separate bodies): a pair closer than d_c pushes apart with k (d_c - r).
     */
    struct ParticleContact
    {
      bool enabled = false;
      /** d_c / dx [-]. */
      double distance_factor = 0.9;
      /** k / (E dx^(dim-2)) [-]. */
      double stiffness_factor = 0.3;

      void
      entries(ParameterEntries &entries);
    };

    /** The peridynamic zone: where, how fine, which model, fracture, particle conditions. */
    template <int dim>
    struct Peridynamics
    {
      static constexpr unsigned int n_prescribed_regions = 4;

      Region<dim> region;
      double      lattice_spacing = 0.0025;
      double      horizon_factor  = 3.015;
      std::string material_model  = "LPS";
      /** How the model loops over the bonds: automatic, stencil or bond list. */
      std::string force_kernel = "automatic";
      bool        fracture     = false;
      /** The registered fracture criterion used when fracture is on. */
      std::string                fracture_criterion  = "critical stretch";
      double                     energy_release_rate = 0;
      double                     critical_stretch    = 0;
      std::vector<PreCrack<dim>> pre_cracks;
      Region<dim>                no_fail_region;
      bool                       unbreakable_traction_layer = true;
      std::array<PrescribedParticleRegion<dim>, n_prescribed_regions> prescribed;
      ParticleContact                                                 contact;

      void
      entries(ParameterEntries &entries);

      double
      horizon() const;

      /**
       * How far beyond the PD part of a coupled case the particles reach: two bond reaches,
       * 2 (delta + dx/2), so that no weighted particle has a cut family and neither has any
       * of its neighbours, whose dilatation enters its force [m].
       */
      double
      coupled_particle_reach() const;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace PeriArlequin

#endif
