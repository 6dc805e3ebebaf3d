#include "scene/json_check.hpp"

#include "sph/suggest.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "app/formatted.hpp"

namespace num::app::detail {

std::string closest(const std::string& word, const std::vector<std::string>& candidates) {
    return sph::closestName(word, candidates);
}

std::string shortest(double x) {
    // Every digit that tells the value from a limit it crosses (1.0000001 is not 1).
    std::string text;
    for (int digits = 6; digits <= 17; ++digits)
        if (text = formatted("%.*g", digits, x); std::strtod(text.c_str(), nullptr) == x) break;
    return text;
}

std::string describe(const json& v) {
    switch (v.type()) {
        case json::value_t::null:
            return "null";
        case json::value_t::boolean:
            return v.get<bool>() ? "true" : "false";
        case json::value_t::string: {
            // One line, whatever the string holds: control characters escaped, long text cut.
            std::string text;
            for (unsigned char c : v.get<std::string>()) {
                if (text.size() > 80) return "the string \"" + text + "...\"";
                text += c == '\n'               ? std::string("\\n")
                        : c < 0x20 || c == 0x7f ? formatted("\\u%04x", c)
                                                : std::string(1, char(c));
            }
            return "the string \"" + text + "\"";
        }
        case json::value_t::array:
            return "an array of " + std::to_string(v.size()) + " values";
        case json::value_t::object:
            return "an object";
        default:
            return shortest(v.get<double>());
    }
}

void At::fail(const std::string& expected, const std::string& hint) const {
    throw sceneError(file, path, expected, describe(v), hint);
}

void At::failAt(const std::string& key, const std::string& expected) const {
    throw sceneError(file, join(key), expected, "nothing (the key is missing)");
}

void At::object(const std::vector<std::string>& allowed,
                const std::vector<std::string>& required) const {
    if (!v.is_object()) fail("an object");
    const std::vector<std::string>& names = allowed;
    for (const auto& [key, value] : v.items()) {
        if (std::find(names.begin(), names.end(), key) != names.end()) continue;
        const std::string guess = closest(key, names);
        std::string list;
        for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
        throw sceneError(file, join(key), "one of the keys " + list,
                         "the unknown key '" + key + "'",
                         guess.empty() ? "" : "did you mean '" + guess + "'?");
    }
    for (const std::string& r : required)
        if (!v.contains(r)) failAt(r, "this required key");
}

At At::required(const std::string& key) const {
    if (!has(key)) failAt(key, "this required key");
    return (*this)[key];
}

double At::number(double lo, double hi, bool loOpen, const std::string& unit) const {
    const std::string u = unit.empty() ? "" : " [" + unit + "]";
    // The limits in the shortest form that reads back the same; an open upper limit (1e300)
    // is named where a value exceeds it.
    const auto limit = [](double x) { return shortest(x); };
    const bool above = v.is_number() && v.get<double>() > hi;
    std::ostringstream range;
    if (above && hi >= 1e300)
        range << "a number in " << (loOpen ? "(" : "[") << limit(lo) << ", " << limit(hi) << "]";
    else if (loOpen && lo == 0 && hi >= 1e300)
        range << "a positive number";
    else if (lo == 0 && hi >= 1e300)
        range << "a number >= 0";
    else if (lo <= -1e300 && hi >= 1e300)
        range << "a number";
    else
        range << "a number in " << (loOpen ? "(" : "[") << limit(lo) << ", " << limit(hi) << "]";
    if (!v.is_number()) fail(range.str() + u);
    const double x = v.get<double>();
    if (!std::isfinite(x) || x < lo || x > hi || (loOpen && x == lo)) fail(range.str() + u);
    return x;
}

long At::integer(long lo, long hi) const {
    const std::string e = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (!v.is_number_integer()) fail(e);
    const long x = v.get<long>();
    if (x < lo || x > hi) fail(e);
    return x;
}

bool At::boolean() const {
    if (!v.is_boolean()) fail("true or false");
    return v.get<bool>();
}

std::string At::string() const {
    if (!v.is_string()) fail("a string");
    return v.get<std::string>();
}

std::string At::choice(std::initializer_list<const char*> choices) const {
    return choice(std::vector<std::string>(choices.begin(), choices.end()));
}

std::string At::choice(const std::vector<std::string>& names) const {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + ("\"" + n + "\"");
    if (!v.is_string()) fail("one of " + list);
    const std::string s = v.get<std::string>();
    if (std::find(names.begin(), names.end(), s) != names.end()) return s;
    const std::string guess = closest(s, names);
    fail("one of " + list, guess.empty() ? "" : "did you mean \"" + guess + "\"?");
}

Expression At::expression(const std::string& allowed, const std::string& meaning) const {
    std::string in;
    for (std::size_t k = 0; k < allowed.size(); ++k)
        in += (k == 0 ? "" : k + 1 == allowed.size() ? " and " : ", ") + allowed.substr(k, 1);
    const std::string expected = "a number or an expression in " + in;
    if (v.is_number()) return Expression(number());
    if (!v.is_string()) fail(expected);
    Expression e;
    try {
        e = Expression::parse(v.get<std::string>());
    } catch (const ExpressionError& error) {
        throw sceneError(file, path, "an expression in " + in, describe(v), error.what(),
                         ExitCode::EXPRESSION);
    }
    for (char c : e.variables())
        if (allowed.find(c) == std::string::npos)
            throw sceneError(file, path, expected, describe(v),
                             std::string("it uses '") + c + "', which is not defined here" +
                                 (meaning.empty() ? "" : ": " + meaning),
                             ExitCode::EXPRESSION);
    return e;
}

void At::array(std::size_t n, const std::string& what) const {
    if (!v.is_array() || v.size() != n) fail("an array of " + std::to_string(n) + " " + what);
}

}  // namespace num::app::detail
