// The fingerprint of a run (internal to numerics_app): everything that shapes its particle set and
// its equations, as "key = value" lines (the content of the mesh files its shapes read too). A
// checkpoint stores it; a restart whose fingerprint differs is refused, naming what differs. What
// may change on restart is left out: the end time, the output settings, the threads and the
// backend, and the engine settings that change no result (the neighbour lists' skin), also where a
// checkpoint of an older version lists them.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <variant>

#include "app/errors.hpp"
#include "app/scene_loader.hpp"
#include "app/scene_setup.hpp"
#include "scene/file_hash.hpp"

namespace num::app {

namespace detail {

/// Engine settings no result depends on (sph/settings.hpp): a restart may change them.
inline bool changesNoResult(const std::string& fingerprintKey) {
    for (const char* key : {"threads", "neighbour_skin", "neighbour_skin_max"})
        if (fingerprintKey == std::string("engine setting ") + key) return true;
    return false;
}

inline bool mayChangeOnRestart(const std::string& path) {
    for (const char* p : {"time.end", "output", "name", "description"})
        if (path == p || path.rfind(std::string(p) + ".", 0) == 0) return true;
    return false;
}

/// One line per leaf value of the scene: "fluids[0].temperature = 20".
inline void flattenScene(const nlohmann::json& v, const std::string& path,
                         std::map<std::string, std::string>& out) {
    if (mayChangeOnRestart(path) || ((v.is_object() || v.is_array()) && v.empty())) return;
    if (v.is_object()) {
        for (const auto& [key, value] : v.items())
            flattenScene(value, path.empty() ? key : path + "." + key, out);
    } else if (v.is_array()) {
        for (std::size_t i = 0; i < v.size(); ++i)
            flattenScene(v[i], path + "[" + std::to_string(i) + "]", out);
    } else {
        out[path] = v.dump();
    }
}

/// One line per mesh file a shape reads ("mesh", "section"; names relative to `sceneDir`):
/// "walls[0].file content (FNV-1a) = ...", so that a restart notices an edited mesh.
inline void hashShapeFiles(const nlohmann::json& v, const std::string& path,
                           const std::string& sceneDir, std::map<std::string, std::string>& out) {
    if (v.is_object()) {
        const auto shape = v.find("shape"), file = v.find("file");
        if (shape != v.end() && file != v.end() && file->is_string() &&
            (*shape == "mesh" || *shape == "section"))
            out[path + ".file content (FNV-1a)"] =
                fileHash((std::filesystem::path(sceneDir) / file->get<std::string>()).string());
        for (const auto& [key, value] : v.items())
            hashShapeFiles(value, path.empty() ? key : path + "." + key, sceneDir, out);
    } else if (v.is_array()) {
        for (std::size_t i = 0; i < v.size(); ++i)
            hashShapeFiles(v[i], path + "[" + std::to_string(i) + "]", sceneDir, out);
    }
}

/// Whether a scene line names a file whose content another line holds: a shape's `file` (its
/// content hash) or a plugin's `library` (its absolute path and content hash, "plugin i
/// library"). Its text is left out, so that a checkpoint may store it absolute (a restart from
/// the checkpoint alone finds it) and a restart of the scene file, relative, is the same run.
inline bool namesHashedFile(const std::string& key, const std::map<std::string, std::string>& a,
                            const std::map<std::string, std::string>& b) {
    const std::string hash = key + " content (FNV-1a)";
    if (key.ends_with(".file") && (a.count(hash) || b.count(hash))) return true;
    const std::string prefix = "plugins[", suffix = "].library";
    if (!key.starts_with(prefix) || !key.ends_with(suffix) ||
        key.size() <= prefix.size() + suffix.size())
        return false;
    const std::string index = key.substr(prefix.size(), key.size() - prefix.size() - suffix.size());
    return index.find_first_not_of("0123456789") == std::string::npos;
}

inline std::map<std::string, std::string> parseFingerprint(const std::string& text) {
    std::map<std::string, std::string> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        const auto eq = line.find(" = ");
        if (eq != std::string::npos) lines[line.substr(0, eq)] = line.substr(eq + 3);
    }
    return lines;
}

}  // namespace detail

template <int Dim>
std::string runFingerprint(const SceneDocument& doc, const SceneSetup<Dim>& setup,
                           const sph::Storage<Dim>& initial) {
    std::map<std::string, std::string> lines;
    detail::flattenScene(doc.json(), "", lines);
    detail::hashShapeFiles(doc.json(), "", std::filesystem::path(doc.file()).parent_path().string(),
                           lines);
    std::erase_if(
        lines, [&](const auto& line) { return detail::namesHashedFile(line.first, lines, lines); });
    for (const auto& [key, spec] : setup.settings.specs()) {
        if (detail::changesNoResult("engine setting " + key)) continue;
        // Every setting is one of bool, integer, number, string: print whichever it holds.
        std::string value;
        std::visit(
            [&](const auto& d) {
                using T = std::decay_t<decltype(d)>;
                std::ostringstream s;
                s.precision(17);
                s << setup.settings.template get<T>(key);
                value = s.str();
            },
            spec.defaultValue);
        lines["engine setting " + key] = value;
    }
    std::ostringstream c0;
    c0.precision(17);
    c0 << setup.model.c0();
    lines["engine sound speed"] = c0.str();
    lines["engine initial particles"] = std::to_string(initial.size());
    std::string quantities;
    initial.forEach([&](sph::QuantityId id, const sph::Quantity<Dim>& q) {
        quantities += std::to_string(int(id)) + ":" + std::to_string(int(q.order())) + " ";
    });
    lines["engine quantities (id:order)"] = quantities;
    std::string text;
    for (const auto& [key, value] : lines) text += key + " = " + value + "\n";
    return text;
}

/// Refuses (AppError CHECKPOINT) a restart whose fingerprint differs from the checkpoint's.
inline void checkFingerprint(const std::string& stored, const std::string& current,
                             const std::string& checkpoint) {
    const auto a = detail::parseFingerprint(stored), b = detail::parseFingerprint(current);
    const std::string quantitiesKey = "engine quantities (id:order)";
    std::string diff;
    int count = 0;
    bool otherQuantities = false;
    auto report = [&](const std::string& key, const std::string& here, const std::string& there) {
        otherQuantities |= key == quantitiesKey;
        if (++count <= 3)
            diff += std::string(diff.empty() ? "" : "; ") + key + " is " + here + " here, " +
                    there + " in the checkpoint";
    };
    for (const auto& [key, value] : b) {
        if (detail::changesNoResult(key) || detail::namesHashedFile(key, a, b)) continue;
        const auto it = a.find(key);
        if (it == a.end())
            report(key, value, "absent");
        else if (it->second != value)
            report(key, value, it->second);
    }
    for (const auto& [key, value] : a)
        if (!b.count(key) && !detail::changesNoResult(key) && !detail::namesHashedFile(key, a, b))
            report(key, "absent", value);
    if (count == 0) return;
    if (count > 3) diff += "; and " + std::to_string(count - 3) + " more";
    // The stored quantities also change with the version of numerics (or of a plugin).
    const std::string version =
        otherQuantities ? "; the particles hold other quantities: a checkpoint of another "
                          "version of numerics or of a plugin restarts only with that version "
                          "(with this one, run the scene from the start)"
                        : "";
    throw AppError(
        ExitCode::CHECKPOINT,
        checkpoint + ": the checkpoint was written for another scene or set-up: " + diff + version +
            " (a restart may change only time.end, output.*, --end-time, --out, "
            "--threads and --backend)");
}

}  // namespace num::app
