// A user's choice among named alternatives (kernel, integrator, evaluation, equation of state):
// one table per choice, from which its dispatch, the values settings and scenes allow and the
// error texts that list them all come. A table is a std::tuple of entries when each alternative
// is a type (kernels, integrators: the dispatch instantiates each at compile time), or a
// std::array of Choice<Value> when it is a value; every entry has a `name` and a `help` line
// (which the setting's help lists).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "sph/settings_error.hpp"

namespace num::sph {

/// An alternative that selects a value (an enumerator).
template <class Value>
struct Choice {
    std::string_view name;
    Value value;
    std::string_view help;
};

/// The names of a table's entries, in its order.
template <class Table>
std::vector<std::string> choiceNames(const Table& table) {
    return std::apply(
        [](const auto&... entry) { return std::vector<std::string>{std::string(entry.name)...}; },
        table);
}

/// "a, b or c": the names as an error text lists them.
inline std::string choiceList(const std::vector<std::string>& names) {
    std::string list;
    for (std::size_t i = 0; i < names.size(); ++i)
        list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return list;
}

/// "a (help of a), b (help of b) or c (help of c)": the names with their help, as a setting's
/// help lists them.
template <class Table>
std::string choiceHelp(const Table& table) {
    std::vector<std::string> lines = std::apply(
        [](const auto&... entry) {
            return std::vector<std::string>{std::string(entry.name) + " (" +
                                            std::string(entry.help) + ")" ...};
        },
        table);
    return choiceList(lines);
}

/// The position of `name` in the table, if it is there.
template <class Table>
constexpr std::optional<std::size_t> choiceIndex(const Table& table, std::string_view name) {
    std::optional<std::size_t> found;
    std::size_t i = 0;
    auto visit = [&](const auto& entry) {
        if (!found && entry.name == name) found = i;
        ++i;
    };
    std::apply([&](const auto&... entry) { (visit(entry), ...); }, table);
    return found;
}

/// The position of `name` in the table; else a SettingsError "unknown <what> '<name>' (expected
/// a, b or c)".
template <class Table>
std::size_t chooseIndex(const Table& table, std::string_view what, const std::string& name) {
    if (const auto i = choiceIndex(table, name)) return *i;
    throw SettingsError("unknown " + std::string(what) + " '" + name + "' (expected " +
                        choiceList(choiceNames(table)) + ")");
}

/// Calls f(entry) with the table's entry at `index` (the last entry past the end), each entry
/// with its own type: the alternatives of a tuple are instantiated at compile time, and the
/// call is a chain of comparisons, once per call, not per particle or pair.
template <std::size_t I = 0, class Table, class F>
decltype(auto) withChoice(const Table& table, std::size_t index, F&& f) {
    if constexpr (I + 1 == std::tuple_size_v<Table>) {
        return f(std::get<I>(table));
    } else {
        if (index == I) return f(std::get<I>(table));
        return withChoice<I + 1>(table, index, f);
    }
}

}  // namespace num::sph
