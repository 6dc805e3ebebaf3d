// Typed settings with defaults and validation: RunSettings for the run, Material for the
// parameters of a material (IMaterial). An unknown key, a value of the wrong type or out of
// range is a SettingsError whose message names the key and what was expected.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "sph/defaults.hpp"
#include "sph/evaluation_mode.hpp"
#include "sph/kernel_table.hpp"
#include "sph/settings_error.hpp"
#include "sph/suggest.hpp"

namespace num::sph {

using SettingValue = std::variant<bool, std::int64_t, double, std::string>;

/// One declared key: its default, admissible range or choices, and a line of help.
struct SettingSpec {
    SettingSpec() = default;
    SettingSpec(std::string key_, SettingValue defaultValue_, std::string help_,
                double min_ = -std::numeric_limits<double>::infinity(),
                double max_ = std::numeric_limits<double>::infinity(),
                std::vector<std::string> choices_ = {})
        : key(std::move(key_)),
          defaultValue(std::move(defaultValue_)),
          help(std::move(help_)),
          min(min_),
          max(max_),
          choices(std::move(choices_)) {}

    std::string key;
    SettingValue defaultValue;
    std::string help;
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    std::vector<std::string> choices;  // for strings: the allowed values (empty = any)
};

/// A set of declared keys and their current values.
class ParameterSet {
  public:
    ParameterSet() = default;
    explicit ParameterSet(const std::vector<SettingSpec>& schema) {
        for (const auto& s : schema) declare(s);
    }

    /// Declares a key (re-declaring an existing key keeps its current value).
    void declare(const SettingSpec& spec) {
        if (specs_.count(spec.key)) return;
        specs_[spec.key] = spec;
        values_[spec.key] = spec.defaultValue;
    }

    bool declared(const std::string& key) const { return specs_.count(key) != 0; }

    /// Sets a value after checking key, type and range. An integer is accepted for a real.
    ParameterSet& setValue(const std::string& key, SettingValue value) {
        const SettingSpec& spec = specOf(key);
        if (std::holds_alternative<double>(spec.defaultValue) &&
            std::holds_alternative<std::int64_t>(value))
            value = double(std::get<std::int64_t>(value));
        if (value.index() != spec.defaultValue.index())
            throw SettingsError("setting '" + key + "': expected " + typeName(spec.defaultValue) +
                                ", got " + typeName(value));
        if (const double* d = std::get_if<double>(&value)) checkRange(spec, *d);
        if (const auto* i = std::get_if<std::int64_t>(&value)) checkRange(spec, double(*i));
        if (const auto* s = std::get_if<std::string>(&value); s && !spec.choices.empty()) {
            bool ok = false;
            for (const auto& c : spec.choices) ok |= c == *s;
            if (!ok) {
                std::string list;
                for (const auto& c : spec.choices) list += (list.empty() ? "" : ", ") + c;
                throw SettingsError("setting '" + key + "': '" + *s + "' is not one of " + list);
            }
        }
        values_[key] = std::move(value);
        return *this;
    }
    /// Sets a bool, an integer, a real or a string (see setValue).
    template <class T>
    ParameterSet& set(const std::string& key, const T& value) {
        if constexpr (std::is_same_v<T, bool>)
            return setValue(key, SettingValue(value));
        else if constexpr (std::is_integral_v<T>)
            return setValue(key, std::int64_t(value));
        else if constexpr (std::is_floating_point_v<T>)
            return setValue(key, double(value));
        else
            return setValue(key, SettingValue(std::string(value)));
    }

    template <class T>
    T get(const std::string& key) const {
        specOf(key);
        const SettingValue& v = values_.at(key);
        if constexpr (std::is_same_v<T, double> || std::is_same_v<T, float>) {
            if (auto* d = std::get_if<double>(&v)) return T(*d);
        } else if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
            if (auto* i = std::get_if<std::int64_t>(&v)) return T(*i);
        } else if constexpr (std::is_same_v<T, bool>) {
            if (auto* b = std::get_if<bool>(&v)) return *b;
        } else if constexpr (std::is_same_v<T, std::string>) {
            if (auto* s = std::get_if<std::string>(&v)) return *s;
        }
        throw SettingsError("setting '" + key + "' is a " + typeName(v) +
                            ", read with another type");
    }

    const std::map<std::string, SettingSpec>& specs() const { return specs_; }
    /// Equal values of every key (e.g. two requests for a derivative made from settings).
    friend bool operator==(const ParameterSet& a, const ParameterSet& b) {
        return a.values_ == b.values_;
    }

  private:
    const SettingSpec& specOf(const std::string& key) const {
        auto it = specs_.find(key);
        if (it != specs_.end()) return it->second;
        std::vector<std::string> names;
        for (const auto& [k, spec] : specs_) names.push_back(k);
        const std::string hint = closestName(key, names);
        throw SettingsError("unknown setting '" + key + "'" +
                            (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
    }
    static void checkRange(const SettingSpec& s, double v) {
        if (!(v >= s.min && v <= s.max))
            throw SettingsError("setting '" + s.key + "' = " + shortest(v) + " is outside [" +
                                shortest(s.min) + ", " + shortest(s.max) + "]");
    }
    /// A number as printf's %.17g writes it, shortened to the fewest digits that read back
    /// the same: 1e-07, 0.25, 1e+300, inf.
    static std::string shortest(double v) {
        char text[32];
        for (int digits = 1; digits <= 17; ++digits) {
            std::snprintf(text, sizeof text, "%.*g", digits, v);
            if (std::strtod(text, nullptr) == v || v != v) break;
        }
        return text;
    }
    static std::string typeName(const SettingValue& v) {
        static const char* names[] = {"boolean", "integer", "number", "string"};
        return names[v.index()];
    }

    std::map<std::string, SettingSpec> specs_;
    std::map<std::string, SettingValue> values_;
};

/// Settings of a run: kernel, smoothing length, time-step factors, threads, evaluation mode.
class RunSettings : public ParameterSet {
  public:
    RunSettings() : ParameterSet(schema()) {}

    static std::vector<SettingSpec> schema() {
        const double inf = std::numeric_limits<double>::infinity();
        return {
            {"kernel", std::string(defaults::kernel),
             "smoothing kernel: " + choiceHelp(kernelTable), 0, 0, choiceNames(kernelTable)},
            {"smoothing_length", defaults::smoothingLength, "smoothing length h [m]", 1e-300, inf},
            {"threads", std::int64_t(defaults::threads), "worker threads of the parallel scheduler",
             1, 1024},
            {"evaluation", std::string(defaults::evaluation),
             "pair evaluation: " + choiceHelp(evaluationTable), 0, 0, choiceNames(evaluationTable)},
            {"blocks", std::int64_t(defaults::blocks),
             "particle blocks of the symmetric pair loop (at least 8 per thread when asymmetric); "
             "results may depend on it, never on threads",
             1, 4096},
            {"cfl", defaults::cfl, "Courant factor C in dt <= C h / (c + |v|)", 1e-6, 1.0},
            {"acceleration_factor", defaults::accelerationFactor, "factor in dt <= f sqrt(h / |a|)",
             1e-6, 1.0},
            {"viscous_factor", defaults::viscousFactor, "factor in dt <= f h^2 / nu", 1e-6, 1.0},
            {"diffusion_factor", defaults::diffusionFactor, "factor in dt <= f h^2 / alpha", 1e-6,
             1.0},
            {"dt_max", inf, "largest time step [s]", 1e-300, inf},
            {"dt_fixed", 0.0, "fixed time step [s]; 0 selects the adaptive step", 0.0, inf},
            {"reorder_every", std::int64_t(defaults::reorderEvery),
             "steps between reorderings by cell (0: never)", 0, 1e9},
            {"neighbour_skin", defaults::neighbourSkin,
             "skin of the neighbour lists, a fraction of the support radius: they are rebuilt when "
             "a particle moved more than half of it (0: at every evaluation); the smallest skin "
             "when it adapts to the flow (neighbour_skin_max); results do not depend on it",
             0.0, 10.0},
            {"neighbour_skin_max", defaults::neighbourSkinMax,
             "largest skin of the neighbour lists: each build takes the skin with which they "
             "would last 8 evaluations at the speed the fastest particle moved since the last "
             "build, within [neighbour_skin, neighbour_skin_max] (at most neighbour_skin: a fixed "
             "skin); results do not depend on it",
             0.0, 10.0},
        };
    }
};

/// A material: a name and its parameters.
class IMaterial {
  public:
    virtual ~IMaterial() = default;
    virtual const std::string& name() const = 0;
    virtual const ParameterSet& params() const = 0;
    virtual ParameterSet& params() = 0;
};

/// The default material with the parameters of the built-in physics.
class Material : public IMaterial {
  public:
    explicit Material(std::string name = "water") : name_(std::move(name)), params_(schema()) {}

    const std::string& name() const override { return name_; }
    const ParameterSet& params() const override { return params_; }
    ParameterSet& params() override { return params_; }

    static std::vector<SettingSpec> schema() {
        const double inf = std::numeric_limits<double>::infinity();
        return {
            {"density", defaults::density, "rest density rho0 [kg/m^3]", 1e-300, inf},
            {"sound_speed", defaults::materialSoundSpeed, "artificial sound speed c0 [m/s]", 1e-300,
             inf},
            {"viscosity", defaults::viscosity, "kinematic viscosity nu [m^2/s]", 0.0, inf},
            {"artificial_viscosity", defaults::materialArtificialViscosity,
             "Monaghan's alpha (the apps' default: defaults.hpp)", 0.0, 10.0},
            {"conductivity", defaults::conductivity, "thermal conductivity k [W/(m K)]", 0.0, inf},
            {"heat_capacity", defaults::heatCapacity, "specific heat capacity c [J/(kg K)]", 1e-300,
             inf},
            {"thermal_expansion", defaults::thermalExpansion,
             "volumetric thermal expansion beta [1/K]", 0.0, inf},
            {"reference_temperature", defaults::referenceTemperature,
             "temperature of the rest density", -inf, inf},
        };
    }

  private:
    std::string name_;
    ParameterSet params_;
};

}  // namespace num::sph
