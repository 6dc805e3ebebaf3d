// Checked reading of JSON values with key paths: every mistake becomes an AppError naming the
// file, the key path, what was expected and what was found (internal to numerics_app).
#pragma once

#include <array>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/errors.hpp"
#include "app/expression.hpp"
#include "spatial/vec.hpp"

namespace num::app::detail {

using nlohmann::json;

/// The closest of `candidates` to `word` if close enough to be a likely misspelling, else "".
std::string closest(const std::string& word, const std::vector<std::string>& candidates);
/// A short description of a JSON value for "found ..." ("the string \"abc\"", "-0.01").
/// A number in the fewest digits (at least 6, as %g) that read back the same value.
std::string shortest(double x);
std::string describe(const json& v);

/// A JSON value and where it is (file and key path such as "fluids[0].velocity").
struct At {
    const json& v;
    const std::string& file;
    std::string path;

    At operator[](const std::string& key) const { return {v.at(key), file, join(key)}; }
    At operator[](std::size_t i) const {
        return {v.at(i), file, path + "[" + std::to_string(i) + "]"};
    }
    std::string join(const std::string& key) const { return path.empty() ? key : path + "." + key; }
    bool has(const std::string& key) const { return v.is_object() && v.contains(key); }

    [[noreturn]] void fail(const std::string& expected, const std::string& hint = "") const;
    [[noreturn]] void failAt(const std::string& key, const std::string& expected) const;

    /// This must be an object with only the keys listed (and those listed as required).
    void object(const std::vector<std::string>& allowed,
                const std::vector<std::string>& required = {}) const;
    /// The value of a required key (error naming the key when missing).
    At required(const std::string& key) const;

    double number(double lo = -1e300, double hi = 1e300, bool loOpen = false,
                  const std::string& unit = "") const;
    double number(const std::string& key, double fallback, double lo, double hi,
                  bool loOpen = false, const std::string& unit = "") const {
        return has(key) ? (*this)[key].number(lo, hi, loOpen, unit) : fallback;
    }
    long integer(long lo, long hi) const;
    bool boolean() const;
    bool boolean(const std::string& key, bool fallback) const {
        return has(key) ? (*this)[key].boolean() : fallback;
    }
    std::string string() const;
    std::string choice(std::initializer_list<const char*> choices) const;
    /// One of `names` (a choice's table: sph/choice_table.hpp), else fails listing them.
    std::string choice(const std::vector<std::string>& names) const;
    /// A number or an expression string in the variables `allowed` (of "xyzt"); one that uses
    /// another variable is refused (exit code 6), naming it: it would be taken as 0.
    /// `meaning` says why the others are not allowed ("gravity is uniform in space").
    Expression expression(const std::string& allowed = "xyzt",
                          const std::string& meaning = "") const;
    /// An array of exactly n elements (n = dimension for vectors).
    void array(std::size_t n, const std::string& what) const;
};

/// A vector of Dim numbers [unit], one per axis.
template <int Dim>
Vec<double, Dim> readVec(const At& a, const std::string& unit) {
    a.array(Dim, std::string("numbers [") + unit + "] (one per axis of the " + std::to_string(Dim) +
                     "D scene)");
    Vec<double, Dim> v;
    for (int k = 0; k < Dim; ++k) v[k] = a[std::size_t(k)].number(-1e300, 1e300, false, unit);
    return v;
}

/// A vector of Dim numbers or expressions in the variables `allowed` (At::expression).
template <int Dim>
std::array<Expression, Dim> readField(const At& a, const std::string& allowed,
                                      const std::string& meaning) {
    a.array(Dim, "numbers or expressions (one per axis of the " + std::to_string(Dim) + "D scene)");
    std::array<Expression, Dim> f;
    for (int k = 0; k < Dim; ++k) f[k] = a[std::size_t(k)].expression(allowed, meaning);
    return f;
}

}  // namespace num::app::detail
