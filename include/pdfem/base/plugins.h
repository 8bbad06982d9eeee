// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_BASE_PLUGINS_H
#define PDFEM_BASE_PLUGINS_H

#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace pdfem
{
  /**
   * Plugins: the extension mechanism of pdfem, in the spirit of ASPECT's
   * registries. Each plugin family (drivers, crack criteria,
   * postprocessors, PD models) has one interface class and one Registry of
   * it. A plugin registers itself at the end of its own `.cc` file with the
   * family's macro (e.g. PDFEM_REGISTER_DRIVER), giving its name as it is
   * written in a parameter file, a one-line description (for
   * `pdfem --list-plugins`), a function that declares its parameters, and a
   * factory. A program linked against the library registers its own
   * plugins the same way: the registration runs when the program starts.
   *
   * Names are compared only here: everywhere else a plugin is an object of
   * its family's interface.
   */
  namespace Plugins
  {
    /**
     * Throw InputError naming @p file and @p parameter: @p name is not a
     * registered @p what; the message suggests the nearest of @p
     * candidates and lists @p allowed.
     */
    [[noreturn]] void
    throw_unknown(const std::string              &name,
                  const std::vector<std::string> &candidates,
                  const std::string              &file,
                  const std::string              &parameter,
                  const std::string              &what,
                  const std::string              &allowed);

    /** One registered plugin. */
    template <typename Interface>
    struct Entry
    {
      std::string name;
      /// One line: what it does (pdfem --list-plugins).
      std::string description;
      /// Declares the plugin's own entries in the family's subsection (may
      /// be empty).
      std::function<void(dealii::ParameterHandler &)> declare_parameters;
      std::function<std::unique_ptr<Interface>()>     create;
    };

    /**
     * The plugins of one family. Each family has one, returned by a
     * function defined in the library next to the family's interface (e.g.
     * Drivers::registry()), so that the library and every program share it.
     */
    template <typename Interface>
    class Registry
    {
    public:
      /// Add a plugin; returns true (for a static initialiser). A second
      /// plugin of the same name replaces the first, so that a program may
      /// override a built-in one.
      bool
      add(const std::string                                     &name,
          const std::string                                     &description,
          const std::function<void(dealii::ParameterHandler &)> &declare,
          const std::function<std::unique_ptr<Interface>()>     &create)
      {
        entries[name] = Entry<Interface>{name, description, declare, create};
        return true;
      }

      /// Is a plugin of this name registered?
      bool
      has(const std::string &name) const
      {
        return entries.count(name) > 0;
      }

      /// The one-line description of @p name (empty if there is none).
      std::string
      description(const std::string &name) const
      {
        const auto it = entries.find(name);
        return it == entries.end() ? "" : it->second.description;
      }

      /// A new object of the plugin @p name (nullptr if there is none;
      /// check has() first, or use the family's checked factory).
      std::unique_ptr<Interface>
      create(const std::string &name) const
      {
        const auto it = entries.find(name);
        return it == entries.end() ? nullptr : it->second.create();
      }

      /**
       * A new object of the plugin @p name, which a user gave as
       * @p parameter in @p file; InputError ("unknown @p what", with a
       * suggestion and the allowed values, @p extra first) if there is
       * none.
       */
      std::unique_ptr<Interface>
      create(const std::string              &name,
             const std::string              &file,
             const std::string              &parameter,
             const std::string              &what,
             const std::vector<std::string> &extra = {}) const
      {
        if (!has(name))
          throw_unknown(name, names(), file, parameter, what, selection(extra));
        return create(name);
      }

      /// "name: description " for every plugin, for a parameter's
      /// documentation.
      std::string
      summary() const
      {
        std::string s;
        for (const auto &e : entries)
          s += e.first + ": " + e.second.description + " ";
        return s;
      }

      /// The names in alphabetical order.
      std::vector<std::string>
      names() const
      {
        std::vector<std::string> result;
        for (const auto &e : entries)
          result.push_back(e.first);
        return result;
      }

      /// The names as a deal.II Selection pattern ("a|b|c"), with @p extra
      /// choices (such as "none") first.
      std::string
      selection(const std::vector<std::string> &extra = {}) const
      {
        std::string s;
        for (const auto &name : extra)
          s += (s.empty() ? "" : "|") + name;
        for (const auto &e : entries)
          s += (s.empty() ? "" : "|") + e.first;
        return s;
      }

      /// Every plugin's parameters, declared in the current subsection.
      void
      declare_parameters(dealii::ParameterHandler &prm) const
      {
        for (const auto &e : entries)
          if (e.second.declare_parameters)
            e.second.declare_parameters(prm);
      }

      /// "  name  description" lines.
      void
      list(std::ostream &out) const
      {
        for (const auto &e : entries)
          out << "  " << e.first
              << std::string(e.first.size() < 24 ? 24 - e.first.size() : 1, ' ')
              << e.second.description << "\n";
      }

    private:
      std::map<std::string, Entry<Interface>> entries;
    };

    /**
     * The name nearest to @p name among @p candidates (edit distance, case
     * ignored), for "did you mean" in messages; empty if none is close.
     */
    std::string
    nearest_name(const std::string              &name,
                 const std::vector<std::string> &candidates);
  } // namespace Plugins
} // namespace pdfem

#define PDFEM_PLUGIN_CONCAT_(a, b) a##b
#define PDFEM_PLUGIN_CONCAT(a, b) PDFEM_PLUGIN_CONCAT_(a, b)

#endif
