#ifndef periarlequin_base_plugin_registry_h
#define periarlequin_base_plugin_registry_h

#include <deal.II/base/exceptions.h>

#include <functional>
#include <map>
#include <memory>
#include <string>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * An open registry of the implementations of an interface, by name, in ASPECT's manner: a
   * plugin registers a factory from a static initialiser in its own source file (see the
   * REGISTER macros of each interface), and the parameter that selects it is a
   * Patterns::Selection of names(). Each interface's header declares its registry as an
   * extern template and the library instantiates it, so the library and user code share one
   * registry.
   */
  template <typename Interface, typename... Arguments>
  class PluginRegistry
  {
  public:
    using Creator = std::function<std::unique_ptr<Interface>(Arguments...)>;

    /** Add a plugin; a name registered twice is an error. Returns true (for initialisers). */
    static bool
    register_plugin(const std::string &name, const std::string &description, Creator creator)
    {
      AssertThrow(plugins().count(name) == 0,
                  ExcMessage("A plugin named '" + name + "' is registered twice."));
      plugins()[name] = {description, std::move(creator)};
      return true;
    }

    /** A new instance of the plugin @p name, constructed from @p arguments. */
    static std::unique_ptr<Interface>
    create(const std::string &name, Arguments... arguments)
    {
      const auto found = plugins().find(name);
      AssertThrow(found != plugins().end(),
                  ExcMessage("No plugin named '" + name + "' is registered; registered: " +
                             names() + "."));
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
    };

    static std::map<std::string, Entry> &
    plugins()
    {
      static std::map<std::string, Entry> registered;
      return registered;
    }
  };
} // namespace PeriArlequin

#endif
