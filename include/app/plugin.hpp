// Plugins: equation terms and output writers in a shared library that fluid_sim and fluid_sim_3d
// load at run time when a scene names it under "plugins" (docs/scenes.md, docs/extending.md).
//
// A plugin exports one C symbol, numerics_plugin_entry(hostVersion, registry): it returns the
// plugin API version it was built against and, when that equals the host's, registers its
// term factories (2D, 3D or both), the quantities its terms create and its writers (formats a
// scene may name in output.formats). NUMERICS_PLUGIN writes
// that function; a whole plugin is a term class and a few lines:
//
//     #include "app/plugin.hpp"
//     NUMERICS_PLUGIN(registry) {
//         registry.add<MyTerm>("my_term", [](const num::app::plugin::Parameters& p) {
//             p.allow({"strength"});
//             return std::tuple{p.positive("strength", "N/kg")};   // MyTerm<Dim>(strength)
//         });
//     }
//
// The classes below cross the library boundary as C++ objects: a plugin must be built by the
// same compiler against the same numerics (NUMERICS_PLUGIN_API_VERSION says which layout).
#pragma once

#include <functional>
#include <initializer_list>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "app/writer_registry.hpp"
#include "sph/equation_term.hpp"

/// The version of this header's classes; a plugin built against another version is refused.
/// (2 added the range of a field, Registry::addField with lo and hi; 3 added writers,
/// Registry::addWriter.)
#define NUMERICS_PLUGIN_API_VERSION 3
/// The symbol every plugin exports (as extern "C").
#define NUMERICS_PLUGIN_ENTRY_NAME "numerics_plugin_entry"

namespace num::app::plugin {

/// The parameters of one term of a scene: its JSON object (less the "term" key). Every read
/// checks type and range; a mistake stops the app with the scene file and the key path, e.g.
/// "scene.json: plugins.0.terms.1.stiffness: expected a positive number [N/m], found -3".
class Parameters {
  public:
    Parameters(nlohmann::json term, std::string file, std::string path);

    /// Only these keys (and "term") may appear; another is an error with a suggestion. Without
    /// allow(), the keys the factory read are the allowed ones (checked after it returns).
    void allow(std::initializer_list<const char*> keys) const;
    bool has(const std::string& key) const;

    /// A required number in [lo, hi]; the unit appears in messages.
    double number(const std::string& key, double lo, double hi, const std::string& unit = "") const;
    /// An optional number in [lo, hi] (fallback when absent).
    double number(const std::string& key, double fallback, double lo, double hi,
                  const std::string& unit = "") const;
    /// A required number > 0 (finite).
    double positive(const std::string& key, const std::string& unit = "") const;
    long integer(const std::string& key, long fallback, long lo, long hi) const;
    bool boolean(const std::string& key, bool fallback) const;
    std::string string(const std::string& key) const;
    /// A required string, one of `choices`.
    std::string choice(const std::string& key, std::initializer_list<const char*> choices) const;
    /// A required array of Dim numbers (a point or a vector).
    template <int Dim>
    sph::Vector<Dim> vector(const std::string& key, const std::string& unit = "") const;

    /// Stops with "file: path.key: expected `expected`, found <the value>".
    [[noreturn]] void fail(const std::string& key, const std::string& expected) const;

    /// The keys of the term's object that no call named (allow or a read), "term" aside.
    std::vector<std::string> unnamedKeys() const;
    /// The keys calls named so far.
    const std::set<std::string>& namedKeys() const { return named_; }

    const nlohmann::json& json() const { return json_; }
    const std::string& file() const { return file_; }
    /// The key path of the term in the scene, "plugins.0.terms.1".
    const std::string& path() const { return path_; }

  private:
    const std::string& name(const std::string& key) const { return *named_.insert(key).first; }

    nlohmann::json json_;
    std::string file_, path_;
    mutable std::set<std::string> named_;
};

/// Makes a term of dimension Dim from its parameters.
template <int Dim>
using TermFactory = std::function<std::shared_ptr<sph::IEquationTerm<Dim>>(const Parameters&)>;

/// What the host hands to a plugin's entry point.
class Registry {
  public:
    /// Registers a term by name for 2D or 3D (a name may have both).
    virtual void addTerm2(const std::string& name, TermFactory<2> factory) = 0;
    virtual void addTerm3(const std::string& name, TermFactory<3> factory) = 0;
    /// A quantity the plugin's terms create (a user id: negative or >= QuantityId::USER_FIRST).
    /// A scene writes it to the outputs under `name` by listing the name in the plugin's
    /// "fields"; quantities not listed are left out of the outputs.
    virtual void addField(const std::string& name, sph::QuantityId id) = 0;
    /// The same for a scalar quantity (a double per particle) with a physical range [lo, hi]
    /// (in `unit`, for messages): a run in which a particle's value leaves it stops as unstable
    /// (exit code 9), naming the field, whether or not the scene writes it.
    virtual void addField(const std::string& name, sph::QuantityId id, double lo, double hi,
                          const std::string& unit) = 0;

    /// Registers a writer (app/output_writer.hpp) by name for 2D or 3D (a name may have both): a
    /// scene that loads the plugin may name it in output.formats.
    virtual void addWriter2(const std::string& name, WriterFactory<2> factory) = 0;
    virtual void addWriter3(const std::string& name, WriterFactory<3> factory) = 0;

    /// Registers Writer<2> and Writer<3>, each made by `Writer<Dim>(context)`.
    template <template <int> class Writer>
    void addWriter(const std::string& name) {
        addWriter2(name, writerFactory<Writer<2>>());
        addWriter3(name, writerFactory<Writer<3>>());
    }

    /// Registers Term<2> and Term<3>, each made by `Term<Dim>(args...)` with the arguments
    /// `read(parameters)` returns as a tuple.
    template <template <int> class Term, class Read>
    void add(const std::string& name, Read read) {
        addTerm2(name, factory<Term<2>>(read));
        addTerm3(name, factory<Term<3>>(read));
    }
    /// Registers one dimension only: Term is a class of that dimension (Term::dim).
    template <class Term, class Read>
    void addOne(const std::string& name, Read read) {
        if constexpr (Term::dim == 2)
            addTerm2(name, factory<Term>(read));
        else
            addTerm3(name, factory<Term>(read));
    }

  protected:
    ~Registry() = default;

  private:
    template <class Term, class Read>
    static TermFactory<Term::dim> factory(Read read) {
        return [read](const Parameters& p) -> std::shared_ptr<sph::IEquationTerm<Term::dim>> {
            return std::apply(
                [](auto&&... args) {
                    return std::make_shared<Term>(std::forward<decltype(args)>(args)...);
                },
                read(p));
        };
    }
};

/// The signature of numerics_plugin_entry.
using EntryFunction = int (*)(int hostVersion, Registry* registry);

}  // namespace num::app::plugin

/// Defines the plugin's entry point; the braces that follow register its terms and writers:
///     NUMERICS_PLUGIN(registry) { registry.add<MyTerm>("my_term", read); }
#define NUMERICS_PLUGIN(registry)                                                              \
    static void numericsPluginRegister(::num::app::plugin::Registry& registry);                \
    extern "C" __attribute__((visibility("default"))) int numerics_plugin_entry(               \
        int hostVersion, ::num::app::plugin::Registry* host) {                                 \
        if (hostVersion == NUMERICS_PLUGIN_API_VERSION && host) numericsPluginRegister(*host); \
        return NUMERICS_PLUGIN_API_VERSION;                                                    \
    }                                                                                          \
    static void numericsPluginRegister(::num::app::plugin::Registry& registry)
