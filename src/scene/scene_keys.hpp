// The keys of the scene sections that are objects of values (domain, particles, time, numerics,
// materials, physics, output), of the elements of the arrays `fluids`, `bodies`, `emitters` and
// `probes`, of each boundary type, interior walls and a wall's `thermal`
// (scene/boundary_types.hpp), of a body's free and prescribed motions and their springs
// (scene/body_motion_reader.hpp) and of each shape and the shapes' transformations
// (scene/shape_reader.hpp), each declared once: name, type, range, default, unit and meaning.
// The reader reads and checks them from these tables, and the tables of these keys in
// docs/scenes.md and docs/geometry.md are made from them (tests/apps/test_scene_key_docs.cpp
// fails when the two differ). Internal to numerics_app.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "app/scene.hpp"
#include "scene/json_check.hpp"

namespace num::app {

/// What a key holds: true or false; a number in a range; one name of a list; a number in a
/// range or "auto" (an empty optional); a string; anything its own `read` takes (lists,
/// pairs, checked names), left at the struct's default when absent.
enum class KeyType { FLAG, NUMBER, CHOICE, NUMBER_OR_AUTO, TEXT, CUSTOM };

/// One key of a section whose values land in a `Spec`.
template <class Spec>
struct SceneKey {
    using Field = std::variant<bool Spec::*, double Spec::*, std::string Spec::*,
                               std::optional<double> Spec::*>;
    const char* name;
    KeyType type;
    Field field = {};
    std::variant<bool, double, std::string> fallback = {};  ///< the default when the key is absent
    const char* unit = "";                                  ///< as in messages ("m^2/s"); "" none
    double lo = -1e300, hi = 1e300;                         ///< NUMBER, NUMBER_OR_AUTO: [lo, hi]
    bool loOpen = false;                                    ///< (lo, hi]
    std::vector<std::string> choices = {};                  ///< CHOICE
    const char* meaning = "";                               ///< the docs' line
    bool required = false;
    const char* defaultNote = "";  ///< after the default in the docs ("(no limit)")
    void (*read)(const detail::At& value, Spec& spec) = nullptr;  ///< CUSTOM
    /// The docs' default: a CUSTOM key's; another's where given, shown instead of the
    /// fallback ("forever" for 1e300)
    const char* shownDefault = "";
};

template <class Spec>
using KeyTable = std::vector<SceneKey<Spec>>;

/// The reader of a key read before the table's others: a placed shape's `shape`, read with its
/// shape's keys (scene_reader.cpp's readPlacedShape).
template <class Spec>
void readBefore(const detail::At&, Spec&) {}

/// The domain box as its keys are read.
template <int Dim>
struct DomainInput {
    SceneVec<Dim> min{}, max{};
};

/// A fluid block as its keys (beside its shape's) are read: the block, the materials its
/// `material` must name and its object.
template <int Dim>
struct FluidInput : FluidBlock<Dim> {
    const std::map<std::string, MaterialSpec>* materials = nullptr;
    const detail::At* at = nullptr;
};

/// A body as its keys (beside its shape's) are read: the body and the materials its `material`
/// must name.
template <int Dim>
struct BodyInput : Body<Dim> {
    const std::map<std::string, MaterialSpec>* materials = nullptr;
};

/// An emitter as its keys are read: the emitter, and the materials its `material` must name.
template <int Dim>
struct EmitterInput : Emitter<Dim> {
    const std::map<std::string, MaterialSpec>* materials = nullptr;
};

/// A probe as its keys are read: the probe, the names of the probes before it (a name is
/// unique) and the probe's object.
template <int Dim>
struct ProbeInput : Probe<Dim> {
    std::set<std::string>* names = nullptr;
    const detail::At* at = nullptr;

    /// A probe is exactly one of a point, a body, a wall or a side: checked before any of them or
    /// the fields (whose choices depend on it) is read, and after all of them (none given).
    void checkOneKind() const {
        int kinds = 0;
        for (const char* key : {"point", "body", "wall", "side"}) kinds += int(at->has(key));
        if (kinds != 1) at->fail("one of a \"point\", a \"body\", a \"wall\" or a \"side\"");
    }
};

template <int Dim>
const KeyTable<DomainInput<Dim>>& domainKeys();
const KeyTable<ParticleSpec>& particleKeys();
const KeyTable<TimeSpec>& timeKeys();
const KeyTable<NumericsSpec>& numericsKeys();
const KeyTable<MaterialSpec>& materialKeys();
const KeyTable<PhysicsSpec>& physicsKeys();
const KeyTable<OutputSpec>& outputKeys();
template <int Dim>
const KeyTable<FluidInput<Dim>>& fluidKeys();  ///< each element of `fluids`
template <int Dim>
const KeyTable<BodyInput<Dim>>& bodyKeys();  ///< each element of `bodies`
template <int Dim>
const KeyTable<EmitterInput<Dim>>& emitterKeys();  ///< each element of `emitters`
template <int Dim>
const KeyTable<ProbeInput<Dim>>& probeKeys();  ///< each element of `probes`

/// The name of a material defined under "materials"; else fails, listing them (and the one
/// likely meant).
std::string materialName(const detail::At& a, const std::map<std::string, MaterialSpec>& materials);

/// Reads section `at` (an object of only these keys) into `spec`; an absent key gets its default.
template <class Spec>
void readKeys(const detail::At& at, const KeyTable<Spec>& table, Spec& spec);

/// Reads the keys of `table` that `at` has, as readKeys but without checking which keys the
/// object has (its owner does: a boundary's type, an interior wall's shape).
template <class Spec>
void readKeyValues(const detail::At& at, const KeyTable<Spec>& table, Spec& spec);

/// As readKeyValues, but the keys named in `first` before the others, in that order: a section
/// whose keys were read in another order than its messages list them in, before its table (a
/// name not in the table is a std::logic_error).
template <class Spec>
void readKeyValues(const detail::At& at, const KeyTable<Spec>& table, Spec& spec,
                   const std::vector<std::string>& first);

/// The names of the table's keys (its required keys only with `requiredOnly`), in its order.
template <class Spec>
std::vector<std::string> keyNames(const KeyTable<Spec>& table, bool requiredOnly = false) {
    std::vector<std::string> names;
    for (const SceneKey<Spec>& k : table)
        if (!requiredOnly || k.required) names.emplace_back(k.name);
    return names;
}

/// docs/scenes.md's table of these keys (key, unit, default, meaning), lines ending in '\n'.
template <class Spec>
std::string keyTableMarkdown(const KeyTable<Spec>& table);

}  // namespace num::app
