// The parameters of a plugin's term, read with the scene reader's checks (json_check.hpp).
#include <vector>

#include "app/plugin.hpp"
#include "scene/json_check.hpp"

namespace num::app::plugin {

using detail::At;

Parameters::Parameters(nlohmann::json term, std::string file, std::string path)
    : json_(std::move(term)), file_(std::move(file)), path_(std::move(path)) {}

void Parameters::allow(std::initializer_list<const char*> keys) const {
    std::vector<const char*> allowed(keys);
    for (const char* k : keys) name(k);
    allowed.push_back("term");
    const At a{json_, file_, path_};
    if (!json_.is_object()) a.fail("an object");
    for (const auto& [key, value] : json_.items()) {
        bool known = false;
        for (const char* k : allowed) known |= key == k;
        if (known) continue;
        std::vector<std::string> names(allowed.begin(), allowed.end() - 1);
        std::string list;
        for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
        const std::string guess = detail::closest(key, names);
        throw sceneError(file_, a.join(key),
                         list.empty() ? "no parameters for this term" : "one of the keys " + list,
                         "the unknown key '" + key + "'",
                         guess.empty() ? "" : "did you mean '" + guess + "'?");
    }
}

bool Parameters::has(const std::string& key) const {
    return json_.is_object() && json_.contains(name(key));
}

double Parameters::number(const std::string& key, double lo, double hi,
                          const std::string& unit) const {
    return At{json_, file_, path_}.required(name(key)).number(lo, hi, false, unit);
}

double Parameters::number(const std::string& key, double fallback, double lo, double hi,
                          const std::string& unit) const {
    return has(key) ? number(key, lo, hi, unit) : fallback;
}

double Parameters::positive(const std::string& key, const std::string& unit) const {
    return At{json_, file_, path_}.required(name(key)).number(0, 1e300, true, unit);
}

long Parameters::integer(const std::string& key, long fallback, long lo, long hi) const {
    return has(key) ? At{json_, file_, path_}[key].integer(lo, hi) : fallback;  // has() names it
}

bool Parameters::boolean(const std::string& key, bool fallback) const {
    return At{json_, file_, path_}.boolean(name(key), fallback);
}

std::string Parameters::string(const std::string& key) const {
    return At{json_, file_, path_}.required(name(key)).string();
}

std::string Parameters::choice(const std::string& key,
                               std::initializer_list<const char*> choices) const {
    return At{json_, file_, path_}.required(name(key)).choice(choices);
}

template <int Dim>
sph::Vector<Dim> Parameters::vector(const std::string& key, const std::string& unit) const {
    const At a = At{json_, file_, path_}.required(name(key));
    a.array(Dim, "numbers" + (unit.empty() ? "" : " [" + unit + "]") + " (one per axis of the " +
                     std::to_string(Dim) + "D scene)");
    sph::Vector<Dim> v;
    for (int k = 0; k < Dim; ++k) v[k] = a[std::size_t(k)].number(-1e300, 1e300, false, unit);
    return v;
}

std::vector<std::string> Parameters::unnamedKeys() const {
    std::vector<std::string> keys;
    if (json_.is_object())
        for (const auto& [key, value] : json_.items())
            if (key != "term" && !named_.count(key)) keys.push_back(key);
    return keys;
}

void Parameters::fail(const std::string& key, const std::string& expected) const {
    const At a{json_, file_, path_};
    if (!has(key)) a.failAt(key, expected);
    a[key].fail(expected);
}

template sph::Vector<2> Parameters::vector<2>(const std::string&, const std::string&) const;
template sph::Vector<3> Parameters::vector<3>(const std::string&, const std::string&) const;

}  // namespace num::app::plugin
