#ifndef periarlequin_base_problem_data_h
#define periarlequin_base_problem_data_h

#include <periarlequin/base/initial_conditions.h>
#include <periarlequin/base/parameters.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/fe/component_mask.h>

#include <array>
#include <memory>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * Declare, in subsection @p name, the entries of a dim-component muparser function of
   * (x, y[, z], t) with named constants, documented by @p documentation (give the units).
   */
  template <int dim>
  void
  declare_vector_function(ParameterHandler  &prm,
                          const std::string &name,
                          const std::string &documentation);

  /**
   * Parse the function declared by declare_vector_function() in subsection @p name; a
   * malformed expression is reported with its full entry path @p path + @p name.
   */
  template <int dim>
  void
  parse_vector_function(ParameterHandler               &prm,
                        const std::string              &path,
                        const std::string              &name,
                        Functions::ParsedFunction<dim> &function);

  /** What a boundary of the box prescribes. */
  enum class BoundaryType
  {
    free,
    displacement,
    traction
  };

  inline const SelectionNames<BoundaryType> boundary_type_names = {
    {"free", BoundaryType::free},
    {"displacement", BoundaryType::displacement},
    {"traction", BoundaryType::traction}};

  /**
   * Condition on one boundary id: a prescribed displacement on the selected components, or a
   * traction vector, functions of (x, y[, z], t): muparser expressions, or the crack-tip field.
   */
  template <int dim>
  struct BoundaryCondition
  {
    /** The boundary id, named in the entries' documentation. */
    unsigned int                   id   = 0;
    BoundaryType                   type = BoundaryType::free;
    ComponentMask                  components;
    std::unique_ptr<Function<dim>> function;

    /** Type and Components of subsection "Boundary conditions/Boundary <id>". */
    void
    entries(ParameterEntries &entries);
  };

  namespace Parameters
  {
    /** Subsection "Initial conditions": the initial condition, by registered name. */
    template <int dim>
    struct InitialConditionModel
    {
      std::string model = "function";

      void
      entries(ParameterEntries &entries);
    };
  } // namespace Parameters

  /**
   * The data of an elastodynamic problem that do not depend on its discretisation: the
   * initial condition (a registered model), the body force and the condition on each
   * boundary id of the box, the latter vector-valued muparser expressions with named
   * constants ("Function constants"), or, for the ids listed in "Boundary conditions/Crack
   * tip field", the displacement of a mode I/II crack tip (CrackTipField).
   */
  template <int dim>
  class ProblemData
  {
  public:
    static constexpr unsigned int n_boundaries = 2 * dim;

    ProblemData();

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** The model selected in "Initial conditions/Model". */
    std::unique_ptr<InitialCondition<dim>> initial_condition;
    // Mutable: setting the evaluation time does not change the problem.
    /** Body force per unit volume [N/m^3]. */
    mutable Functions::ParsedFunction<dim> body_force;
    /** True unless every component of the body-force expression is the literal 0. */
    bool has_body_force = false;

    std::array<BoundaryCondition<dim>, n_boundaries> boundary_conditions;

    /** Whether any boundary carries a traction, i.e. a surface term of the external force. */
    bool
    has_tractions() const;
  };
} // namespace PeriArlequin

#endif
