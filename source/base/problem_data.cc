#include <periarlequin/base/crack_tip_field.h>
#include <periarlequin/base/parameters.h>
#include <periarlequin/base/problem_data.h>

#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

namespace PeriArlequin
{
  namespace
  {
    /** Default expression "0; 0[; 0]" for a dim-component function. */
    template <int dim>
    std::string
    zero_expression()
    {
      std::string s = "0";
      for (unsigned int d = 1; d < dim; ++d)
        s += "; 0";
      return s;
    }

    /** True if every component expression is a number equal to zero. */
    bool
    is_zero_expression(const std::string &expression)
    {
      for (const std::string &component : Utilities::split_string_list(expression, ';'))
        {
          char        *end   = nullptr;
          const double value = std::strtod(component.c_str(), &end);
          if (end == component.c_str() || *end != '\0' || value != 0.)
            return false;
        }
      return true;
    }

  } // namespace

  template <int dim>
  void
  declare_vector_function(ParameterHandler &prm, const std::string &name, const std::string &doc)
  {
    prm.enter_subsection(name);
    prm.declare_entry("Function expression",
                      zero_expression<dim>(),
                      Patterns::Anything(),
                      doc + " One muparser expression per component, separated by ';'.");
    prm.declare_entry("Function constants",
                      "",
                      Patterns::Anything(),
                      "Named constants used in the expression, e.g. 'a1=3e-4, w1=0.48' "
                      "(pi is predefined).");
    prm.declare_entry("Variable names",
                      dim == 2 ? "x,y,t" : "x,y,z,t",
                      Patterns::Anything(),
                      "Names of the coordinates and of time in the expression.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  parse_vector_function(ParameterHandler               &prm,
                        const std::string              &path,
                        const std::string              &name,
                        Functions::ParsedFunction<dim> &function)
  {
    prm.enter_subsection(name);
    const std::string expression = prm.get("Function expression");
    const std::string constants  = prm.get("Function constants");
    const std::string entry      = path + name + "/Function expression";
    if (Utilities::split_string_list(expression, ';').size() != static_cast<std::size_t>(dim))
      {
        prm.leave_subsection();
        throw_invalid_parameter(entry,
                                expression,
                                std::to_string(dim) + " expressions separated by ';', one per "
                                                      "component");
      }
    try
      {
        function.parse_parameters(prm);
        // The parser compiles lazily: evaluate once so that a syntax error shows here.
        Vector<double> values(dim);
        function.vector_value(Point<dim>(), values);
      }
    catch (const ExceptionBase &error)
      {
        prm.leave_subsection();
        std::ostringstream parser_message;
        error.print_info(parser_message);
        throw_invalid_parameter(entry,
                                expression,
                                "a valid muparser expression in the 'Variable names' and the "
                                "'Function constants' ('" +
                                  constants + "'). " + Utilities::trim(parser_message.str()));
      }
    prm.leave_subsection();
  }

  template <int dim>
  void
  BoundaryCondition<dim>::entries(ParameterEntries &entries)
  {
    entries.add("Type",
                type,
                boundary_type_names,
                "Condition on boundary id " + std::to_string(id) +
                  " (0/1: x faces, 2/3: y faces, 4/5: z faces): free (zero "
                  "traction), displacement (prescribed components) or traction. "
                  "PD particles within two bond reaches (2 delta + dx) of a "
                  "displacement face follow the displacement (a fictitious boundary "
                  "layer inside the domain); those within dx of a traction face "
                  "carry t / dx.");
    entries.add_components("Components",
                           components,
                           dim,
                           "Components whose displacement is prescribed (Type = displacement).");
  }

  namespace Parameters
  {
    template <int dim>
    void
    InitialConditionModel<dim>::entries(ParameterEntries &entries)
    {
      entries.add("Model",
                  model,
                  Patterns::Selection(InitialConditionRegistry<dim>::names()),
                  "The initial displacement and velocity, by registered name:" +
                    InitialConditionRegistry<dim>::documentation() +
                    "\nA model's own parameters are in the subsection of its name.");
    }
  } // namespace Parameters

  template <int dim>
  ProblemData<dim>::ProblemData()
    : body_force(dim)
  {}

  template <int dim>
  void
  ProblemData<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial conditions");
    ParameterEntries::declare_here<Parameters::InitialConditionModel<dim>>(prm);
    InitialConditionRegistry<dim>::declare_parameters(prm);
    prm.leave_subsection();

    declare_vector_function<dim>(prm, "Body force", "Body force per unit volume b(x, t) [N/m^3].");

    prm.enter_subsection("Boundary conditions");
    for (unsigned int b = 0; b < n_boundaries; ++b)
      {
        prm.enter_subsection("Boundary " + std::to_string(b));
        BoundaryCondition<dim> defaults;
        defaults.id = b;
        ParameterEntries::declare_here(prm, std::move(defaults));
        declare_vector_function<dim>(
          prm,
          "Function",
          "Prescribed displacement [m] (Type = displacement) or traction "
          "[Pa] (Type = traction) as a function of position and time.");
        prm.leave_subsection();
      }
    CrackTipField<dim>::declare_parameters(prm);
    prm.leave_subsection();
  }

  template <int dim>
  void
  ProblemData<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial conditions");
    Parameters::InitialConditionModel<dim> initial;
    ParameterEntries::parse_here(prm, initial, "Initial conditions/");
    initial_condition = InitialConditionRegistry<dim>::create(initial.model, prm);
    prm.leave_subsection();

    parse_vector_function(prm, "", "Body force", body_force);
    prm.enter_subsection("Body force");
    has_body_force = !is_zero_expression(prm.get("Function expression"));
    prm.leave_subsection();

    prm.enter_subsection("Boundary conditions");
    for (unsigned int b = 0; b < n_boundaries; ++b)
      {
        const std::string name = "Boundary " + std::to_string(b);
        prm.enter_subsection(name);
        BoundaryCondition<dim> &condition = boundary_conditions[b];
        condition.id                      = b;
        ParameterEntries::parse_here(prm, condition, "Boundary conditions/" + name + "/");
        if (condition.type == BoundaryType::displacement &&
            condition.components.n_selected_components() == 0)
          throw_invalid_parameter("Boundary conditions/" + name + "/Components",
                                  prm.get("Components"),
                                  "at least one of x, y" + std::string(dim == 3 ? ", z" : "") +
                                    " for a displacement condition");
        auto function = std::make_unique<Functions::ParsedFunction<dim>>(dim);
        parse_vector_function(prm, "Boundary conditions/" + name + "/", "Function", *function);
        condition.function = std::move(function);
        prm.leave_subsection();
      }
    prm.leave_subsection();

    // The crack-tip field, one object per boundary id it prescribes (each keeps its time).
    Parameters::Material material;
    material.parse_parameters(prm);
    prm.enter_subsection("Boundary conditions");
    std::vector<unsigned int> crack_tip_ids;
    CrackTipField<dim>(prm, material, crack_tip_ids);
    for (const unsigned int b : crack_tip_ids)
      {
        BoundaryCondition<dim> &condition = boundary_conditions[b];
        if (condition.type != BoundaryType::free)
          throw_invalid_parameter("Boundary conditions/Crack tip field/Boundary ids",
                                  std::to_string(b),
                                  "ids whose own 'Boundary conditions/Boundary " +
                                    std::to_string(b) + "/Type' is free (it is " +
                                    (condition.type == BoundaryType::traction ? "traction" :
                                                                                "displacement") +
                                    ")");
        condition.type       = BoundaryType::displacement;
        condition.components = ComponentMask(dim, true);
        std::vector<unsigned int> same_ids;
        condition.function = std::make_unique<CrackTipField<dim>>(prm, material, same_ids);
      }
    prm.leave_subsection();
  }

  template <int dim>
  bool
  ProblemData<dim>::has_tractions() const
  {
    for (const auto &condition : boundary_conditions)
      if (condition.type == BoundaryType::traction)
        return true;
    return false;
  }

  template void
  declare_vector_function<2>(ParameterHandler &, const std::string &, const std::string &);
  template void
  declare_vector_function<3>(ParameterHandler &, const std::string &, const std::string &);
  template void
  parse_vector_function<2>(ParameterHandler &,
                           const std::string &,
                           const std::string &,
                           Functions::ParsedFunction<2> &);
  template void
  parse_vector_function<3>(ParameterHandler &,
                           const std::string &,
                           const std::string &,
                           Functions::ParsedFunction<3> &);
  template struct BoundaryCondition<2>;
  template struct BoundaryCondition<3>;
  template struct Parameters::InitialConditionModel<2>;
  template struct Parameters::InitialConditionModel<3>;
  template class ProblemData<2>;
  template class ProblemData<3>;
} // namespace PeriArlequin
