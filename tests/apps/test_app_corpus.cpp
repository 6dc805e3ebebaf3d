// The malformed-scene and fault corpus: hostile scenes and command lines, each answered within
// seconds by one line naming the key and the documented exit code (docs/scenes.md), never by
// a crash, a hang, a run without end or a silent broken result.
#include <gtest/gtest.h>

#include <functional>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <vector>

#include "app_runner.hpp"

using namespace apptest;
using nlohmann::json;

namespace {

constexpr int kUsage = 2, kJson = 4, kScene = 5, kExpression = 6;

struct Case {
    std::string name;
    int dim;
    std::function<std::string(json&)> edit;  ///< changes the tiny scene; returns extra arguments
    int code;
    std::vector<std::string> parts;  ///< what the message must name
};

/// A scene text with `depth` nested arrays.
std::string deeplyNested(int depth) {
    return "{\"dimension\": 2, \"name\": " + std::string(depth, '[') + std::string(depth, ']') +
           "}";
}

// The cases, in tables by topic (kCorpus below joins them in this order, the order the tests
// run in); the comments inside each table say what its cases refuse.
const std::vector<Case> kNonFinite = {
    // Expressions and numbers that give NaN or infinity.
    {"nan_temperature",
     2,
     [](json& j) {
         j["fluids"][0]["temperature"] = "sqrt(-1)";
         return "";
     },
     kExpression,
     {"fluids[0].temperature", "a finite temperature", "sqrt(-1)"}},
    {"infinite_pressure",
     2,
     [](json& j) {
         j["fluids"][0]["pressure"] = "1/0";
         return "";
     },
     kExpression,
     {"fluids[0].pressure", "a finite pressure", "1/0"}},
    // Initial pressures whose density the run would stop at before its first step ends.
    {"pressure_giving_a_negative_density",
     2,
     [](json& j) {
         j["fluids"][0]["pressure"] = -1e6;
         return "";
     },
     kScene,
     {"fluids[0].pressure", "half to twice the rest density 1000 kg/m^3", "found -1e+06"}},
    {"pressure_giving_four_times_the_rest_density",
     3,
     [](json& j) {
         j["fluids"][0]["pressure"] = "1e9 + x";
         return "";
     },
     kScene,
     {"fluids[0].pressure", "a pressure from", "1e9 + x"}},
    {"infinite_velocity",
     3,
     [](json& j) {
         j["fluids"][0]["velocity"] = {"1/(x-x)", 0, 0};
         return "";
     },
     kExpression,
     {"fluids[0].velocity[0]", "finite"}},
    {"nan_gravity",
     2,
     [](json& j) {
         j["gravity"] = {0, "ln(t-1)"};
         return "";
     },
     kExpression,
     {"gravity[1]", "finite", "ln(t-1)"}},
};

const std::vector<Case> kPositionDependent = {
    // Variables that parse but would be taken as 0 (issue 47): refused, naming them.
    {"gravity_depends_on_position",
     2,
     [](json& j) {
         j["gravity"] = {"0", "-9.81*(1+10*x)"};
         return "";
     },
     kExpression,
     {"gravity[1]", "an expression in t", "it uses 'x'", "uniform in space"}},
    {"gravity_depends_on_position_3d",
     3,
     [](json& j) {
         j["gravity"] = {0, "y", "-9.81"};
         return "";
     },
     kExpression,
     {"gravity[1]", "it uses 'y'"}},
    {"set_gravity_depends_on_position",
     3,
     [](json&) { return std::string("--set 'gravity=[0,0,\"-9.81*(1+z)\"]'"); },
     kExpression,
     {"gravity[2]", "it uses 'z'"}},
    {"initial_field_uses_z_in_2d",
     2,
     [](json& j) {
         j["fluids"][0]["temperature"] = "20 + 10*z";
         return "";
     },
     kExpression,
     {"fluids[0].temperature", "an expression in x, y and t", "it uses 'z'",
      "a 2D scene has the coordinates x and y only"}},
};

const std::vector<Case> kLimits = {
    // Derived settings within the limits of those they come from (issue 47).
    {"auto_sound_speed_beyond_the_limit",
     2,
     [](json& j) {
         j["materials"]["water"]["sound_speed"] = "auto";
         return "--set 'fluids.0.velocity=[1e6,0]'";
     },
     kScene,
     {"materials.water.sound_speed", "at most 1e+06 m/s", "\"auto\" = 10 x U = 1e+07 m/s",
      "of fluids[0].velocity", "at most 100000 m/s"}},
    {"auto_sound_speed_from_max_speed",
     3,
     [](json& j) {
         j["physics"]["max_speed"] = 2e5;
         return "";
     },
     kScene,
     {"physics.max_speed", "[0, 100000]", "found 200000"}},
    {"cfl_below_the_engine_limit",
     2,
     [](json&) { return std::string("--set time.cfl=1e-7"); },
     kScene,
     {"time.cfl", "expected a number in [1e-06, 1]", "found 1e-07"}},
    // A value just beyond a limit is printed in full, not rounded onto it.
    {"cfl_just_above_one",
     2,
     [](json&) { return std::string("--set time.cfl=1.0000001"); },
     kScene,
     {"time.cfl", "[1e-06, 1]", "found 1.0000001"}},
    {"coordinate_beyond_every_limit",
     2,
     [](json&) { return std::string("--set 'domain.max=[1e301,1]'"); },
     kScene,
     {"domain.max[0]", "a number in [-1e+300, 1e+300]", "found 1e+301"}},
    {"number_beyond_double",
     2,
     [](json&) { return std::string("RAW:1e400"); },
     kJson,
     {"scene.json", "1e400"}},
    {"set_number_beyond_double",
     2,
     [](json&) { return std::string("--set time.end=1e400"); },
     kUsage,
     {"--set time.end=1e400"}},
    {"end_time_nan",
     2,
     [](json&) { return std::string("--end-time nan"); },
     kUsage,
     {"--end-time", "finite"}},
    {"end_time_infinite",
     2,
     [](json&) { return std::string("--end-time inf"); },
     kUsage,
     {"--end-time", "finite"}},
    {"checkpoint_every_nan",
     2,
     [](json&) { return std::string("--checkpoint-every nan"); },
     kUsage,
     {"--checkpoint-every"}},
};

const std::vector<Case> kBelowAbsoluteZero = {
    // Temperatures below absolute zero.
    {"temperature_below_absolute_zero",
     2,
     [](json& j) {
         j["fluids"][0]["temperature"] = -300;
         return "";
     },
     kScene,
     {"fluids[0].temperature", "absolute zero", "-300"}},
    {"temperature_expression_below_absolute_zero",
     2,
     [](json& j) {
         j["fluids"][0]["temperature"] = "-200 - 1000*x";
         return "";
     },
     kScene,
     {"fluids[0].temperature", "absolute zero", "-200 - 1000*x"}},
};

const std::vector<Case> kNesting = {
    // Nesting without end.
    {"nested_100000_levels",
     2,
     [](json&) { return std::string("DEEP"); },
     kJson,
     {"nested deeper than 64 levels"}},
    {"set_key_200_levels",
     2,
     [](json&) {
         std::string key = "physics";
         for (int k = 0; k < 200; ++k) key += ".a";
         return "--set " + key + "=1";
     },
     kUsage,
     {"levels"}},
    // An index beyond any integer (std::stoul threw: an internal error), and the bracket
    // form of an index, which named an unknown top-level key "fluids[0]".
    {"set_index_beyond_integers",
     2,
     [](json&) { return std::string("--set fluids.99999999999999999999999.temperature=1"); },
     kUsage,
     {"fluids is an array of 1 values", "not an index into it"}},
    {"set_index_in_brackets",
     2,
     [](json&) { return std::string("--set fluids[0].temperature=30"); },
     kUsage,
     {"fluids[0]", "an index is a part of its own", "fluids.0.temperature"}},
};

const std::vector<Case> kBeyondTheMachine = {
    // Runs without end and set-ups beyond the machine.
    {"output_every_1e_minus_300",
     2,
     [](json& j) {
         j["output"]["every"] = 1e-300;
         return "";
     },
     kScene,
     {"output.every", "at most 100000 outputs"}},
    {"probes_every_zero",
     2,
     [](json& j) {
         j["output"]["probes_every"] = 0;
         return "";
     },
     kScene,
     {"output.probes_every", "a positive number [s]", "found 0"}},
    {"probes_every_text",
     3,
     [](json& j) {
         j["output"]["probes_every"] = "1 ms";
         return "";
     },
     kScene,
     {"output.probes_every", "a positive number", "\"1 ms\""}},
    {"plots_jpg",
     2,
     [](json& j) {
         j["output"]["plots"] = {"png", "jpg"};
         return "";
     },
     kScene,
     {"output.plots", "\"svg\"", "jpg"}},
    {"checkpoint_every_1e_minus_300",
     2,
     [](json&) { return std::string("--checkpoint-every 1e-300"); },
     kUsage,
     {"--checkpoint-every", "at most 100000 checkpoints"}},
    {"domain_2000_m_at_1_mm",
     2,
     [](json& j) {
         j["domain"]["max"] = {2000, 2000};
         j["particles"]["spacing"] = 0.001;
         return "";
     },
     kScene,
     {"particles.spacing", "lattice points"}},
    {"emitter_without_end",
     2,
     [](json& j) {
         j["emitters"] = json::array({{{"position", {0.15, 0.15}},
                                       {"direction", {0, -1}},
                                       {"speed", 1e4},
                                       {"radius", 0.05},
                                       {"material", "water"}}});
         j["time"]["end"] = 1e4;
         j["output"]["every"] = 1.0;
         return "";
     },
     kScene,
     {"particles.spacing", "particles (fluid", "emitted"}},
    {"emitter_radius_1e6_2d",
     2,
     [](json& j) {
         j["emitters"] = json::array({{{"position", {0.15, 0.15}},
                                       {"direction", {0, -1}},
                                       {"speed", 1},
                                       {"radius", 1e6},
                                       {"material", "water"}}});
         return "";
     },
     kScene,
     {"emitters[0].radius", "at most half the domain's largest extent"}},
    {"emitter_radius_1e6_3d",
     3,
     [](json& j) {
         j["emitters"][0]["radius"] = 1e6;
         return "";
     },
     kScene,
     {"emitters[0].radius", "at most half the domain's largest extent"}},
};

const std::vector<Case> kProbes = {
    // Probe names that would break probes.csv.
    {"probe_name_with_newline",
     2,
     [](json& j) {
         j["probes"][0]["name"] = "a\nb";
         return "";
     },
     kScene,
     {"probes[0].name", "letters, digits"}},
    {"probe_name_with_quote",
     2,
     [](json& j) {
         j["probes"][0]["name"] = "a\"b";
         return "";
     },
     kScene,
     {"probes[0].name"}},
    // A probe on a body: one of point and body, a body that exists, the force only.
    {"probe_with_point_and_body",
     2,
     [](json& j) {
         j["probes"][0]["body"] = 0;
         return "";
     },
     kScene,
     {"probes[0]", "one of a \"point\", a \"body\", a \"wall\" or a \"side\""}},
    {"probe_on_missing_body",
     2,
     [](json& j) {
         j["probes"] = json::array({{{"name", "drag"}, {"body", 1}}});
         return "";
     },
     kScene,
     {"probes[0].body", "one of the scene's 1 bodies"}},
    {"probe_on_missing_wall",
     2,
     [](json& j) {
         j["probes"] = json::array({{{"name", "drag"}, {"wall", 0}}});
         return "";
     },
     kScene,
     {"probes[0].wall", "one of the scene's 0 walls"}},
    {"probe_on_body_with_pressure",
     2,
     [](json& j) {
         j["probes"] = json::array({{{"name", "drag"}, {"body", 0}, {"fields", {"pressure"}}}});
         return "";
     },
     kScene,
     {"probes[0].fields[0]", "force"}},
};

/// The tables, one after the other.
std::vector<Case> joined(std::initializer_list<const std::vector<Case>*> tables) {
    std::vector<Case> all;
    for (const std::vector<Case>* t : tables) all.insert(all.end(), t->begin(), t->end());
    return all;
}

const std::vector<Case> kCorpus =
    joined({&kNonFinite, &kPositionDependent, &kLimits, &kBelowAbsoluteZero, &kNesting,
            &kBeyondTheMachine, &kProbes});

class Corpus : public ::testing::TestWithParam<Case> {};

}  // namespace

TEST_P(Corpus, OneLineAndTheDocumentedExitCode) {
    const Case& c = GetParam();
    json j = json::parse(readFile(scene(c.dim == 2 ? "tiny_2d.json" : "tiny_3d.json")));
    std::string extra = c.edit(j);
    std::string text = j.dump();
    if (extra == "RAW:1e400") {
        text.replace(text.find("\"end\":0.02"), 10, "\"end\":1e400");
        extra.clear();
    } else if (extra == "DEEP") {
        text = deeplyNested(100000);
        extra = "--print-scene";
    }
    const std::string dir = freshDir("corpus_" + c.name);
    writeFile(dir + "/scene.json", text);
    const Result r =
        run(c.dim == 2 ? FLUID_SIM : FLUID_SIM_3D, "scene.json --quiet --out out " + extra, dir);
    EXPECT_EQ(r.code, c.code) << r.output;
    for (const std::string& p : c.parts)
        EXPECT_TRUE(contains(r.output, p)) << "missing '" << p << "' in:\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(contains(r.output, "internal error")) << r.output;
}

INSTANTIATE_TEST_SUITE_P(Apps, Corpus, ::testing::ValuesIn(kCorpus),
                         [](const auto& info) { return info.param.name; });
