// Bad geometry through the apps: a shape that misses the domain, a fluid volume without
// particles, a mesh that is not closed, a file that is not a mesh, fluid overlapping a wall, a
// shape in other units (a warning), and the CUDA back end refusing walls and general shapes.
// Each is one line with the key path and exit code 5 (docs/scenes.md), never a crash.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "app_runner.hpp"

using namespace apptest;
using nlohmann::json;

namespace {

constexpr int kScene = 5;

json tiny2d() {
    json j = json::parse(readFile(scene("tiny_2d.json")));
    j.erase("bodies");
    return j;
}

json tiny3d() {
    json j = json::parse(readFile(scene("tiny_3d.json")));
    j.erase("emitters");
    return j;
}

/// Runs the app of the scene's dimension on it, written to <dir>/scene.json with `files`
/// beside it.
Result runScene(const std::string& name, const json& j, const std::string& extra = "--quiet",
                const std::map<std::string, std::string>& files = {}) {
    const std::string dir = freshDir("geometry_" + name);
    writeFile(dir + "/scene.json", j.dump());
    for (const auto& [file, text] : files) writeFile(dir + "/" + file, text);
    const char* app = j["dimension"] == 2 ? FLUID_SIM : FLUID_SIM_3D;
    return run(app, "scene.json --out out --end-time 0.002 " + extra, dir);
}

void expectMessage(const Result& r, std::initializer_list<const char*> parts) {
    EXPECT_EQ(r.code, kScene) << r.output;
    for (const char* p : parts)
        EXPECT_TRUE(contains(r.output, p)) << "missing '" << p << "' in:\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

json polygon(std::initializer_list<std::array<double, 2>> points) {
    json p = {{"shape", "polygon"}, {"points", json::array()}};
    for (const auto& q : points) p["points"].push_back({q[0], q[1]});
    return p;
}

/// A tetrahedron as ASCII STL; without its last face it is open (three open edges).
std::string tetrahedron(bool closed) {
    const char* faces[] = {"0 0 0\n vertex 0 0.05 0\n vertex 0.05 0 0",
                           "0 0 0\n vertex 0.05 0 0\n vertex 0 0 0.05",
                           "0 0 0\n vertex 0 0 0.05\n vertex 0 0.05 0",
                           "0.05 0 0\n vertex 0 0.05 0\n vertex 0 0 0.05"};
    std::string stl = "solid t\n";
    for (int f = 0; f < (closed ? 4 : 3); ++f)
        stl += std::string("facet normal 0 0 0\n outer loop\n vertex ") + faces[f] +
               "\n endloop\nendfacet\n";
    return stl + "endsolid t\n";
}

}  // namespace

TEST(BadGeometry, FluidShapeOutsideTheDomain) {
    json j = tiny2d();
    json f = polygon({{1, 1}, {1.1, 1}, {1, 1.1}});
    f["material"] = "water";
    j["fluids"] = json::array({f});
    expectMessage(runScene("fluid_outside", j), {"fluids[0]", "inside the domain", "spanning"});
}

TEST(BadGeometry, WallOutsideTheDomain) {
    json j = tiny2d();
    j["walls"] = json::array({polygon({{-1, -1}, {-0.5, -1}, {-1, -0.5}})});
    expectMessage(runScene("wall_outside", j), {"walls[0]", "a wall inside the domain"});
}

TEST(BadGeometry, FluidVolumeWithoutParticles) {
    json j = tiny2d();
    json f = polygon({{0.101, 0.101}, {0.105, 0.101}, {0.101, 0.105}});  // between lattice points
    f["material"] = "water";
    j["fluids"].push_back(f);
    expectMessage(runScene("empty_volume", j), {"fluids[1]", "holding particles", "found none"});
}

TEST(BadGeometry, FluidOverlappingAWall) {
    json j = tiny2d();
    j["walls"] = json::array({polygon({{0.02, 0.02}, {0.08, 0.02}, {0.05, 0.08}})});
    expectMessage(runScene("overlap_wall", j),
                  {"fluids[0]", "does not overlap a wall", "walls[0]"});
}

TEST(BadGeometry, MeshNotClosed) {
    json j = tiny3d();
    j["bodies"] =
        json::array({{{"shape", "mesh"}, {"file", "open.stl"}, {"translate", {0.1, 0.04, 0.04}}}});
    const Result r = runScene("open_mesh", j, "--quiet", {{"open.stl", tetrahedron(false)}});
    expectMessage(r, {"bodies[0]", "not closed", "3 open edges"});
}

TEST(BadGeometry, MeshMovedFarOutIsNamedOutsideTheDomain) {
    // Translated by 1e300 the mesh's distances overflow: the body is named, not the fluid
    // block it was thought to cover.
    const std::string cube =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
        "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n"
        "f 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
    json j = tiny3d();
    j["domain"] = {{"min", {0, 0, 0}}, {"max", {2, 2, 2}}};
    j["particles"]["spacing"] = 0.1;
    j["fluids"][0]["max"] = {2, 2, 0.5};
    j["probes"] = json::array();
    j["boundaries"]["z_max"] = {{"type", "wall"}};
    j["bodies"] =
        json::array({{{"shape", "mesh"}, {"file", "cube.obj"}, {"translate", {1e300, 0, 0}}}});
    const Result r = runScene("far_mesh", j, "--quiet", {{"cube.obj", cube}});
    expectMessage(r, {"bodies[0]", "inside the domain", "1e+300"});
}

TEST(BadGeometry, FileNotAMesh) {
    json j = tiny3d();
    j["walls"] = json::array({{{"shape", "mesh"}, {"file", "notes.stl"}}});
    const Result r = runScene("not_mesh", j, "--quiet", {{"notes.stl", "not a mesh at all\n"}});
    expectMessage(r, {"walls[0]", "notes.stl"});
}

TEST(BadGeometry, ShapeInOtherUnitsIsAWarning) {
    json j = tiny2d();
    json f = polygon({{-50, -50}, {150, -50}, {150, 150}, {-50, 150}});  // in cm, say
    f["material"] = "water";
    j["fluids"] = json::array({f});
    j["boundaries"]["y_max"] = {{"type", "wall"}};
    const Result r = runScene("units", j, "--set output.images=false");
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "fluids[0]")) << r.output;
    EXPECT_TRUE(contains(r.output, "times larger than the domain")) << r.output;
}

TEST(BadGeometry, CudaBackendRefusesMeshShapesByTheirKey) {
    json j = tiny3d();
    j["bodies"] = json::array({{{"shape", "mesh"},
                                {"file", "t.stl"},
                                {"scale", 1.6},
                                {"translate", {0.08, 0.02, 0.04}}}});
    expectMessage(
        runScene("cuda_mesh", j, "--quiet --backend cuda", {{"t.stl", tetrahedron(true)}}),
        {"--backend cuda", "bodies[0].shape", "a mesh shape", "CPU back end only"});
}

TEST(BadGeometry, EmitterNozzleInsideAWall) {
    // The nozzle's only point (radius = half a spacing) lies inside the wall.
    json j = tiny2d();
    j["walls"] = json::array({polygon({{0.145, 0.13}, {0.2, 0.13}, {0.2, 0.19}, {0.145, 0.19}})});
    j["emitters"] = json::array({{{"position", {0.17, 0.16}},
                                  {"direction", {0, -1}},
                                  {"speed", 1},
                                  {"radius", 0.01},
                                  {"material", "water"}}});
    expectMessage(runScene("nozzle_in_wall", j),
                  {"emitters[0].position", "in or next to walls[0]", "move the nozzle"});
}

namespace {

/// A box shape of the scene's dimension.
json box(std::vector<double> min, std::vector<double> max) {
    return {{"shape", "box"}, {"min", min}, {"max", max}};
}

/// A wall or body that holds no point of the particle lattice is refused naming it and the
/// spacing, instead of running as if it were not there.
void expectNoParticles(const std::string& name, json j, const char* key, const json& shape) {
    const std::string list = std::string(key).substr(0, std::string(key).find('['));
    j[list] = json::array({shape});
    expectMessage(runScene(name, j), {key, "holding boundary particles", "spacing 0.02 m",
                                      "found none", "refine particles.spacing"});
}

}  // namespace

TEST(BadGeometry, WallOrBodyWithoutParticles) {
    // The lattice of tiny_2d: cell centres 0.01, 0.03, ..., 0.19.
    const json disjoint = {
        {"shape", "intersection"},
        {"shapes", {box({0.12, 0.02}, {0.14, 0.08}), box({0.16, 0.02}, {0.18, 0.08})}}};
    expectNoParticles("empty_intersection", tiny2d(), "walls[0]", disjoint);
    const json covered = {{"shape", "difference"},
                          {"shapes", {box({0.12, 0.02}, {0.16, 0.06}), box({0.1, 0}, {0.2, 0.1})}}};
    expectNoParticles("empty_difference", tiny2d(), "bodies[0]", covered);
    const json thinLine = {
        {"shape", "polyline"}, {"points", {{0.12, 0.1}, {0.18, 0.1}}}, {"thickness", 0.005}};
    expectNoParticles("thin_polyline", tiny2d(), "walls[0]", thinLine);
    expectNoParticles("thin_box", tiny2d(), "walls[0]", box({0.12, 0.095}, {0.18, 0.105}));
    expectNoParticles("tiny_circle", tiny2d(), "bodies[0]",
                      {{"shape", "circle"}, {"center", {0.15, 0.1}}, {"radius", 1e-4}});
    json j3 = tiny3d();
    j3["particles"]["spacing"] = 0.02;
    expectNoParticles("tiny_cylinder", j3, "bodies[0]",
                      {{"shape", "cylinder"},
                       {"base", {0.12, 0.06, 0.02}},
                       {"top", {0.12, 0.06, 0.1}},
                       {"radius", 1e-4}});
}
