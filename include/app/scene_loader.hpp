// From a scene file to a checked Scene<Dim>: read the text, parse the JSON (errors with line and
// column), apply command-line overrides (--set KEY=VALUE by dotted path), read every key with its
// type and range, and check the geometry.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

#include "app/scene.hpp"

namespace num::app {

/// The largest scene file read [bytes].
inline constexpr std::size_t kMaxSceneBytes = std::size_t(16) << 20;

class SceneDocument {
  public:
    /// Reads and parses a scene file (exit codes SCENE_FILE and JSON_SYNTAX).
    static SceneDocument fromFile(const std::string& path);
    /// Parses scene text; `file` names it in messages.
    static SceneDocument fromText(const std::string& text, const std::string& file);

    /// Applies "a.b.c=VALUE": VALUE is JSON (a number, true, [1, 2], "text") or else a plain
    /// string. Array elements are addressed by index ("fluids.0.temperature=30").
    void set(const std::string& assignment);

    /// The "dimension" key (2 or 3).
    int dimension() const;
    const std::string& file() const { return file_; }
    const nlohmann::json& json() const { return json_; }
    /// The document as text.
    std::string dump() const { return json_.dump(1); }
    /// The document as a checkpoint stores it: every relative file a shape reads (`mesh`,
    /// `section`) and every relative plugin library made absolute, resolved from the scene
    /// file's directory, so that a restart from the checkpoint alone finds them wherever the
    /// checkpoint is.
    std::string dumpWithAbsolutePaths() const;

  private:
    std::string file_;
    nlohmann::json json_;
};

/// Reads and checks every key of the document.
template <int Dim>
Scene<Dim> readScene(const SceneDocument& doc);

/// Checks geometry: fluid blocks and bodies inside the domain, no fluid overlapping a body,
/// periodic axes on both sides, at least one particle. Called by readScene.
template <int Dim>
void checkSceneGeometry(const Scene<Dim>& scene);

}  // namespace num::app
