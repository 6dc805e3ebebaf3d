// Loading the plugins a scene names: dlopen, the versioned entry point, the registry of term
// factories and writers, the terms made from their parameters, and the fields they write.
#include "plugin/plugins.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include "app/formatted.hpp"
#include "app/plugin.hpp"
#include "plugin/elf_check.hpp"
#include "plugin/plugin_term.hpp"
#include "plugin/plugin_writer.hpp"
#include "scene/file_hash.hpp"
#include "scene/json_check.hpp"

namespace num::app {

using detail::At;
namespace fs = std::filesystem;

/// What one library registered (its writers join the run's, ScenePlugins::writers).
struct PluginLibrary {
    std::string path;
    std::map<std::string, plugin::TermFactory<2>> terms2;
    std::map<std::string, plugin::TermFactory<3>> terms3;
    std::map<std::string, sph::QuantityId> fields;
    struct Range {
        double lo, hi;
        std::string unit;
    };
    std::map<std::string, Range> ranges;  ///< of fields, by name
};

namespace {

/// Element i of an array, its path in the --set form ("plugins.0.terms.1").
At element(const At& a, std::size_t i) { return {a.v.at(i), a.file, a.join(std::to_string(i))}; }

bool plainName(const std::string& s) {
    return !s.empty() && s.size() <= 64 && std::all_of(s.begin(), s.end(), [](char c) {
        return std::isalnum((unsigned char)c) || c == '_' || c == '-';
    });
}

bool userId(sph::QuantityId id) {
    return int(id) < 0 || int(id) >= int(sph::QuantityId::USER_FIRST);
}

std::string names(const std::vector<std::string>& list) {
    std::string text;
    for (const auto& n : list) text += (text.empty() ? "" : ", ") + n;
    return text;
}

using Library = PluginLibrary;

class HostRegistry final : public plugin::Registry {
  public:
    /// Terms and fields go to `lib`, writers to `writers` (with the built-in ones).
    HostRegistry(Library& lib, WriterRegistry& writers) : lib_(lib), writers_(writers) {}
    void addTerm2(const std::string& name, plugin::TermFactory<2> f) override {
        add(lib_.terms2, name, std::move(f), "2D");
    }
    void addTerm3(const std::string& name, plugin::TermFactory<3> f) override {
        add(lib_.terms3, name, std::move(f), "3D");
    }
    void addField(const std::string& name, sph::QuantityId id) override {
        if (!plainName(name) || lib_.fields.count(name))
            refuse("a field named \"" + name +
                   "\": expected a new name of 1 to 64 letters, "
                   "digits, '_' or '-'");
        if (!userId(id))
            refuse("the field \"" + name + "\" with quantity id " + std::to_string(int(id)) +
                   ": expected a user id (negative or >= QuantityId::USER_FIRST = 1000)");
        lib_.fields[name] = id;
    }
    void addField(const std::string& name, sph::QuantityId id, double lo, double hi,
                  const std::string& unit) override {
        if (!(lo <= hi) || std::isnan(lo) || std::isnan(hi))
            refuse("the field \"" + name + "\" with the range [" + formatted("%g", lo) + ", " +
                   formatted("%g", hi) + "]: expected lo <= hi");
        addField(name, id);
        lib_.ranges[name] = {lo, hi, unit};
    }
    void addWriter2(const std::string& name, WriterFactory<2> f) override {
        addWriter<2>(name, std::move(f));
    }
    void addWriter3(const std::string& name, WriterFactory<3> f) override {
        addWriter<3>(name, std::move(f));
    }

  private:
    template <class Map, class F>
    void add(Map& map, const std::string& name, F f, const char* dim) {
        if (!plainName(name) || map.count(name) || !f)
            refuse(std::string("a ") + dim + " term named \"" + name +
                   "\": expected a factory under a new name of 1 to 64 letters, digits, '_' "
                   "or '-'");
        map[name] = std::move(f);
    }
    template <int Dim>
    void addWriter(const std::string& name, WriterFactory<Dim> f) {
        if (!plainName(name) || writers_.has<Dim>(name) || !f)
            refuse("a " + std::to_string(Dim) + "D writer named \"" + name +
                   "\": expected a factory under a name of 1 to 64 letters, digits, '_' or '-' "
                   "that no other writer has (" +
                   names(writers_.names<Dim>()) + ")");
        const std::string label =
            "writer \"" + name + "\" (" + fs::path(lib_.path).filename().string() + ")";
        writers_.add(name, guardedWriterFactory<Dim>(std::move(f), label));
    }
    [[noreturn]] void refuse(const std::string& what) const {
        throw AppError(ExitCode::PLUGIN, lib_.path + ": the plugin registers " + what);
    }
    Library& lib_;
    WriterRegistry& writers_;
};

std::string absoluteLibrary(const std::string& library, const std::string& sceneFile) {
    fs::path p(library);
    if (p.is_relative()) p = fs::path(sceneFile).parent_path() / p;
    return fs::absolute(p).lexically_normal().string();
}

/// dlopens one library (never closed: its code runs until the process ends) and calls its
/// entry point with a registry; its writers are added to `writers`.
Library openLibrary(const At& at, const std::string& path, const std::string& program,
                    WriterRegistry& writers) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw AppError(ExitCode::SCENE, at.file + ": " + at.path + ": no plugin library " + path +
                                            " (expected a file, the path relative to the scene "
                                            "file or absolute)");
    if (const std::string problem = detail::elfProblem(path); !problem.empty())
        throw AppError(ExitCode::PLUGIN,
                       at.file + ": " + at.path + ": cannot load " + path + ": " + problem);
    Library lib;
    lib.path = path;
    dlerror();
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* why = dlerror();
        throw AppError(ExitCode::PLUGIN, at.file + ": " + at.path + ": cannot load " + path + ": " +
                                             (why ? why : "unknown error"));
    }
    auto entry = reinterpret_cast<plugin::EntryFunction>(dlsym(handle, NUMERICS_PLUGIN_ENTRY_NAME));
    if (!entry)
        throw AppError(ExitCode::PLUGIN,
                       at.file + ": " + at.path + ": " + path +
                           " is not a numerics plugin: it does not export " +
                           NUMERICS_PLUGIN_ENTRY_NAME +
                           " (define it with NUMERICS_PLUGIN from app/plugin.hpp and build the "
                           "library with numerics_add_plugin)");
    HostRegistry registry(lib, writers);
    int version = 0;
    try {
        version = entry(NUMERICS_PLUGIN_API_VERSION, &registry);
    } catch (const AppError&) {
        throw;
    } catch (const std::exception& e) {
        throw AppError(ExitCode::PLUGIN, path + ": the plugin failed to register: " + e.what());
    } catch (...) {
        throw AppError(ExitCode::PLUGIN, path +
                                             ": the plugin failed to register: its entry point "
                                             "threw something that is not a std::exception");
    }
    if (version != NUMERICS_PLUGIN_API_VERSION)
        throw AppError(ExitCode::PLUGIN, at.file + ": " + at.path + ": " + path +
                                             " was built against plugin API version " +
                                             std::to_string(version) + ", " + program +
                                             " has version " +
                                             std::to_string(NUMERICS_PLUGIN_API_VERSION) +
                                             ": rebuild the plugin against this numerics");
    return lib;
}

template <int Dim>
const std::map<std::string, plugin::TermFactory<Dim>>& factories(const Library& lib) {
    if constexpr (Dim == 2)
        return lib.terms2;
    else
        return lib.terms3;
}

template <int Dim>
std::shared_ptr<sph::IEquationTerm<Dim>> makeTerm(const Library& lib, const At& t,
                                                  const std::string& program,
                                                  const std::shared_ptr<PluginFailure>& failure) {
    if (!t.v.is_object()) t.fail("an object {\"term\": NAME, parameters...}");
    const At nameAt = t.required("term");
    const std::string name = nameAt.string();
    const auto& mine = factories<Dim>(lib);
    const auto& other = factories<5 - Dim>(lib);
    const std::string file = fs::path(lib.path).filename().string();
    if (!mine.count(name) && other.count(name))
        nameAt.fail("a term of " + file + " for " + std::to_string(Dim) + "D scenes",
                    "the plugin provides \"" + name + "\" for " + std::to_string(5 - Dim) +
                        "D only; " + program + " runs " + std::to_string(Dim) +
                        "D scenes: the plugin must register a " + std::to_string(Dim) +
                        "D term of that name");
    if (!mine.count(name)) {
        std::vector<std::string> known;
        for (const auto& [n, f] : mine) known.push_back(n);
        const std::string guess = detail::closest(name, known);
        nameAt.fail("a term of " + file + " (" + (known.empty() ? "none" : names(known)) + ")",
                    guess.empty() ? "" : "did you mean \"" + guess + "\"?");
    }
    const std::string label = "term \"" + name + "\" (" + t.path + ", " + file + ")";
    std::shared_ptr<sph::IEquationTerm<Dim>> term;
    const plugin::Parameters parameters(t.v, t.file, t.path);
    try {
        term = mine.at(name)(parameters);
    } catch (const AppError&) {
        throw;
    } catch (const std::exception& e) {
        throw AppError(ExitCode::PLUGIN,
                       label + " failed when made from its parameters: " + std::string(e.what()));
    } catch (...) {
        throw AppError(ExitCode::PLUGIN, label +
                                             " failed when made from its parameters: it threw "
                                             "something that is not a std::exception");
    }
    if (!term) throw AppError(ExitCode::PLUGIN, label + ": its factory returned no term");
    // A key the factory neither allowed nor read is a mistake (a misspelt parameter).
    if (const auto unnamed = parameters.unnamedKeys(); !unnamed.empty()) {
        const std::vector<std::string> known(parameters.namedKeys().begin(),
                                             parameters.namedKeys().end());
        const std::string guess = detail::closest(unnamed[0], known);
        throw sceneError(t.file, t.join(unnamed[0]),
                         known.empty() ? "no parameters for the term \"" + name + "\""
                                       : "one of the parameters " + names(known) +
                                             " of the term \"" + name + "\"",
                         "the unknown key '" + unnamed[0] + "'",
                         guess.empty() ? "" : "did you mean '" + guess + "'?");
    }
    return std::make_shared<PluginTerm<Dim>>(std::move(term), label, failure);
}

/// The scene's output.formats as written (readScene checked that they are strings).
std::vector<std::string> outputFormats(const SceneDocument& doc) {
    const nlohmann::json& j = doc.json();
    if (!j.contains("output") || !j["output"].contains("formats") ||
        !j["output"]["formats"].is_array())
        return {};
    std::vector<std::string> formats;
    for (const auto& f : j["output"]["formats"])
        formats.push_back(f.is_string() ? f.get<std::string>() : std::string());
    return formats;
}

/// The fields of a plugin of `lib` the scene writes.
template <int Dim>
void addFields(const At& fields, const Library& lib, ScenePlugins<Dim>& out) {
    if (!fields.v.is_array()) fields.fail("an array of field names");
    for (std::size_t k = 0; k < fields.v.size(); ++k) {
        const At f = element(fields, k);
        const std::string name = f.string();
        if (!lib.fields.count(name)) {
            std::vector<std::string> known;
            for (const auto& [n, id] : lib.fields) known.push_back(n);
            const std::string guess = detail::closest(name, known);
            f.fail("a field of " + fs::path(lib.path).filename().string() + " (" +
                       (known.empty() ? "it declares none" : names(known)) + ")",
                   guess.empty() ? "" : "did you mean \"" + guess + "\"?");
        }
        out.fields.push_back({lib.fields.at(name), name, f.path});
    }
}

template <int Dim>
std::string programName() {
    return Dim == 2 ? "fluid_sim" : "fluid_sim_3d";
}

/// Opens the plugin's library, read first: the other keys use it.
template <int Dim>
void readLibrary(const At& a, PluginInput<Dim>& in) {
    const std::string path = absoluteLibrary(a.string(), *in.sceneFile);
    in.library =
        std::make_shared<const Library>(openLibrary(a, path, programName<Dim>(), in.out->writers));
    const std::string key = "plugin " + std::to_string(in.index);
    in.out->fingerprint += key + " library = " + path + "\n";
    in.out->fingerprint += key + " library content (FNV-1a) = " + fileHash(path) + "\n";
    for (const auto& [name, r] : in.library->ranges)
        in.out->ranges.push_back({in.library->fields.at(name), name, r.unit,
                                  fs::path(path).filename().string(), r.lo, r.hi});
}

template <int Dim>
void readTerms(const At& terms, PluginInput<Dim>& in) {
    if (!terms.v.is_array() || terms.v.empty())
        terms.fail("a non-empty array of terms, each {\"term\": NAME, parameters...}");
    for (std::size_t k = 0; k < terms.v.size(); ++k)
        in.out->terms += sph::EquationHolder<Dim>(
            makeTerm<Dim>(*in.library, element(terms, k), programName<Dim>(), in.out->failure));
}

template <int Dim>
void readFields(const At& fields, PluginInput<Dim>& in) {
    addFields(fields, *in.library, *in.out);
}

template <int Dim>
const KeyTable<PluginInput<Dim>> kPluginKeys{
    {.name = "library",
     .type = KeyType::CUSTOM,
     .meaning = "the plugin's file, relative to the scene file or absolute",
     .required = true,
     .read = readLibrary<Dim>},
    {.name = "terms",
     .type = KeyType::CUSTOM,
     .meaning = "if given, a non-empty array (a plugin of writers only needs none): `term` names "
                "a term the library provides for the scene's dimension, the other keys are its "
                "parameters, checked by the plugin (`scene.json: plugins.0.terms.1.stiffness: "
                "expected a positive number [N/m], found -3`)",
     .read = readTerms<Dim>,
     .shownDefault = "[]"},
    {.name = "fields",
     .type = KeyType::CUSTOM,
     .meaning = "quantities of the plugin's terms written to the VTU and CSV outputs, by their "
                "declared names; the others are not written",
     .read = readFields<Dim>,
     .shownDefault = "[]"},
};

/// Loads plugin number i of the scene (`p`) and adds its terms, fields and writers to `out`.
template <int Dim>
void loadPlugin(const At& p, const std::string& sceneFile, std::size_t i, ScenePlugins<Dim>& out) {
    PluginInput<Dim> in{&out, &sceneFile, i, nullptr};
    readKeys(p, kPluginKeys<Dim>, in);
}

}  // namespace

SceneDocument withAbsolutePluginPaths(const SceneDocument& doc) {
    SceneDocument out = doc;
    const auto& plugins = doc.json().contains("plugins") ? doc.json()["plugins"] : nullptr;
    if (!plugins.is_array()) return out;
    for (std::size_t i = 0; i < plugins.size(); ++i) {
        if (!plugins[i].is_object() || !plugins[i].contains("library") ||
            !plugins[i]["library"].is_string())
            continue;  // reported by loadPlugins
        const std::string path =
            absoluteLibrary(plugins[i]["library"].get<std::string>(), doc.file());
        out.set("plugins." + std::to_string(i) + ".library=" + nlohmann::json(path).dump());
    }
    return out;
}

template <int Dim>
ScenePlugins<Dim> loadPlugins(const SceneDocument& doc) {
    ScenePlugins<Dim> out;
    const At root{doc.json(), doc.file(), ""};
    if (root.has("plugins")) {
        const At list = root["plugins"];
        if (!list.v.is_array())
            list.fail("an array of plugins, each {\"library\": FILE, \"terms\": [...]}");
        for (std::size_t i = 0; i < list.v.size(); ++i)
            loadPlugin(element(list, i), doc.file(), i, out);
    }
    checkOutputFormats<Dim>(doc.file(), outputFormats(doc), out.writers);
    return out;
}

template <int Dim>
FieldNames pluginFieldNames(const ScenePlugins<Dim>& plugins, const sph::Storage<Dim>& initial,
                            FieldNames names, const std::string& file) {
    if (plugins.empty()) return names;
    for (const auto& f : plugins.fields) {
        if (!initial.has(f.id))
            throw AppError(ExitCode::PLUGIN, file + ": " + f.path +
                                                 ": the plugin declares the field \"" + f.name +
                                                 "\" (quantity " + std::to_string(int(f.id)) +
                                                 "), but none of the scene's terms created it");
        names.add(f.id, f.name);
    }
    for (const auto& r : plugins.ranges)
        if (initial.has(r.id) && !initial.get(r.id).template holds<double>())
            throw AppError(ExitCode::PLUGIN, r.library +
                                                 ": the plugin declares a range for the "
                                                 "field \"" +
                                                 r.name +
                                                 "\", which is not a scalar (a double per "
                                                 "particle)");
    initial.forEach([&](sph::QuantityId id, const sph::Quantity<Dim>&) {
        if (userId(id) && names.name(id).empty()) names.hide(id);
    });
    return names;
}

template <int Dim>
const KeyTable<PluginInput<Dim>>& pluginKeys() {
    return kPluginKeys<Dim>;
}

template ScenePlugins<2> loadPlugins<2>(const SceneDocument&);
template ScenePlugins<3> loadPlugins<3>(const SceneDocument&);
template const KeyTable<PluginInput<2>>& pluginKeys<2>();
template const KeyTable<PluginInput<3>>& pluginKeys<3>();
template FieldNames pluginFieldNames<2>(const ScenePlugins<2>&, const sph::Storage<2>&, FieldNames,
                                        const std::string&);
template FieldNames pluginFieldNames<3>(const ScenePlugins<3>&, const sph::Storage<3>&, FieldNames,
                                        const std::string&);

}  // namespace num::app
