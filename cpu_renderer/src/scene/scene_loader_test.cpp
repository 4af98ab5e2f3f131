#include "safegi/cpu_renderer/scene_loader.hpp"

#include "safegi/cpu_renderer/image.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <random>
#include <unistd.h>

namespace safegi::render {
namespace {


std::string with_camera(const std::string& rest) {
  return std::string("{\"camera\": {\"position\": {\"value\": [0, 0, 5], \"unit\": \"m\"}, \"look_at\": {\"value\": [0, 0, "
                     "0], \"unit\": \"m\"}, \"up\": [0, 1, 0], \"fov\": \"40 deg\"}") +
         (rest.empty() ? "" : ", " + rest) + "}";
}

std::string load_error(const std::string& json) {
  try {
    parse_scene(json, "test.json", ".");
  } catch (const SceneError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no error for " << json;
  return "";
}

TEST(SceneLoader, AFiltersModeIsSampleOrSplat) {
  EXPECT_EQ(load_error(with_camera(R"("render": {"filter": {"type": "gaussian", "mode": "scatter"}})")),
            "test.json: render.filter.mode: expected \"sample\" or \"splat\", got \"scatter\"");
}

TEST(SceneLoader, WrongDimensionNamesPathExpectedAndFound) {
  EXPECT_EQ(load_error(with_camera(R"("lights": [{"type": "point", "position": {"value": [0, 1, 0], "unit": "m"}, "power": "3 m"}])")),
            "test.json: lights[0].power: expected power (e.g. W), got \"3 m\" (length)");
  EXPECT_EQ(load_error(with_camera(R"("shapes": [{"type": "sphere", "center": {"value": [0, 0, 0], "unit": "m"}, "radius": "2 W"}])")),
            "test.json: shapes[0].radius: expected length (e.g. m), got \"2 W\" (power)");
  EXPECT_EQ(load_error(with_camera(R"("shapes": [{"type": "sphere", "center": {"value": [0, 0, 0], "unit": "m"}, "radius": 2}])")),
            "test.json: shapes[0].radius: expected length (e.g. m), got 2 (a number without unit)");
  EXPECT_EQ(load_error(with_camera(R"("shapes": [{"type": "quad", "origin": {"value": [0, 0, 0], "unit": "s"}, "edge_u": "1 m", "edge_v": "1 m"}])")),
            "test.json: shapes[0].origin: expected length (e.g. m), got {\"unit\":\"s\",\"value\":[0,0,0]} (time)");
  EXPECT_EQ(load_error(with_camera(
                R"("shapes": [{"type": "sphere", "center": {"value": [0, 0, 0], "unit": "m"}, "radius": "1 m", "emission": "5 W/m2"}])")),
            "test.json: shapes[0].emission: expected radiance (e.g. W/(m2 sr)), got \"5 W/m2\" (irradiance)");
  EXPECT_EQ(load_error(R"({"camera": {"position": {"value": [0, 0, 5], "unit": "m"}, "look_at": {"value": [0, 0, 0], "unit": "m"}, "up": [0, 1, 0], "fov": "40 sr"}})"),
            "test.json: camera.fov: expected angle (e.g. deg), got \"40 sr\" (solid angle)");
}

TEST(SceneLoader, MalformedInput) {
  EXPECT_EQ(load_error("{\n  \"camera\": [1, 2,\n}"), "test.json:3:1: invalid JSON: syntax error while parsing value - unexpected '}'; expected '[', '{', or a literal");
  EXPECT_EQ(load_error(with_camera(R"("render": {"spp": 1e999})")),
            "test.json: invalid JSON: number overflow parsing '1e999'");
  EXPECT_EQ(load_error("[]"), "test.json: expected an object, got []");
  EXPECT_EQ(load_error("{}"), "test.json: missing field 'camera'");
  EXPECT_EQ(load_error(with_camera(R"("colour": 1)")),
            "test.json: colour: unknown field (expected one of: format, description, render, camera, textures, materials, shapes, lights)");
  EXPECT_EQ(load_error(with_camera(R"("lights": [{"type": "point", "position": {"value": [0, 1, 0], "unit": "m"}, "power": "3 parsec"}])")),
            "test.json: lights[0].power: cannot read \"3 parsec\": unknown unit 'parsec'");
  EXPECT_EQ(load_error(with_camera(R"("shapes": [{"type": "sphere", "center": {"value": [0, 0, 0], "unit": "m"}, "radius": "1 m", "material": "gold"}])")),
            "test.json: shapes[0].material: no material named \"gold\"");
  EXPECT_EQ(load_error(with_camera(R"("shapes": [{"type": "mesh", "file": "missing.obj", "unit": "m"}])")),
            "test.json: shapes[0].file: cannot read mesh 'missing.obj'");
  EXPECT_EQ(load_error(with_camera(R"("materials": {"shiny": {"type": "phong", "diffuse": 0.6, "specular": 0.6, "exponent": 10}})")),
            "test.json: materials.shiny: diffuse + specular must not exceed 1 in any channel (energy conservation)");
  EXPECT_EQ(load_error(with_camera(R"("materials": {"m": {"type": "lambert", "reflectance": [0.5, 1.5, 0.5]}})")),
            "test.json: materials.m.reflectance: reflectance must lie in [0, 1], got [0.5,1.5,0.5]");
  EXPECT_EQ(load_error(with_camera(R"("render": {"resolution": [0, 10]})")),
            "test.json: render.resolution[0]: expected an integer in [1, 65536], got 0");
  EXPECT_EQ(load_error(with_camera(R"("shapes": [{"type": "triangles", "positions": {"value": [[0,0,0],[1,0,0],[0,1,0]], "unit": "m"}, "indices": [0, 1, 3]}])")),
            "test.json: shapes[0].indices[2]: expected an integer in [0, 2], got 3");
  EXPECT_EQ(load_error("\xff\xfe"), "test.json:1:1: invalid JSON: syntax error while parsing value - invalid literal; last read: '\\xFF'");
}

// The camera's fields follow its projection: a field another projection owns is
// an error, not silently ignored.
std::string camera(const std::string& fields) {
  return R"({"camera": {"position": {"value": [0, 0, 5], "unit": "m"}, "look_at": {"value": [0, 0, 0], "unit": "m"}, "up": [0, 1, 0], )" +
         fields + "}}";
}

TEST(SceneLoader, CameraProjections) {
  Scene ortho = parse_scene(camera(R"("projection": "orthographic", "view_size": "20 cm")"), "test.json", ".");
  EXPECT_EQ(ortho.camera.projection, CameraProjection::orthographic);
  EXPECT_NEAR(sg::raw(ortho.camera.view_size), 0.2f, 1e-7);
  Scene env = parse_scene(camera(R"("projection": "environment")"), "test.json", ".");
  EXPECT_EQ(env.camera.projection, CameraProjection::environment);
  EXPECT_EQ(load_error(camera(R"("projection": "fisheye", "fov": "40 deg")")),
            "test.json: camera.projection: expected \"perspective\", \"orthographic\" or \"environment\", got \"fisheye\"");
  EXPECT_EQ(load_error(camera(R"("projection": "orthographic")")), "test.json: camera: missing field 'view_size'");
  EXPECT_EQ(load_error(camera(R"("projection": "orthographic", "view_size": "0 m")")),
            "test.json: camera.view_size: must be positive");
  EXPECT_EQ(load_error(camera(R"("projection": "orthographic", "view_size": "1 m", "fov": "40 deg")")),
            "test.json: camera.fov: only a perspective camera has a field of view");
  EXPECT_EQ(load_error(camera(R"("fov": "40 deg", "view_size": "1 m")")),
            "test.json: camera.view_size: only an orthographic camera has a view size");
  EXPECT_EQ(load_error(camera(R"("projection": "environment", "lens_radius": "1 cm")")),
            "test.json: camera.lens_radius: an environment camera has no lens");
  EXPECT_EQ(load_error(camera(R"("lens_radius": "0 m")")), "test.json: camera: missing field 'fov'");
}

// A point light's map: its layout's fields, rotations only, and "power" shared
// out over the directions the map lights (a 90° square window: 1/6 of the sphere).
TEST(SceneLoader, PointLightMaps) {
  auto light = [](const std::string& map, const char* output = R"("intensity": "1 W/sr")") {
    return with_camera(std::string(R"("lights": [{"type": "point", "position": ["0 m", "0 m", "0 m"], )") + output +
                       R"(, "map": )" + map + "}]");
  };
  Scene scene = parse_scene(light(R"({"layout": "projection", "fov": "90 deg"})", R"("power": "12 W")"), "test.json", ".");
  ASSERT_TRUE(scene.point_lights[0].profile);
  EXPECT_NEAR(sg::raw(scene.point_lights[0].intensity).x, 12 * 6 / (4 * std::numbers::pi), 1e-5);
  EXPECT_EQ(load_error(light(R"({"layout": "ies"})")),
            "test.json: lights[0].map.layout: expected \"goniometric\" or \"projection\", got \"ies\"");
  EXPECT_EQ(load_error(light(R"({"layout": "goniometric", "fov": "10 deg"})")),
            "test.json: lights[0].map.fov: only a projection map has a field of view");
  EXPECT_EQ(load_error(light(R"({"layout": "projection"})")), "test.json: lights[0].map: missing field 'fov'");
  EXPECT_EQ(load_error(light(R"({"layout": "projection", "fov": "180 deg"})")),
            "test.json: lights[0].map.fov: expected an angle in (0 deg, 180 deg)");
  EXPECT_EQ(load_error(light(R"({"layout": "goniometric", "transform": [{"scale": [1, 2, 1]}]})")),
            "test.json: lights[0].map.transform[0]: a light's map can only be rotated");
}

TEST(SceneLoader, ConvertsUnitsOnceAtLoad) {
  Scene scene = parse_scene(with_camera(R"json(
    "shapes": [{"type": "sphere", "center": {"value": [0, 0, 0], "unit": "mm"}, "radius": "250 mm",
                "emission": {"value": [1, 2, 3], "unit": "W/(mm2 sr)"}}],
    "lights": [{"type": "point", "position": ["1 m", "200 cm", "3000 mm"], "power": "4 kW"}])json"),
                            "test.json", ".");
  ASSERT_EQ(scene.shapes.size(), 1u);
  EXPECT_FLOAT_EQ(sg::raw(scene.shapes[0].radius), 0.25f);
  EXPECT_FLOAT_EQ(sg::raw(*scene.shapes[0].emission).g, 2e6f);
  ASSERT_EQ(scene.point_lights.size(), 1u);
  EXPECT_FLOAT_EQ(sg::raw(scene.point_lights[0].position).y, 2.0f);
  EXPECT_FLOAT_EQ(sg::raw(scene.point_lights[0].intensity).r, 4000.0f / (4 * 3.14159265f));
}

TEST(SceneLoader, EstimatorSettings) {
  RenderSettings defaults = parse_scene(with_camera(""), "test.json", ".").settings;
  EXPECT_TRUE(defaults.mis);
  EXPECT_EQ(defaults.light_samples, 1);
  EXPECT_TRUE(defaults.russian_roulette);
  EXPECT_EQ(defaults.russian_roulette_depth, 3);
  RenderSettings set = parse_scene(with_camera(R"("render": {"mis": false, "light_samples": 4, "russian_roulette": false,
                                                             "russian_roulette_depth": 0})"),
                                   "test.json", ".")
                           .settings;
  EXPECT_FALSE(set.mis);
  EXPECT_EQ(set.light_samples, 4);
  EXPECT_FALSE(set.russian_roulette);
  EXPECT_EQ(set.russian_roulette_depth, 0);
  EXPECT_EQ(load_error(with_camera(R"("render": {"mis": "off"})")),
            "test.json: render.mis: expected true or false, got \"off\"");
  EXPECT_EQ(load_error(with_camera(R"("render": {"light_samples": 0})")),
            "test.json: render.light_samples: expected an integer in [1, 1024], got 0");
  EXPECT_EQ(load_error(with_camera(R"("render": {"russian_roulette_depth": -1})")),
            "test.json: render.russian_roulette_depth: expected an integer in [0, 1024], got -1");
}

TEST(SceneLoader, PlyMeshes) {
  Scene scene = load_scene(std::filesystem::path(SAFEGI_SCENES_DIR) / "ply-mesh.json");
  const Shape& torus = scene.shapes[1];
  EXPECT_EQ(torus.positions.size(), 32u * 16u);
  EXPECT_EQ(torus.indices.size(), 32u * 16u * 2u * 3u);  // quads become two triangles
  ASSERT_EQ(torus.normals.size(), torus.positions.size());  // its nx ny nz shade
  for (const normal<Object>& n : torus.normals) EXPECT_NEAR(glm::length(glm::vec3(sg::raw(n))), 1.0f, 1e-5f);
  // A damaged PLY file: the JSON path, the file and what is wrong with it.
  std::filesystem::path directory = std::filesystem::temp_directory_path() / ("safegi-ply-" + std::to_string(::getpid()));
  std::filesystem::create_directories(directory);
  {
    std::ofstream out(directory / "bad.ply", std::ios::binary);
    out << "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n";
  }
  try {
    parse_scene(with_camera(R"("shapes": [{"type": "mesh", "file": "bad.ply", "unit": "mm"}])"), "test.json", directory);
    ADD_FAILURE() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(std::string(error.what()),
              "test.json: shapes[0].file: cannot read mesh 'bad.ply': the vertex element needs a scalar property 'y'");
  }
  std::filesystem::remove_all(directory);
}

// Vertex normals: an OBJ's vn (by their own indices: a corner is a position, texcoord and normal triple) and a
// "triangles" list's "normals" shade; a zero one in a file becomes its triangles' normal, a zero one written in
// the scene is an error.
TEST(SceneLoader, VertexNormals) {
  std::filesystem::path directory = std::filesystem::temp_directory_path() / ("safegi-normals-" + std::to_string(::getpid()));
  std::filesystem::create_directories(directory);
  {
    std::ofstream out(directory / "tent.obj");
    out << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 1\nvn 0 0 2\nvn 1 0 1\nvn 0 0 0\nf 1//1 2//1 3//2\nf 1//1 3//3 4//1\n";
  }
  Scene scene = parse_scene(with_camera(R"("shapes": [{"type": "mesh", "file": "tent.obj", "unit": "m"}])"), "test.json", directory);
  const Shape& tent = scene.shapes.at(0);
  ASSERT_EQ(tent.positions.size(), 5u);  // position 3 twice: with normal 2 and with normal 3
  ASSERT_EQ(tent.normals.size(), 5u);
  auto raw = [](const normal<Object>& n) { return glm::vec3(sg::raw(n)); };
  EXPECT_NEAR(glm::distance(raw(tent.normals[0]), glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(raw(tent.normals[2]), glm::normalize(glm::vec3(1, 0, 1))), 0.0f, 1e-6f);
  // The zero vn at position 3 of the second triangle: that triangle's winding normal, (1,0,0)×(... ) normalised.
  const glm::vec3 a(0, 0, 0), c(1, 1, 0), d(0, 1, 1);
  EXPECT_NEAR(glm::distance(raw(tent.normals[3]), glm::normalize(glm::cross(c - a, d - a))), 0.0f, 1e-6f);
  EXPECT_TRUE(scene.textured());  // hits need their normals interpolated
  std::filesystem::remove_all(directory);

  const std::string triangles =
      R"("shapes": [{"type": "triangles", "positions": {"value": [[0,0,0],[1,0,0],[0,1,0]], "unit": "m"}, "indices": [0,1,2], )";
  Scene listed = parse_scene(with_camera(triangles + R"("normals": [[0,0,3],[0,0,1],[0,1,1]]}])"), "test.json", ".");
  EXPECT_NEAR(glm::distance(raw(listed.shapes[0].normals[2]), glm::normalize(glm::vec3(0, 1, 1))), 0.0f, 1e-6f);
  EXPECT_EQ(load_error(with_camera(triangles + R"("normals": [[0,0,1],[0,0,1]]}])")),
            "test.json: shapes[0].normals: expected one [x, y, z] per position (3)");
  EXPECT_EQ(load_error(with_camera(triangles + R"("normals": [[0,0,1],[0,0,0],[0,0,1]]}])")),
            "test.json: shapes[0].normals[1]: a normal needs a direction, got [0, 0, 0]");
}

TEST(SceneLoader, BundledScenesLoad) {
  // The core reads PFM images alone; others (the PNG textures) stand in as grey
  // here, where OpenImageIO is not linked.
  SceneLoadOptions options{[](const std::filesystem::path& file) {
    if (file.extension() == ".pfm") return read_pfm(file);
    EXPECT_TRUE(std::filesystem::is_regular_file(file)) << file;
    return Image{2, 2, std::vector<float>(12, 0.5f)};
  }};
  int count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(SAFEGI_SCENES_DIR)) {
    if (entry.path().extension() != ".json") continue;
    EXPECT_NO_THROW(load_scene(entry.path(), options)) << entry.path();
    ++count;
  }
  EXPECT_GE(count, 6);
}

}  // namespace
}  // namespace safegi::render

namespace safegi::render {
namespace {

// Damaged scene files of every kind give a SceneError, never another exception or a crash.
TEST(SceneLoader, DamagedFilesGiveSceneErrors) {
  std::filesystem::path directory = std::filesystem::path(SAFEGI_SCENES_DIR);
  std::string original;
  {
    std::ifstream in(directory / "phong.json");
    original.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::string replacements[] = {"", "0", "-1", "\"", "{", "]", "1e999", "\"5 W\"", "null", "[1,2]", "\"m\"", "true"};
  std::mt19937 rng(2024);
  int errors = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::string text = original;
    size_t at = std::uniform_int_distribution<size_t>(0, text.size() - 1)(rng);
    size_t length = std::uniform_int_distribution<size_t>(0, 12)(rng);
    text.replace(at, length, replacements[trial % std::size(replacements)]);
    try {
      parse_scene(text, "damaged.json", directory);
    } catch (const SceneError&) {
      ++errors;
    } catch (const std::exception& other) {
      ADD_FAILURE() << "unexpected exception: " << other.what() << "\n" << text;
    }
  }
  EXPECT_GT(errors, 200);
}

}  // namespace
}  // namespace safegi::render
