// The keys of the scene sections that are objects of values (particles, time, numerics,
// materials, physics, output), each declared once: name, type, range, default, unit and
// meaning. The reader reads and checks them from these tables, and docs/scenes.md's tables of
// these sections are made from them (tests/apps/test_scene_key_docs.cpp fails when the two
// differ). Internal to numerics_app.
#pragma once

#include <optional>
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
    const char* shownDefault = "";                                ///< CUSTOM: the docs' default
};

template <class Spec>
using KeyTable = std::vector<SceneKey<Spec>>;

const KeyTable<ParticleSpec>& particleKeys();
const KeyTable<TimeSpec>& timeKeys();
const KeyTable<NumericsSpec>& numericsKeys();
const KeyTable<MaterialSpec>& materialKeys();
const KeyTable<PhysicsSpec>& physicsKeys();
const KeyTable<OutputSpec>& outputKeys();

/// Reads section `at` (an object of only these keys) into `spec`; an absent key gets its default.
template <class Spec>
void readKeys(const detail::At& at, const KeyTable<Spec>& table, Spec& spec);

/// docs/scenes.md's table of these keys (key, unit, default, meaning), lines ending in '\n'.
template <class Spec>
std::string keyTableMarkdown(const KeyTable<Spec>& table);

}  // namespace num::app
