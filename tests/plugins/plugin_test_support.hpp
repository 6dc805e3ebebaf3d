// Helpers of the plugin tests: scenes of examples/plugins/scenes with their plugins rewritten to
// the libraries of this build, and the CSV outputs of a run read back.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../apps/app_runner.hpp"

namespace plugintest {

using nlohmann::json;

inline json exampleScene(const std::string& name) {
    std::ifstream in(std::string(PLUGIN_SCENES) + "/" + name);
    return json::parse(in, nullptr, true, /*ignore_comments=*/true);
}

/// Writes `scene` to dir/scene.json and runs `app` on it with `args`; output goes to dir/out.
inline apptest::Result runScene(const std::string& app, const json& scene, const std::string& dir,
                                const std::string& args = "") {
    apptest::writeFile(dir + "/scene.json", scene.dump(2));
    return apptest::run(app, "scene.json --out out --threads 1 -q " + args, dir);
}

using apptest::readCsv;
using apptest::Table;

/// The CSV output number k of the run in dir/out ("particles_0004.csv").
inline Table output(const std::string& dir, int k) {
    char name[32];
    std::snprintf(name, sizeof name, "/out/particles_%04d.csv", k);
    return readCsv(dir + name);
}

inline double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0 : s / double(v.size());
}

/// The error lines of an app's output ("fluid_sim: error: ..."); a clear error is exactly one.
inline std::vector<std::string> errorLines(const std::string& output) {
    std::vector<std::string> lines;
    std::stringstream s(output);
    for (std::string line; std::getline(s, line);)
        if (line.find("error") != std::string::npos) lines.push_back(line);
    return lines;
}

}  // namespace plugintest
