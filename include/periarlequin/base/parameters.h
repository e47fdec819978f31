#ifndef periarlequin_base_parameters_h
#define periarlequin_base_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>
#include <deal.II/fe/component_mask.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

/**
 * Parameter structures of the parts of a simulation. Each one declares its own documented
 * subsection of the input file and parses (and validates) it, ASPECT style.
 */
namespace PeriArlequin
{
  using namespace dealii;

  /**
   * Throw a uniform error for an invalid input value: it names the parameter (with its
   * subsection path), the value that was given and what is allowed.
   */
  [[noreturn]] void
  throw_invalid_parameter(const std::string &parameter,
                          const std::string &value,
                          const std::string &allowed);

  /** The same for a number, printed as the parameter file would give it. */
  [[noreturn]] void
  throw_invalid_parameter(const std::string &parameter,
                          const double       value,
                          const std::string &allowed);

  /**
   * The values of an enumeration with the names a parameter file gives them: one table per
   * enumeration declares the entry's pattern (selection_pattern) and converts what was read
   * (selection_value), so names and values cannot drift apart.
   */
  template <typename Enum>
  using SelectionNames = std::vector<std::pair<std::string, Enum>>;

  /** Patterns::Selection of the names of @p names. */
  template <typename Enum>
  Patterns::Selection
  selection_pattern(const SelectionNames<Enum> &names)
  {
    std::string list;
    for (const auto &[name, value] : names)
      list += (list.empty() ? "" : "|") + name;
    return Patterns::Selection(list);
  }

  /** The value named @p name in @p names (the entry's pattern has checked the name). */
  template <typename Enum>
  Enum
  selection_value(const std::string &name, const SelectionNames<Enum> &names)
  {
    for (const auto &[candidate, value] : names)
      if (candidate == name)
        return value;
    AssertThrow(false, ExcMessage("'" + name + "' is not a name of the selection."));
    return names.front().second;
  }

  /** The name of @p value in @p names. */
  template <typename Enum>
  const std::string &
  selection_name(const Enum value, const SelectionNames<Enum> &names)
  {
    for (const auto &[name, candidate] : names)
      if (candidate == value)
        return name;
    AssertThrow(false, ExcMessage("A value without a name in its selection."));
    return names.front().first;
  }

  /**
   * The entries of one parameter structure, written once for declaring and for parsing: a
   * structure lists its entries in `void entries(ParameterEntries &entries)` with add() and
   * add_parsed(), which declare() runs on a default-constructed structure (the members'
   * initial values are the declared defaults) and parse() on the structure being filled.
   * The path (subsection/...) names the entries in error messages.
   */
  class ParameterEntries
  {
  public:
    /** Declare the entries of @p Structure in subsection @p subsection. */
    template <typename Structure>
    static void
    declare(ParameterHandler &prm, const std::string &subsection)
    {
      prm.enter_subsection(subsection);
      declare_here<Structure>(prm);
      prm.leave_subsection();
    }

    /**
     * Declare the entries of @p Structure in the current subsection (plugins), with the
     * defaults and documentation of @p defaults (default constructed if not given).
     */
    template <typename Structure>
    static void
    declare_here(ParameterHandler &prm, Structure defaults = Structure())
    {
      ParameterEntries entries(prm, "", false);
      defaults.entries(entries);
    }

    /** Read the entries of @p structure from the current subsection, whose path is @p path. */
    template <typename Structure>
    static void
    parse_here(ParameterHandler &prm, Structure &structure, const std::string &path)
    {
      ParameterEntries entries(prm, path, true);
      structure.entries(entries);
    }

    /**
     * Read the entries of @p structure from subsection @p subsection (inside the current
     * subsection, whose path @p parent_path, "A/B/", is for error messages).
     */
    template <typename Structure>
    static void
    parse(ParameterHandler  &prm,
          const std::string &subsection,
          Structure         &structure,
          const std::string &parent_path = "")
    {
      prm.enter_subsection(subsection);
      parse_here(prm, structure, parent_path + subsection + "/");
      prm.leave_subsection();
    }

    /** An entry of a type deal.II converts (number, bool, string, vector of these). */
    template <typename T>
    void
    add(const std::string           &name,
        T                           &member,
        const Patterns::PatternBase &pattern,
        const std::string           &documentation)
    {
      using Convert = Patterns::Tools::Convert<T>;
      if (parsing)
        member = Convert::to_value(prm.get(name), pattern);
      else
        prm.declare_entry(name, Convert::to_string(member, pattern), pattern, documentation);
    }

    /** An enumeration: a selection among the names of @p names. */
    template <typename Enum>
    void
    add(const std::string          &name,
        Enum                       &member,
        const SelectionNames<Enum> &names,
        const std::string          &documentation)
    {
      if (parsing)
        member = selection_value(prm.get(name), names);
      else
        for (const auto &[text, value] : names)
          if (value == member)
            prm.declare_entry(name, text, selection_pattern(names), documentation);
    }

    /**
     * A selection of displacement components, "x, y[, z]" in @p dim dimensions, as a
     * ComponentMask (declared default: the components @p member selects, all if it is empty).
     */
    void
    add_components(const std::string &name,
                   ComponentMask     &member,
                   const unsigned int dim,
                   const std::string &documentation)
    {
      const char *axes[3] = {"x", "y", "z"};
      if (parsing)
        {
          std::vector<bool> selected(dim, false);
          for (const std::string &c : Utilities::split_string_list(prm.get(name)))
            selected[c == "x" ? 0 : (c == "y" ? 1 : 2)] = true;
          member = ComponentMask(selected);
          return;
        }
      std::string choices, default_text;
      for (unsigned int d = 0; d < dim; ++d)
        {
          choices += (d > 0 ? "|" : "") + std::string(axes[d]);
          if (member.size() == 0 || member[d])
            default_text += (default_text.empty() ? "" : ", ") + std::string(axes[d]);
        }
      prm.declare_entry(name, default_text, Patterns::MultipleSelection(choices), documentation);
    }

    /**
     * A text entry parsed into an object at parse time by @p parse(text, path of the entry)
     * (regions, cracks), with the default text @p default_text.
     */
    template <typename Parsed>
    void
    add_parsed(const std::string                                                     &name,
               Parsed                                                                &member,
               const std::string                                                     &default_text,
               const std::function<Parsed(const std::string &, const std::string &)> &parse,
               const std::string                                                     &documentation)
    {
      if (parsing)
        member = parse(prm.get(name), path + name);
      else
        prm.declare_entry(name, default_text, Patterns::Anything(), documentation);
    }

  private:
    ParameterEntries(ParameterHandler &prm, const std::string &path, const bool parsing)
      : prm(prm)
      , path(path)
      , parsing(parsing)
    {}

    ParameterHandler &prm;
    const std::string path;
    const bool        parsing;
  };

  namespace Parameters
  {
    /**
     * The domain: a box meshed by a subdivided hyper-rectangle, or a mesh read from a Gmsh
     * file (then the corners become the mesh's bounding box, the PD lattice's anchor).
     */
    struct Geometry
    {
      std::string               mesh_file;
      std::vector<double>       lower_corner       = {0, 0};
      std::vector<double>       upper_corner       = {1, 1};
      std::vector<unsigned int> subdivisions       = {10, 10};
      unsigned int              global_refinements = 0;

      void
      entries(ParameterEntries &entries);
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const unsigned int dim);
    };

    /** How a two-dimensional model reads the third direction. */
    enum class PlanarModel
    {
      plane_stress,
      plane_strain
    };

    inline const SelectionNames<PlanarModel> planar_model_names =
      {{"plane stress", PlanarModel::plane_stress}, {"plane strain", PlanarModel::plane_strain}};

    /** Isotropic linear elastic material shared by the FE and PD zones. */
    struct Material
    {
      double      youngs_modulus = 69e9;
      double      poissons_ratio = 0.3;
      double      density        = 2700;
      PlanarModel planar_model   = PlanarModel::plane_stress;

      void
      entries(ParameterEntries &entries);
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /** Shear modulus mu [Pa]. */
      double
      shear_modulus() const;
      /** Three-dimensional bulk modulus K [Pa]. */
      double
      bulk_modulus() const;
      /**
       * First Lame constant of the model in @p dim dimensions [Pa]: in plane stress the
       * eliminated out-of-plane strain turns lambda into 2 lambda mu / (lambda + 2 mu).
       */
      double
      effective_lambda(const unsigned int dim) const;
      /** Speed of plane longitudinal waves, sqrt((lambda_eff + 2 mu) / rho) [m/s]. */
      double
      longitudinal_wave_speed(const unsigned int dim) const;
      /**
       * Speed of shear waves, sqrt(mu / rho) [m/s]: above the Rayleigh speed, the limit of a
       * running crack.
       */
      double
      shear_wave_speed() const;
    };

    /** The finite-element discretisation of the classical zone. */
    struct FiniteElements
    {
      unsigned int degree = 1;

      void
      entries(ParameterEntries &entries);
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** How the time loop advances. */
    enum class Integration
    {
      /** The explicit loop from the initial conditions. */
      explicit_dynamics,
      /** The static equilibrium under the loads of t = 0 first, then the explicit loop. */
      static_then_explicit,
      /**
       * A sequence of static equilibria under the loads of t = k x Static solve/Load step,
       * bonds breaking between re-equilibrations.
       */
      quasi_static
    };

    inline const SelectionNames<Integration> integration_names = {
      {"explicit", Integration::explicit_dynamics},
      {"static then explicit", Integration::static_then_explicit},
      {"quasi-static", Integration::quasi_static}};

    struct Time
    {
      Integration integration = Integration::explicit_dynamics;
      double      time_step   = 1e-7;
      double      end_time    = 1e-5;
      /** Power iterations allowed for the estimate of the largest eigenvalue of M^-1 K. */
      unsigned int stability_iterations = 200;

      void
      entries(ParameterEntries &entries);
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** The zlib level of the field files' data. */
    enum class OutputCompression
    {
      /** zlib's fastest level. */
      fast,
      /** zlib's smallest (deal.II's default). */
      small,
      /** No compression. */
      none
    };

    inline const SelectionNames<OutputCompression> output_compression_names = {
      {"fast", OutputCompression::fast},
      {"small", OutputCompression::small},
      {"none", OutputCompression::none}};

    /** What is written, where, and how often. */
    struct Output
    {
      std::string       directory         = "output";
      std::string       base_name         = "solution";
      unsigned int      output_interval   = 100;
      unsigned int      energy_interval   = 1;
      double            progress_interval = 5;
      bool              print_timing      = true;
      OutputCompression compression       = OutputCompression::fast;
      /**
       * Segment "x0, y0 : x1, y1" along which displacements are sampled ("" for none), and
       * boxes whose PD energies are recorded as the pure PD zone's ("": the PD region). Kept
       * as text because this structure does not know the dimension: the Simulator parses
       * them at construction, so --check validates them.
       */
      std::string sample_line, monitor_region;

      void
      entries(ParameterEntries &entries);
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** When to write checkpoints, and whether to resume from one. */
    struct Checkpoint
    {
      unsigned int interval           = 0;
      double       wall_time_interval = 0;
      bool         at_end             = false;
      bool         resume             = false;

      void
      entries(ParameterEntries &entries);
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace PeriArlequin

#endif
