#include "scene_meshes.hpp"

#include <gtest/gtest.h>

#include "safegi/cpu_renderer/scene_loader.hpp"

namespace safegi::preview {
namespace {

Scene cornell() { return load_scene(SAFEGI_SCENES_DIR "/cornell-box/cornell-box.json"); }

TEST(SceneMeshes, EveryShapeGetsItsTriangles) {
  Scene scene = cornell();
  SceneMeshes meshes = tessellate(scene);
  ASSERT_EQ(meshes.ranges.size(), scene.shapes.size());
  for (size_t s = 0; s < scene.shapes.size(); ++s)
    EXPECT_EQ(meshes.ranges[s].count, static_cast<int>(scene.shapes[s].indices.size())) << scene.shapes[s].name;
  EXPECT_EQ(meshes.positions.size(), meshes.normals.size());
}

TEST(SceneMeshes, AMeshsVertexNormalsShadeIt) {
  Scene scene = parse_scene(
      R"({"camera": {"position": {"value": [0, 0, 5], "unit": "m"}, "look_at": {"value": [0, 0, 0], "unit": "m"},
          "up": [0, 1, 0], "fov": "40 deg"},
          "shapes": [{"type": "triangles", "positions": {"value": [[0,0,0],[1,0,0],[0,1,0]], "unit": "m"},
                      "indices": [0, 1, 2], "normals": [[0,0,1],[1,0,1],[0,0,-1]]}]})",
      "test.json", ".");
  SceneMeshes meshes = tessellate(scene);
  ASSERT_EQ(meshes.normals.size(), 3u);
  EXPECT_NEAR(glm::distance(glm::vec3(sg::raw(meshes.normals[1])), glm::normalize(glm::vec3(1, 0, 1))), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(glm::vec3(sg::raw(meshes.normals[2])), glm::vec3(0, 0, 1)), 0.0f, 1e-6f);  // turned to the facet's side
}

TEST(SceneMeshes, SpheresAreTessellatedOnTheirSurface) {
  Scene scene = load_scene(SAFEGI_SCENES_DIR "/phong.json");
  SceneMeshes meshes = tessellate(scene, 16);
  const Shape& sphere = scene.shapes[1];
  ASSERT_EQ(sphere.type, Shape::Type::sphere);
  DrawRange range = meshes.ranges[1];
  EXPECT_EQ(range.count, 16 * 8 * 6);
  for (int i = range.first; i < range.first + range.count; ++i)
    EXPECT_NEAR(sg::raw(sg::length(meshes.positions[i] - sphere.center)), sg::raw(sphere.radius), 1e-5);
}

TEST(Emitter, AreaAndSamplesMatchTheQuad) {
  Scene scene = cornell();
  std::vector<Emitter> emitters = emitters_of(scene);
  ASSERT_EQ(emitters.size(), 1u);
  EXPECT_NEAR(sg::raw(emitters[0].area()), 0.47 * 0.38, 1e-5);
  for (uint32_t i = 0; i < 256; ++i) {
    float u, v;
    r2_point(i, u, v);
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(v, 1.0f);
    EmitterPoint y = emitters[0].sample(u, v);
    glm::vec3 p = sg::raw(y.position);
    EXPECT_NEAR(p.y, 1.98f, 1e-5f);
    EXPECT_GE(p.x, -0.24f - 1e-5f);
    EXPECT_LE(p.x, 0.23f + 1e-5f);
    EXPECT_GE(p.z, -0.22f - 1e-5f);
    EXPECT_LE(p.z, 0.16f + 1e-5f);
    EXPECT_NEAR(std::abs(sg::raw(y.normal).y), 1.0f, 1e-5f);
  }
}

TEST(ScenePoses, MotionFollowsTheShutter) {
  Scene scene = load_scene(SAFEGI_SCENES_DIR "/motion-blur.json");
  ScenePoses poses(scene);
  ASSERT_TRUE(poses.animated());
  const size_t sphere = 2;
  auto centre_at = [&](float t) { return sg::raw(poses.at(sphere, sg::from_raw<Time>(t))(scene.shapes[sphere].center)); };
  EXPECT_NEAR(centre_at(0.0f).x, -1.2f, 1e-5f);
  EXPECT_NEAR(centre_at(0.02f).x, -0.5f, 1e-5f);
  EXPECT_NEAR(centre_at(0.04f).x, 0.2f, 1e-5f);
}

}  // namespace
}  // namespace safegi::preview
