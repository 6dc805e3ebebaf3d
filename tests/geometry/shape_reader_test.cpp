// Shapes read from scene JSON: each kind, the transformations, nested combinations, and the
// one-line errors (file, key path, what was expected).
#include <gtest/gtest.h>

#include <string>

#include "app/errors.hpp"
#include "scene/shape_reader.hpp"

namespace {

using nlohmann::json;
using num::app::AppError;
using num::app::ExitCode;
using num::app::readSolid;
using num::app::detail::At;
using P2 = num::geometry::Point<2>;
using P3 = num::geometry::Point<3>;

const std::string file = "scene.json";

/// The shape of `text`, its files relative to scenes/meshes/.
template <int Dim>
num::geometry::SolidPtr<Dim> read(const std::string& text) {
    const json j = json::parse(text);
    return readSolid<Dim>(At{j, file, "walls[0]"}, GEOMETRY_MESHES);
}

/// The message of the AppError that reading `text` throws (exit code SCENE).
template <int Dim>
std::string error(const std::string& text) {
    try {
        read<Dim>(text);
    } catch (const AppError& e) {
        EXPECT_EQ(e.code(), ExitCode::SCENE);
        return e.what();
    }
    ADD_FAILURE() << "no error for " << text;
    return "";
}

TEST(ShapeReader, Primitives3D) {
    const auto cyl = read<3>(R"({"shape": "cylinder", "base": [0, 0, 0], "top": [0, 0, 2],
                                 "radius": 1})");
    EXPECT_DOUBLE_EQ(cyl->signedDistance(P3{{0, 0, 1}}), -1);
    const auto cone = read<3>(R"({"shape": "cone", "base": [0, 0, 0], "top": [0, 0, 1],
                                  "base_radius": 1, "top_radius": 0})");
    EXPECT_NEAR(cone->signedDistance(P3{{0, 0, 0.1}}), -0.1, 1e-15);
    const auto plane = read<3>(R"({"shape": "plane", "point": [0, 0, 1], "normal": [0, 0, 1]})");
    EXPECT_DOUBLE_EQ(plane->signedDistance(P3{{0, 0, 3}}), 2);
    const auto ball = read<3>(R"({"shape": "sphere", "center": [1, 1, 1], "radius": 0.5})");
    EXPECT_DOUBLE_EQ(ball->signedDistance(P3{{1, 1, 1}}), -0.5);
}

TEST(ShapeReader, RotatedBoxAndTransforms) {
    // A box centred on the origin, turned 90 degrees about z, moved to (1, 0, 0).
    const auto box = read<3>(R"({"shape": "box", "min": [-2, -1, -1], "max": [2, 1, 1],
                                 "rotate": [0, 0, 90], "translate": [1, 0, 0]})");
    EXPECT_NEAR(box->signedDistance(P3{{1, 1.5, 0}}), -0.5, 1e-12);
    EXPECT_NEAR(box->signedDistance(P3{{2.5, 0, 0}}), 0.5, 1e-12);
    const auto tri = read<2>(R"({"shape": "polygon", "points": [[0, 0], [1, 0], [0, 1]],
                                 "scale": 2, "rotate": 90})");
    EXPECT_NEAR(tri->signedDistance(P2{{-0.5, 0.2}}), -0.2, 1e-12);
}

TEST(ShapeReader, NestedCombinations) {
    const auto cup = read<3>(R"({"shape": "difference", "shapes": [
        {"shape": "cylinder", "base": [0, 0, 0], "top": [0, 0, 1], "radius": 0.5},
        {"shape": "union", "shapes": [
            {"shape": "cylinder", "base": [0, 0, 0.1], "top": [0, 0, 2], "radius": 0.4},
            {"shape": "sphere", "center": [0, 0, 5], "radius": 1}]}]})");
    EXPECT_LT(cup->signedDistance(P3{{0.45, 0, 0.5}}), 0);
    EXPECT_NEAR(cup->signedDistance(P3{{0, 0, 0.5}}), 0.4, 1e-15);
    const auto band = read<2>(R"({"shape": "intersection", "shapes": [
        {"shape": "polyline", "points": [[0, 0], [2, 0]], "thickness": 0.2},
        {"shape": "circle", "center": [0, 0], "radius": 1}]})");
    EXPECT_LT(band->signedDistance(P2{{0.5, 0}}), 0);
    EXPECT_GT(band->signedDistance(P2{{1.5, 0}}), 0);
}

TEST(ShapeReader, MeshAndSection) {
    const auto sphere = read<3>(R"({"shape": "mesh", "file": "sphere.stl", "scale": 2,
                                    "translate": [1, 0, 0]})");
    EXPECT_NEAR(sphere->signedDistance(P3{{1, 0, 0}}), -0.2, 1e-3);  // the facets are flat
    EXPECT_NEAR(sphere->bounds().min[0], 0.8, 1e-6);
    const auto circle = read<2>(R"({"shape": "section", "file": "sphere.stl", "axis": "y",
                                    "at": 0.06, "translate": [1, 1]})");
    EXPECT_NEAR(circle->signedDistance(P2{{1, 1}}), -0.08, 1e-3);  // sqrt(0.1^2 - 0.06^2)
    EXPECT_NE(error<3>(R"({"shape": "mesh", "file": "missing.stl"})")
                  .find("walls[0]: " GEOMETRY_MESHES "/missing.stl: not a readable mesh"),
              std::string::npos);
    EXPECT_EQ(error<2>(R"({"shape": "section", "file": "sphere.stl", "axis": "z", "at": 0.5})"),
              "scene.json: walls[0].at: expected a plane z = at that cuts the mesh, found 0.5");
}

TEST(ShapeReader, Errors) {
    EXPECT_EQ(
        error<2>(R"({"shape": "cylinder", "base": [0, 0], "top": [0, 1], "radius": 1})"),
        "scene.json: walls[0].shape: expected a shape of a 2D scene: box, circle, "
        "polygon, polyline, section, plane, union, intersection or difference, found the string "
        "\"cylinder\" (\"cylinder\" is a 3D shape)");
    EXPECT_NE(error<3>(R"({"shape": "cylindre"})").find("did you mean \"cylinder\"?"),
              std::string::npos);
    EXPECT_EQ(error<2>(R"({"shape": "polygon", "points": [[0, 0], [1, 1], [1, 0], [0, 1]]})"),
              "scene.json: walls[0]: the polygon crosses itself: edge 0 (points 0-1) and edge 2 "
              "(points 2-3) meet (list the points in order around the outline)");
    EXPECT_NE(error<3>(R"({"shape": "sphere", "center": [0, 0, 0], "radius": 1, "radios": 2})")
                  .find("radios"),
              std::string::npos);
    EXPECT_NE(error<3>(R"({"shape": "union", "shapes": [{"shape": "sphere", "center": [0, 0, 0],
                           "radius": 1}, {"shape": "box", "min": [0, 0, 0], "max": [1, 1]}]})")
                  .find("walls[0].shapes[1].max"),
              std::string::npos);
    EXPECT_NE(error<3>(R"({"shape": "box", "min": [0, 0, 0], "max": [1, 1, 1], "scale": 0})")
                  .find("walls[0].scale"),
              std::string::npos);
}

}  // namespace
