// The "plugins" of a scene (internal to numerics_app): shared libraries loaded with dlopen, in the
// order listed, before the run is set up; their terms join the fluid model (extraTerms), their
// writers the formats that output.formats may name.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/fields.hpp"
#include "app/scene_loader.hpp"
#include "app/writer_registry.hpp"
#include "plugin/plugin_term.hpp"
#include "scene/scene_keys.hpp"
#include "sph/equation_term.hpp"

namespace num::app {

template <int Dim>
struct ScenePlugins {
    sph::EquationHolder<Dim> terms;  ///< every plugin's terms, in scene order
    /// The quantities the scene names in a plugin's "fields": id, name, and where it was named.
    struct Field {
        sph::QuantityId id;
        std::string name, path;
    };
    std::vector<Field> fields;
    /// The ranges the plugins declared for their fields (Registry::addField with lo and hi).
    struct Range {
        sph::QuantityId id;
        std::string name, unit, library;
        double lo, hi;
    };
    std::vector<Range> ranges;
    /// The built-in writers and those the plugins registered: the formats output.formats may name.
    WriterRegistry writers = builtInWriters();
    /// "key = value" lines for the checkpoint's fingerprint: each library and its content.
    std::string fingerprint;
    /// Where the terms keep a failure until the step ends (plugin_term.hpp).
    std::shared_ptr<PluginFailure> failure = std::make_shared<PluginFailure>();
    bool empty() const { return terms.size() == 0; }
};

/// What one plugin library registered (plugins.cpp).
struct PluginLibrary;

/// An element of the scene's "plugins" as its keys are read: what its library adds to, the scene
/// file (a relative library is taken from its folder), the element's index and its library once
/// opened (by "library", the first key read).
template <int Dim>
struct PluginInput {
    ScenePlugins<Dim>* out = nullptr;
    const std::string* sceneFile = nullptr;
    std::size_t index = 0;
    std::shared_ptr<const PluginLibrary> library;
};

/// The keys of each element of the scene's "plugins" (docs/scenes.md's table of them is made
/// from it).
template <int Dim>
const KeyTable<PluginInput<Dim>>& pluginKeys();

/// A copy of the document whose plugin library paths are absolute (relative paths are taken
/// from the scene file's directory), so the scene a checkpoint stores finds them from anywhere.
SceneDocument withAbsolutePluginPaths(const SceneDocument& doc);

/// Loads the libraries of the scene's "plugins" and makes their terms (each guarded, see
/// plugin_term.hpp), then checks the scene's output.formats against the built-in writers and
/// the plugins' (checkOutputFormats). Scene mistakes (missing file, unknown term, bad
/// parameters, a term of the other dimension, an unknown format) are AppErrors SCENE; a library
/// that is not a plugin, of another API version or whose code fails is PLUGIN.
template <int Dim>
ScenePlugins<Dim> loadPlugins(const SceneDocument& doc);

/// The output names with the plugins' fields: the fields the scene names are written under
/// their names, other quantities of user ids are left out. Checks that the terms created every
/// named field. Without plugins, `names` unchanged.
template <int Dim>
FieldNames pluginFieldNames(const ScenePlugins<Dim>& plugins, const sph::Storage<Dim>& initial,
                            FieldNames names, const std::string& file);

}  // namespace num::app
