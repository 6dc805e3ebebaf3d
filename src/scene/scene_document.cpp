// Scene files as JSON documents: reading, syntax errors with line and column, overrides.
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/scene_loader.hpp"
#include "scene/json_check.hpp"

namespace num::app {

namespace {

/// Nesting bound of scene JSON: deeper documents are refused before they are built (printing or
/// walking them recursively would overflow the stack).
constexpr int kMaxDepth = 64;
struct TooDeep {};

nlohmann::json parseBounded(const std::string& text) {
    return nlohmann::json::parse(
        text,
        [](int depth, nlohmann::json::parse_event_t event, nlohmann::json&) {
            if (depth > kMaxDepth && (event == nlohmann::json::parse_event_t::object_start ||
                                      event == nlohmann::json::parse_event_t::array_start))
                throw TooDeep{};
            return true;
        },
        true, /*ignore_comments=*/true);
}

/// A JSON error other than a syntax error: in practice a number out of the range of a double.
std::string jsonProblem(const nlohmann::json::exception& e) {
    std::string what = e.what();
    if (const auto p = what.find("] "); p != std::string::npos) what = what.substr(p + 2);
    return what + " (numbers must lie within about 1e308 in magnitude)";
}

}  // namespace

SceneDocument SceneDocument::fromFile(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw AppError(ExitCode::SCENE_FILE,
                       path + ": cannot read the scene file: it is a directory, not a JSON file");
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const std::string why = std::strerror(errno);
        throw AppError(ExitCode::SCENE_FILE, path + ": cannot read the scene file: " + why +
                                                 " (check the path; built-in scenes run when no "
                                                 "file is given)");
    }
    // At most kMaxSceneBytes are read: /dev/zero, or a large file given by mistake, is refused
    // before it fills the memory.
    std::string text(kMaxSceneBytes + 1, '\0');
    in.read(text.data(), std::streamsize(text.size()));
    text.resize(std::size_t(in.gcount()));
    if (in.bad()) throw AppError(ExitCode::SCENE_FILE, path + ": read error");
    if (text.size() > kMaxSceneBytes)
        throw AppError(ExitCode::SCENE_FILE,
                       path + ": cannot read the scene file: it is larger than " +
                           std::to_string(kMaxSceneBytes >> 20) +
                           " MiB, which no scene is (a scene file is a few kilobytes of JSON): "
                           "check the path");
    return fromText(text, path);
}

SceneDocument SceneDocument::fromText(const std::string& text, const std::string& file) {
    SceneDocument doc;
    doc.file_ = file;
    try {
        doc.json_ = parseBounded(text);
    } catch (const nlohmann::json::parse_error& e) {
        // Line and column of the byte where parsing stopped (e.byte is 1-based).
        std::size_t line = 1, column = 1;
        for (std::size_t k = 0; k + 1 < e.byte && k < text.size(); ++k) {
            if (text[k] == '\n')
                ++line, column = 1;
            else
                ++column;
        }
        std::string what = e.what();
        if (const auto p = what.find("syntax error"); p != std::string::npos) what = what.substr(p);
        throw AppError(ExitCode::JSON_SYNTAX, file + ":" + std::to_string(line) + ":" +
                                                  std::to_string(column) +
                                                  ": malformed JSON: " + what);
    } catch (const nlohmann::json::exception& e) {
        throw AppError(ExitCode::JSON_SYNTAX, file + ": " + jsonProblem(e));
    } catch (const TooDeep&) {
        throw AppError(ExitCode::JSON_SYNTAX, file + ": JSON nested deeper than " +
                                                  std::to_string(kMaxDepth) +
                                                  " levels (a scene needs about 5)");
    }
    if (!doc.json_.is_object())
        throw sceneError(file, "", "a JSON object { ... }", detail::describe(doc.json_));
    return doc;
}

namespace {

/// Makes `value` (a path relative to `dir`) absolute, where it is a relative path.
void makeAbsolute(nlohmann::json& value, const std::filesystem::path& dir) {
    if (!value.is_string()) return;
    const std::filesystem::path p(value.get<std::string>());
    if (p.empty() || p.is_absolute()) return;
    std::error_code ec;
    const std::filesystem::path a = std::filesystem::absolute(dir / p, ec);
    if (!ec) value = a.lexically_normal().string();
}

/// Every shape's file (a `mesh` or `section`) under v made absolute.
void absoluteShapeFiles(nlohmann::json& v, const std::filesystem::path& dir) {
    if (v.is_object()) {
        const auto shape = v.find("shape"), file = v.find("file");
        if (shape != v.end() && file != v.end() && (*shape == "mesh" || *shape == "section"))
            makeAbsolute(*file, dir);
        for (auto& [key, value] : v.items()) absoluteShapeFiles(value, dir);
    } else if (v.is_array()) {
        for (auto& e : v) absoluteShapeFiles(e, dir);
    }
}

}  // namespace

std::string SceneDocument::dumpWithAbsolutePaths() const {
    nlohmann::json j = json_;
    const std::filesystem::path dir = std::filesystem::path(file_).parent_path();
    absoluteShapeFiles(j, dir);
    if (const auto plugins = j.find("plugins"); plugins != j.end() && plugins->is_array())
        for (auto& plugin : *plugins)
            if (plugin.is_object() && plugin.contains("library"))
                makeAbsolute(plugin["library"], dir);
    return j.dump(1);
}

void SceneDocument::set(const std::string& assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw AppError(ExitCode::USAGE, "--set " + assignment +
                                            ": expected KEY=VALUE with a dotted key, e.g. "
                                            "--set particles.spacing=0.01");
    const std::string key = assignment.substr(0, eq), text = assignment.substr(eq + 1);
    nlohmann::json value;
    try {
        value = parseBounded(text);
    } catch (const nlohmann::json::parse_error&) {
        value = text;  // a bare word or an expression: a string
    } catch (const nlohmann::json::exception& e) {
        throw AppError(ExitCode::USAGE, "--set " + assignment + ": " + jsonProblem(e));
    } catch (const TooDeep&) {
        throw AppError(ExitCode::USAGE, "--set " + assignment + ": a value nested deeper than " +
                                            std::to_string(kMaxDepth) + " levels");
    }
    if (std::count(key.begin(), key.end(), '.') >= kMaxDepth)
        throw AppError(ExitCode::USAGE, "--set " + assignment + ": a key of more than " +
                                            std::to_string(kMaxDepth) + " levels");
    nlohmann::json* node = &json_;
    std::string path;
    std::stringstream parts(key);
    std::string part;
    while (std::getline(parts, part, '.')) {
        if (part.empty())
            throw AppError(ExitCode::USAGE, "--set " + assignment + ": empty key in '" + key + "'");
        if (part.find('[') != std::string::npos)
            throw AppError(ExitCode::USAGE,
                           "--set " + assignment + ": '" + part +
                               "': an index is a part of its own, after a dot (e.g. --set "
                               "fluids.0.temperature=30 for fluids[0].temperature)");
        if (node->is_array()) {
            // At most 9 digits: std::stoul would throw beyond its range; no array is that long.
            const bool digits =
                part.size() <= 9 && part.find_first_not_of("0123456789") == std::string::npos;
            const std::size_t i = digits ? std::stoul(part) : node->size();
            if (i >= node->size())
                throw AppError(ExitCode::USAGE,
                               "--set " + assignment + ": " + (path.empty() ? "" : path) +
                                   " is an array of " + std::to_string(node->size()) +
                                   " values; '" + part + "' is not an index into it");
            node = &(*node)[i];
        } else {
            // A parent the scene left out ("physics" for physics.shifting) starts empty; a
            // misspelt one is then reported by the reader as an unknown key.
            if (node->is_null()) *node = nlohmann::json::object();
            if (!node->is_object())
                throw AppError(ExitCode::USAGE, "--set " + assignment + ": " + path +
                                                    " is not an object, cannot set '" + part +
                                                    "' in it");
            node = &(*node)[part];
        }
        path += (path.empty() ? "" : ".") + part;
    }
    *node = value;
}

int SceneDocument::dimension() const {
    const detail::At root{json_, file_, ""};
    return int(root.required("dimension").integer(2, 3));
}

}  // namespace num::app
