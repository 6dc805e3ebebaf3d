#include "app/writer_registry.hpp"

#include <algorithm>
#include <stdexcept>

#include "app/errors.hpp"
#include "scene/json_check.hpp"

// The built-in formats of output.formats, in this order: one line each. FORMAT(name) is the
// function void <name>Format(WriterRegistry&) that formats/<name>_writer.cpp defines (it
// registers its writer under the name). A new format is its file there and its line here.
#define NUMERICS_BUILT_IN_FORMATS(FORMAT) \
    FORMAT(vtu)                           \
    FORMAT(csv)                           \
    /* the end of the table */

namespace num::app {

#define NUMERICS_DECLARE_FORMAT(name) void name##Format(WriterRegistry& registry);
NUMERICS_BUILT_IN_FORMATS(NUMERICS_DECLARE_FORMAT)
#undef NUMERICS_DECLARE_FORMAT

WriterRegistry builtInWriters() {
    WriterRegistry registry;
#define NUMERICS_ADD_FORMAT(name) name##Format(registry);
    NUMERICS_BUILT_IN_FORMATS(NUMERICS_ADD_FORMAT)
#undef NUMERICS_ADD_FORMAT
    return registry;
}

namespace {

template <class Table, class Factory>
void addTo(Table& table, const std::string& name, Factory factory, const char* dim) {
    for (const auto& [taken, f] : table)
        if (taken == name)
            throw std::logic_error("a second " + std::string(dim) + " writer named \"" + name +
                                   "\"");
    table.emplace_back(name, std::move(factory));
}

}  // namespace

void WriterRegistry::add(const std::string& name, WriterFactory<2> factory) {
    addTo(writers2_, name, std::move(factory), "2D");
}

void WriterRegistry::add(const std::string& name, WriterFactory<3> factory) {
    addTo(writers3_, name, std::move(factory), "3D");
}

template <int Dim>
const std::vector<std::pair<std::string, WriterFactory<Dim>>>& WriterRegistry::table() const {
    if constexpr (Dim == 2)
        return writers2_;
    else
        return writers3_;
}

template <int Dim>
bool WriterRegistry::has(const std::string& name) const {
    const auto& t = table<Dim>();
    return std::any_of(t.begin(), t.end(), [&](const auto& entry) { return entry.first == name; });
}

template <int Dim>
std::vector<std::string> WriterRegistry::names() const {
    std::vector<std::string> out;
    for (const auto& [name, factory] : table<Dim>()) out.push_back(name);
    return out;
}

template <int Dim>
std::unique_ptr<IWriter<Dim>> WriterRegistry::make(const std::string& name,
                                                   const WriterContext& context) const {
    for (const auto& [n, factory] : table<Dim>())
        if (n == name) return factory(context);
    throw std::logic_error("no " + std::to_string(Dim) + "D writer named \"" + name + "\"");
}

template <int Dim>
void checkOutputFormats(const std::string& file, const std::vector<std::string>& formats,
                        const WriterRegistry& writers) {
    const std::vector<std::string> names = writers.names<Dim>();
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + ("\"" + n + "\"");
    for (std::size_t i = 0; i < formats.size(); ++i) {
        if (writers.has<Dim>(formats[i])) continue;
        const std::string guess = detail::closest(formats[i], names);
        throw sceneError(file, "output.formats." + std::to_string(i), "one of " + list,
                         detail::describe(nlohmann::json(formats[i])),
                         guess.empty() ? "" : "did you mean \"" + guess + "\"?");
    }
}

template bool WriterRegistry::has<2>(const std::string&) const;
template bool WriterRegistry::has<3>(const std::string&) const;
template std::vector<std::string> WriterRegistry::names<2>() const;
template std::vector<std::string> WriterRegistry::names<3>() const;
template std::unique_ptr<IWriter<2>> WriterRegistry::make<2>(const std::string&,
                                                             const WriterContext&) const;
template std::unique_ptr<IWriter<3>> WriterRegistry::make<3>(const std::string&,
                                                             const WriterContext&) const;
template void checkOutputFormats<2>(const std::string&, const std::vector<std::string>&,
                                    const WriterRegistry&);
template void checkOutputFormats<3>(const std::string&, const std::vector<std::string>&,
                                    const WriterRegistry&);

}  // namespace num::app
