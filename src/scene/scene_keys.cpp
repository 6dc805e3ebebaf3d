// Reading the scene sections that are objects of values from their key tables, and the tables'
// docs (scene/scene_keys.hpp; the tables: scene_key_tables.cpp, scene_key_tables_arrays.cpp).
#include "scene/scene_keys.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "plugin/plugins.hpp"
#include "scene/boundary_types.hpp"
#include "scene/shape_reader.hpp"

namespace num::app {

using detail::At;

namespace {

/// A number or "auto" (an empty optional), in the key's range.
template <class Spec>
std::optional<double> numberOrAuto(const At& a, const SceneKey<Spec>& k) {
    if (a.v.is_string() && a.v.template get<std::string>() == "auto") return std::nullopt;
    if (a.v.is_number()) return a.number(k.lo, k.hi, k.loOpen, k.unit);
    const std::string unit = *k.unit ? std::string(" [") + k.unit + "]" : "";
    a.fail((k.loOpen && k.lo == 0
                ? std::string("a positive number")
                : "a number in [" + detail::shortest(k.lo) + ", " + detail::shortest(k.hi) + "]") +
           unit + " or \"auto\"");
}

template <class Spec>
void readKey(const At& section, const SceneKey<Spec>& k, Spec& spec) {
    const bool given = section.has(k.name);
    const auto value = [&] { return section[k.name]; };
    switch (k.type) {
        case KeyType::FLAG:
            spec.*std::get<bool Spec::*>(k.field) =
                given ? value().boolean() : std::get<bool>(k.fallback);
            break;
        case KeyType::NUMBER:
            spec.*std::get<double Spec::*>(k.field) =
                given ? value().number(k.lo, k.hi, k.loOpen, k.unit) : std::get<double>(k.fallback);
            break;
        case KeyType::CHOICE:
            spec.*std::get<std::string Spec::*>(k.field) =
                given ? value().choice(k.choices) : std::get<std::string>(k.fallback);
            break;
        case KeyType::NUMBER_OR_AUTO:
            spec.*std::get<std::optional<double> Spec::*>(k.field) =
                given ? numberOrAuto(value(), k) : std::nullopt;
            break;
        case KeyType::TEXT:
            spec.*std::get<std::string Spec::*>(k.field) =
                given ? value().string() : std::get<std::string>(k.fallback);
            break;
        case KeyType::CUSTOM:
            if (given) k.read(value(), spec);
            break;
    }
}

/// A limit as docs/scenes.md writes it: 1e12, 1e-6, 0.8, -273.15 (powers of ten from 1e3 and to
/// 1e-3 as 1eN).
std::string docNumber(double x) {
    const double decade = std::log10(std::abs(x));
    if (x != 0 && decade == std::round(decade) && std::abs(decade) >= 3)
        return std::string(x < 0 ? "-" : "") + "1e" + std::to_string(int(decade));
    return detail::shortest(x);
}

/// A unit as docs/scenes.md writes it: m²/s, kg/m³, °C; "–" for none.
std::string docUnit(const std::string& unit) {
    if (unit.empty()) return "–";
    if (unit == "degC") return "°C";
    std::string s = unit;
    for (const auto& [from, to] : {std::pair{"^2", "²"}, std::pair{"^3", "³"}})
        if (const std::size_t at = s.find(from); at != std::string::npos) s.replace(at, 2, to);
    return s;
}

template <class Spec>
std::string docRange(const SceneKey<Spec>& k) {
    if (k.hi >= 1e300) return std::string(k.loOpen ? "> " : "≥ ") + docNumber(k.lo);
    return std::string(k.loOpen ? "(" : "[") + docNumber(k.lo) + ", " + docNumber(k.hi) + "]";
}

template <class Spec>
std::string docDefault(const SceneKey<Spec>& k) {
    if (k.required) return "required";
    if (k.type == KeyType::CUSTOM || *k.shownDefault) return k.shownDefault;
    std::string text;
    if (const bool* b = std::get_if<bool>(&k.fallback)) text = *b ? "true" : "false";
    if (const double* x = std::get_if<double>(&k.fallback)) text = detail::shortest(*x);
    if (const std::string* s = std::get_if<std::string>(&k.fallback)) text = "`\"" + *s + "\"`";
    return *k.defaultNote ? text + " " + k.defaultNote : text;
}

template <class Spec>
std::string docMeaning(const SceneKey<Spec>& k) {
    std::string values;
    if (k.type == KeyType::NUMBER) values = docRange(k);
    if (k.type == KeyType::NUMBER_OR_AUTO) values = docRange(k) + " or `\"auto\"`";
    if (k.type == KeyType::CHOICE)
        for (const std::string& name : k.choices)
            values += (values.empty() ? "`" : ", `") + name + "`";
    if (values.empty()) return k.meaning;
    return *k.meaning ? values + ": " + k.meaning : values;
}

}  // namespace

template <class Spec>
void readKeys(const At& at, const KeyTable<Spec>& table, Spec& spec) {
    std::vector<std::string> names, required;
    for (const SceneKey<Spec>& k : table) {
        names.push_back(k.name);
        if (k.required) required.push_back(k.name);
    }
    at.object(names, required);
    readKeyValues(at, table, spec);
}

template <class Spec>
void readKeyValues(const At& at, const KeyTable<Spec>& table, Spec& spec) {
    for (const SceneKey<Spec>& k : table) readKey(at, k, spec);
}

template <class Spec>
void readKeyValues(const At& at, const KeyTable<Spec>& table, Spec& spec,
                   const std::vector<std::string>& first) {
    const auto named = [&](const std::string& name) {
        for (const SceneKey<Spec>& k : table)
            if (name == k.name) return &k;
        throw std::logic_error("no scene key \"" + name + "\" in the table of " + at.path);
    };
    for (const std::string& name : first) readKey(at, *named(name), spec);
    for (const SceneKey<Spec>& k : table)
        if (std::find(first.begin(), first.end(), k.name) == first.end()) readKey(at, k, spec);
}

template <class Spec>
std::string keyTableMarkdown(const KeyTable<Spec>& table) {
    std::string md = "| key | unit | default | meaning |\n| --- | --- | --- | --- |\n";
    for (const SceneKey<Spec>& k : table)
        md += "| `" + std::string(k.name) + "` | " + docUnit(k.unit) + " | " + docDefault(k) +
              " | " + docMeaning(k) + " |\n";
    return md;
}

#define NUMERICS_SCENE_KEYS(Spec)                                               \
    template void readKeys<Spec>(const At&, const KeyTable<Spec>&, Spec&);      \
    template void readKeyValues<Spec>(const At&, const KeyTable<Spec>&, Spec&); \
    template void readKeyValues<Spec>(const At&, const KeyTable<Spec>&, Spec&,  \
                                      const std::vector<std::string>&);         \
    template std::string keyTableMarkdown<Spec>(const KeyTable<Spec>&);
NUMERICS_SCENE_KEYS(DomainInput<2>)
NUMERICS_SCENE_KEYS(DomainInput<3>)
NUMERICS_SCENE_KEYS(ParticleSpec)
NUMERICS_SCENE_KEYS(TimeSpec)
NUMERICS_SCENE_KEYS(NumericsSpec)
NUMERICS_SCENE_KEYS(MaterialSpec)
NUMERICS_SCENE_KEYS(PhysicsSpec)
NUMERICS_SCENE_KEYS(OutputSpec)
NUMERICS_SCENE_KEYS(FluidInput<2>)
NUMERICS_SCENE_KEYS(FluidInput<3>)
NUMERICS_SCENE_KEYS(BodyInput<2>)
NUMERICS_SCENE_KEYS(BodyInput<3>)
NUMERICS_SCENE_KEYS(EmitterInput<2>)
NUMERICS_SCENE_KEYS(EmitterInput<3>)
NUMERICS_SCENE_KEYS(ProbeInput<2>)
NUMERICS_SCENE_KEYS(ProbeInput<3>)
NUMERICS_SCENE_KEYS(SideInput<2>)
NUMERICS_SCENE_KEYS(SideInput<3>)
NUMERICS_SCENE_KEYS(TransformInput<2>)
NUMERICS_SCENE_KEYS(TransformInput<3>)
NUMERICS_SCENE_KEYS(ShapeInput<2>)
NUMERICS_SCENE_KEYS(ShapeInput<3>)
NUMERICS_SCENE_KEYS(BodyMotionSpec<2>)
NUMERICS_SCENE_KEYS(BodyMotionSpec<3>)
NUMERICS_SCENE_KEYS(SpringSpec<2>)
NUMERICS_SCENE_KEYS(SpringSpec<3>)
NUMERICS_SCENE_KEYS(ThermalInput)
NUMERICS_SCENE_KEYS(PluginInput<2>)
NUMERICS_SCENE_KEYS(PluginInput<3>)
#undef NUMERICS_SCENE_KEYS

}  // namespace num::app
