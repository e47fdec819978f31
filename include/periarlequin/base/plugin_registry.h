#ifndef periarlequin_base_plugin_registry_h
#define periarlequin_base_plugin_registry_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <type_traits>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * An open registry of the implementations of an interface, by name, in ASPECT's manner: a
   * plugin registers a factory, and optionally the declaration of its own parameters, from a
   * static initialiser in its own source file (see the REGISTER macros of each interface);
   * the parameter that selects it is a Patterns::Selection of names(). A plugin's parameters
   * live in a subsection named after it, which declare_parameters() declares for every
   * registered plugin (so --print-parameters shows them all), and create() with a
   * ParameterHandler hands to the instance's parse_parameters(). Each interface's header
   * declares its registry as an extern template and the library instantiates it, so the
   * library and user code share one registry.
   */
  template <typename Interface, typename... Arguments>
  class PluginRegistry
  {
  public:
    using Creator = std::function<std::unique_ptr<Interface>(Arguments...)>;
    using Declare = std::function<void(ParameterHandler &)>;

    /**
     * Add a plugin, with the declaration of its parameters if it has any; a name registered
     * twice is an error. Returns true (for static initialisers).
     */
    static bool
    register_plugin(const std::string &name,
                    const std::string &description,
                    Creator            creator,
                    Declare            declare = Declare())
    {
      AssertThrow(plugins().count(name) == 0,
                  ExcMessage("A plugin named '" + name + "' is registered twice."));
      plugins()[name] = {description, std::move(creator), std::move(declare)};
      return true;
    }

    /** Each plugin's parameters, in a subsection of its name inside the current one. */
    static void
    declare_parameters(ParameterHandler &prm)
    {
      for (const auto &[name, entry] : plugins())
        if (entry.declare)
          {
            prm.enter_subsection(name);
            entry.declare(prm);
            prm.leave_subsection();
          }
    }

    /**
     * A new instance of the plugin @p name, constructed from @p arguments, that has read its
     * parameters from its subsection (inside the current subsection of @p prm).
     */
    static std::unique_ptr<Interface>
    create(const std::string &name, ParameterHandler &prm, Arguments... arguments)
    {
      auto instance = create(name, arguments...);
      if (plugins().at(name).declare)
        {
          prm.enter_subsection(name);
          instance->parse_parameters(prm);
          prm.leave_subsection();
        }
      return instance;
    }

    /** A new instance of the plugin @p name, constructed from @p arguments. */
    static std::unique_ptr<Interface>
    create(const std::string &name, Arguments... arguments)
    {
      const auto found = plugins().find(name);
      AssertThrow(found != plugins().end(),
                  ExcMessage("No plugin named '" + name +
                             "' is registered; registered: " + names() + "."));
      return found->second.creator(arguments...);
    }

    /** "a|b|..." for a Patterns::Selection. */
    static std::string
    names()
    {
      std::string list;
      for (const auto &[name, entry] : plugins())
        list += (list.empty() ? "" : "|") + name;
      return list;
    }

    /** One line per plugin: name and description. */
    static std::string
    documentation()
    {
      std::string text;
      for (const auto &[name, entry] : plugins())
        text += "\n  " + name + ": " + entry.description;
      return text;
    }

  private:
    struct Entry
    {
      std::string description;
      Creator     creator;
      Declare     declare;
    };

    static std::map<std::string, Entry> &
    plugins()
    {
      static std::map<std::string, Entry> registered;
      return registered;
    }
  };

  /** Does the plugin class @p Plugin declare parameters (a static declare_parameters)? */
  template <typename Plugin, typename = void>
  struct declares_parameters : std::false_type
  {};

  template <typename Plugin>
  struct declares_parameters<Plugin, std::void_t<decltype(&Plugin::declare_parameters)>>
    : std::true_type
  {};

  /**
   * Register the class template @p Plugin, derived from @p Interface<dim> and constructed
   * from the registry's @p Arguments, in the registries of dim = 2 and 3 under @p name, with
   * its static declare_parameters() if it has one. What the REGISTER macros call.
   */
  template <template <int> class Interface, template <int> class Plugin, typename... Arguments>
  bool
  register_plugin_template(const std::string &name, const std::string &description)
  {
    const auto add = [&](auto dimension) {
      constexpr int dim = decltype(dimension)::value;
      using Registry    = PluginRegistry<Interface<dim>, Arguments...>;
      typename Registry::Declare declare;
      if constexpr (declares_parameters<Plugin<dim>>::value)
        declare = &Plugin<dim>::declare_parameters;
      return Registry::register_plugin(
        name,
        description,
        [](Arguments... arguments) {
          return std::unique_ptr<Interface<dim>>(new Plugin<dim>(arguments...));
        },
        declare);
    };
    return add(std::integral_constant<int, 2>()) && add(std::integral_constant<int, 3>());
  }
} // namespace PeriArlequin

#endif
