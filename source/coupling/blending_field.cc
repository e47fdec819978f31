#include <periarlequin/coupling/blending_field.h>
#include <periarlequin/coupling/coupling.h>

#include <cmath>
#include <sstream>

namespace PeriArlequin
{
  namespace Parameters
  {
    void
    Coupling::entries(ParameterEntries &entries)
    {
      // Couplings are registered for both dimensions under the same names.
      entries.add("Method",
                  method,
                  Patterns::Selection("none|" + CouplingRegistry<2>::names()),
                  "How the PD and FE zones are glued: none (uncoupled) or a registered "
                  "coupling:" +
                    CouplingRegistry<2>::documentation() +
                    "\nA coupling's own parameters are in the subsection of its name.");
      entries.add("Overlap region",
                  overlap_text,
                  Patterns::Anything(),
                  "Boxes 'lower : upper ; ...' [m] where both zones live and alpha rises "
                  "linearly from 0 (edge on the PD region) to 1 (edge on the FE region). "
                  "Peridynamics/Region is the pure PD zone.");
      entries.add("Finite element region",
                  fe_region_text,
                  Patterns::Anything(),
                  "Boxes 'lower : upper ; ...' [m] of the pure FE zone (alpha = 1). The PD "
                  "region, the overlap and this region must cover the domain.");
      entries.add("Overlap width",
                  overlap_width,
                  Patterns::Double(0),
                  "If positive, the overlap is the band of this width around "
                  "Peridynamics/Region, alpha = min(1, distance to the PD region / width), "
                  "and the FE region is the rest: leave Overlap region and Finite element "
                  "region empty. Required by an adaptive PD zone, whose band moves with the "
                  "region. At least one FE cell wide [m].");
      entries.add("Blending",
                  blending,
                  blending_names,
                  "Where alpha enters the forces: paper (FE weight inside the stiffness "
                  "integral, PD force weighted per node, eq. 47b and 55), energy (the weight "
                  "inside the sums on both sides, forces from the blended Hamiltonian), force "
                  "(nodal weights on both sides, FE force alpha_I (K u)_I).");
      entries.add("Multiplier solver",
                  multiplier_solver,
                  multiplier_solver_names,
                  "How A lambda = H^T (N v* - w*) is solved: diagonal (the paper's row-sum "
                  "diagonal of A, eq. 68) or cg (conjugate gradients to a relative residual "
                  "of 1e-12).");
      entries.add("Fine-scale damping",
                  damping,
                  Patterns::Bool(),
                  "Damp the fine-scale velocity w - N v of the PD nodes of the overlap "
                  "(eq. 76-80) with C_I = C v_w alpha_I^2 / L_B.");
      entries.add("Damping constant",
                  damping_constant,
                  Patterns::Double(0),
                  "C of eq. 78 [-]. The paper's value is 30; 10 with the default lambda-mesh "
                  "(Coupling/weak/Multiplier spacing = 2) kept the reflection of the whole band "
                  "below 4 % in the measured overlaps of 3 and 5 cells and costs resolved waves "
                  "less (studies/wave_coupling/README.md, also where it does not hold).");
      entries.add("Damping wave speed",
                  damping_wave_speed,
                  Patterns::Double(0),
                  "v_w of eq. 78 [m/s]; 0: the longitudinal wave speed of the material "
                  "(plane stress or plane strain in 2D).");
      entries.add("Damping overlap width",
                  damping_overlap_width,
                  Patterns::Double(0),
                  "L_B of eq. 78 [m]; 0: the local width of the overlap, l1 + l2.");
      entries.add("Damping integration",
                  damping_integration,
                  damping_integration_names,
                  "Which velocity the damping force -C_I (w - N v) takes in a step: implicit "
                  "(the end-of-step velocity, solved node by node: stable for any C up to the "
                  "undamped stable step) or half step (the half-step velocity of the paper's "
                  "eq. 79c: explicit, the damping lowers the stable step, by 23 % with C = 10, "
                  "a 5 mm overlap and glass at dx = 0.35 mm; a step above the lowered one is "
                  "refused).");
      entries.add("Minimum PD weight",
                  minimum_pd_weight,
                  Patterns::Double(0, 1),
                  "PD nodes whose weight 1 - alpha is below this follow the FE field as "
                  "slaves, their mass added to the FE nodes; every other PD node of the "
                  "overlap has the mass (1 - alpha) rho V, in proportion to its stiffness, so "
                  "its own motion is that of the lattice. Nodes next to the alpha = 1 edge "
                  "with a tiny weight but free would lag behind the FE field and stretch "
                  "their bonds to the slaves [-].");
      entries.add("Strain check interval",
                  strain_check_interval,
                  Patterns::Integer(0),
                  "With fracture: every this many steps, the largest principal strain of the "
                  "FE field at the centre of every cell with FE unknowns (overlap and FE "
                  "zone; the cell's mean strain, as a bond about a cell long sees it) is "
                  "compared with the critical stretch. Where it reaches it, PD might break "
                  "bonds that the FE zone cannot: the run warns with the time and the place "
                  "(enlarge the PD region, or let it grow with the strain criterion of "
                  "Adaptive PD zone). 0: no check [-].");
    }

    void
    Coupling::declare_parameters(ParameterHandler &prm)
    {
      ParameterEntries::declare<Coupling>(prm, "Coupling");
      prm.enter_subsection("Coupling");
      CouplingRegistry<2>::declare_parameters(prm);
      prm.leave_subsection();
    }

    void
    Coupling::parse_parameters(ParameterHandler &prm)
    {
      ParameterEntries::parse(prm, "Coupling", *this);
      if (coupled() && !(minimum_pd_weight > 0))
        throw_invalid_parameter("Coupling/Minimum PD weight",
                                minimum_pd_weight,
                                "a value in (0, 1] when the zones are coupled");
    }

    bool
    Coupling::coupled() const
    {
      return method != "none";
    }
  } // namespace Parameters

  namespace
  {
    template <int dim>
    std::string
    box_text(const Box<dim> &box)
    {
      std::ostringstream text;
      text << box.lower << " : " << box.upper;
      return text.str();
    }
  } // namespace

  template <int dim>
  BlendingField<dim>::BlendingField(const Parameters::Coupling &coupling,
                                    const BlendingProfile       profile,
                                    const Region<dim>          &pure_pd_region)
    : profile(profile)
    , pure_pd(pure_pd_region)
    , overlap_region(Region<dim>::parse(coupling.overlap_text, "Coupling/Overlap region"))
    , pure_fe(Region<dim>::parse(coupling.fe_region_text, "Coupling/Finite element region"))
    , overlap_text(coupling.overlap_text)
    , fe_region_text(coupling.fe_region_text)
    , band_width(coupling.overlap_width)
    , distance_to_pure_pd(pure_pd_region)
  {
    if (pure_pd.empty())
      throw_invalid_parameter("Peridynamics/Region",
                              "",
                              "at least one box (the pure PD zone) when Coupling/Method is not "
                              "none");

    if (band_width > 0)
      {
        for (const auto &[name, text] :
             {std::make_pair("Coupling/Overlap region", coupling.overlap_text),
              std::make_pair("Coupling/Finite element region", coupling.fe_region_text)})
          if (!text.empty())
            throw_invalid_parameter(name,
                                    text,
                                    "nothing when Coupling/Overlap width is set: the overlap "
                                    "is then the band around the PD region and the FE region "
                                    "the rest");
        return;
      }

    if (overlap_region.empty())
      throw_invalid_parameter("Coupling/Overlap region",
                              coupling.overlap_text,
                              "at least one box when Coupling/Method is not none (or a band: "
                              "Coupling/Overlap width)");
    if (pure_fe.empty())
      throw_invalid_parameter("Coupling/Finite element region",
                              coupling.fe_region_text,
                              "at least one box (the pure FE zone) when Coupling/Method is not "
                              "none and no Coupling/Overlap width is set");
  }

  template <int dim>
  void
  BlendingField<dim>::check_against_mesh(const Tensor<1, dim>          &cell_size,
                                         const std::vector<Point<dim>> &points)
  {
    length_tolerance = 1e-10 * cell_size.norm();

    if (band_width > 0)
      {
        double largest_cell = 0;
        for (unsigned int d = 0; d < dim; ++d)
          largest_cell = std::max(largest_cell, cell_size[d]);
        if (band_width < largest_cell * (1. - 1e-10))
          {
            std::ostringstream allowed;
            allowed << "a band at least one FE cell (" << largest_cell << " m) wide";
            throw_invalid_parameter("Coupling/Overlap width", band_width, allowed.str());
          }
        return;
      }

    // The alpha = 0 and alpha = 1 edges: apart by at least one cell across the overlap.
    for (const auto &pd_box : pure_pd.boxes)
      for (const auto &fe_box : pure_fe.boxes)
        {
          const Tensor<1, dim> gap = pd_box.gap(fe_box);
          if (gap.norm() == 0)
            throw_invalid_parameter("Coupling/Finite element region",
                                    fe_region_text,
                                    "boxes that neither touch nor cross the pure PD region "
                                    "(here " +
                                      box_text(fe_box) + " meets " + box_text(pd_box) +
                                      "): the alpha = 0 and alpha = 1 edges must be an "
                                      "overlap apart");
          unsigned int across = 0;
          for (unsigned int d = 1; d < dim; ++d)
            if (gap[d] > gap[across])
              across = d;
          if (gap.norm() < cell_size[across] * (1. - 1e-10))
            {
              std::ostringstream allowed;
              allowed << "an overlap at least one FE cell (" << cell_size[across]
                      << " m) wide; between this box and the PD box " << box_text(pd_box)
                      << " it is " << gap.norm() << " m";
              throw_invalid_parameter("Coupling/Overlap region", overlap_text, allowed.str());
            }
        }

    for (const Point<dim> &p : points)
      if (!pure_pd.contains(p, length_tolerance) && !overlap_region.contains(p, length_tolerance) &&
          !pure_fe.contains(p, length_tolerance))
        {
          std::ostringstream value;
          value << p;
          throw_invalid_parameter("Coupling/Finite element region",
                                  fe_region_text,
                                  "zones that cover the domain: the point " + value.str() +
                                    " is in none of Peridynamics/Region, Coupling/Overlap "
                                    "region and Coupling/Finite element region");
        }
  }

  template <int dim>
  double
  BlendingField<dim>::value(const Point<dim> &x) const
  {
    // Beyond the band alpha is 1: the distance is needed up to its width only.
    const double l1 = band_width > 0 ? distance_to_pure_pd.distance(x, band_width) :
                                       distance_to_pure_pd.distance(x);
    if (l1 == 0)
      return 0.;
    const double l2 = band_width > 0 ? std::max(band_width - l1, 0.) : pure_fe.distance(x);
    if (l2 == 0)
      return 1.;
    if (profile == BlendingProfile::step)
      return l1 < l2 ? 0. : 1.;
    return l1 / (l1 + l2);
  }

  template <int dim>
  bool
  BlendingField<dim>::in_overlap(const Point<dim> &x) const
  {
    if (band_width > 0)
      return distance_to_pure_pd.distance(x, 2. * band_width) <= band_width * (1. + 1e-12);
    return overlap_region.contains(x, 1e-12 * overlap_width(x));
  }

  template <int dim>
  double
  BlendingField<dim>::overlap_width(const Point<dim> &x) const
  {
    return band_width > 0 ? band_width : distance_to_pure_pd.distance(x) + pure_fe.distance(x);
  }

  template <int dim>
  double
  BlendingField<dim>::distance_to_pd_part(const Point<dim> &x, const double cap) const
  {
    if (band_width > 0)
      return std::max(distance_to_pure_pd.distance(x, cap + band_width) - band_width, 0.);
    return std::min(distance_to_pure_pd.distance(x, cap), overlap_region.distance(x));
  }

  template <int dim>
  const Region<dim> &
  BlendingField<dim>::pd_region() const
  {
    return pure_pd;
  }

  template <int dim>
  bool
  BlendingField<dim>::is_band() const
  {
    return band_width > 0;
  }

  template <int dim>
  void
  BlendingField<dim>::add_to_pd_region(const Region<dim> &converted)
  {
    Assert(is_band(), ExcMessage("Only a band overlap follows a growing PD region."));
    pure_pd.add(converted);
    pure_pd.coalesce(length_tolerance);
    distance_to_pure_pd = RegionDistance<dim>(pure_pd);
  }

  template <int dim>
  void
  BlendingField<dim>::set_pd_region(const Region<dim> &grown)
  {
    Assert(is_band(), ExcMessage("Only a band overlap follows a growing PD region."));
    pure_pd             = grown;
    distance_to_pure_pd = RegionDistance<dim>(pure_pd);
  }

  template class BlendingField<2>;
  template class BlendingField<3>;
} // namespace PeriArlequin
