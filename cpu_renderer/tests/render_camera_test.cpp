// The orthographic and environment cameras against the geometry of what they
// see: emitting spheres (radiance L, nothing else in the scene), so a pixel is
// L times the share of it the sphere covers.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scene/camera.hpp"
#include "render_test_support.hpp"

namespace safegi::render {
namespace {

using namespace test_support;

// Per channel: the sum of the pixel values weighted by `weight(x, y)` at the
// pixel centres, and the value-weighted mean pixel position.
struct ChannelMoments {
  double weighted_sum = 0, x = 0, y = 0;
};

template <class Weight>
ChannelMoments moments(const Image& image, int channel, Weight weight) {
  ChannelMoments m;
  double plain = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const double value = image.rgb[3 * (static_cast<size_t>(y) * image.width + x) + channel];
      m.weighted_sum += value * weight(x + 0.5, y + 0.5);
      m.x += value * (x + 0.5);
      m.y += value * (y + 0.5);
      plain += value;
    }
  m.x /= plain;
  m.y /= plain;
  return m;
}

std::string emitting_sphere(const char* centre, const char* rgb) {
  return std::string(R"j({"type": "sphere", "center": {"value": )j") + centre +
         R"j(, "unit": "m"}, "radius": "1 m", "emission": {"value": )j" + rgb + R"j(, "unit": "W/(m2 sr)"}})j";
}

// A unit sphere 2 m right of and 1 m above the view's centre, seen along the
// axis: its disk has area π r² whatever the distance, and its centre is where
// the view size puts it. 64 spp: the edge pixels' coverage is estimated to
// ≈ 0.1 % of the disk's area (one standard error).
TEST(RenderCamera, OrthographicSeesASphereAtItsSizeAndPlace) {
  const std::string scene = R"j({
    "render": {"resolution": [64, 32], "integrator": "path"},
    "camera": {"projection": "orthographic", "position": ["0 m", "0 m", "5 m"], "look_at": ["0 m", "0 m", "0 m"],
               "up": [0, 1, 0], "view_size": "4 m"},
    "shapes": [)j" + emitting_sphere("[2, 1, 0]", "[1, 1, 1]") + "]}";
  const Image image = render_text(scene, 64);
  const double pixel = 4.0 / 32;  // metres per pixel: the shorter axis (32 pixels) spans the view size
  const ChannelMoments m = moments(image, 1, [&](double, double) { return pixel * pixel; });
  EXPECT_NEAR(m.weighted_sum, kPiD, 0.005 * kPiD);
  EXPECT_NEAR(m.x, 32 + 2 / pixel, 0.1);
  EXPECT_NEAR(m.y, 16 - 1 / pixel, 0.1);
}

// pbrt-v3's environment camera: θ down from the camera's up, φ from its right
// towards forward across the image. A pixel spans (2π/w)(π/h) sin θ
// steradians, so Σ value × solid angle is L times the sphere's solid angle
// 2π(1 − cos α), sin α = r/d; each sphere appears where its direction maps:
// forward at a quarter of the width, left (−right) at half, up in the top rows.
TEST(RenderCamera, EnvironmentSeesEachSphereInItsDirectionAndSolidAngle) {
  const std::string scene = R"j({
    "render": {"resolution": [128, 64], "integrator": "path"},
    "camera": {"projection": "environment", "position": ["0 m", "0 m", "0 m"], "look_at": ["0 m", "0 m", "-1 m"],
               "up": [0, 1, 0]},
    "shapes": [)j" + emitting_sphere("[0, 0, -4]", "[1, 0, 0]") + ", " +
                            emitting_sphere("[-4, 0, 0]", "[0, 1, 0]") + ", " +
                            emitting_sphere("[0, 4, 0]", "[0, 0, 1]") + "]}";
  const Image image = render_text(scene, 64);
  const double w = image.width, h = image.height;
  auto solid_angle = [&](double, double y) { return (2 * kPiD / w) * (kPiD / h) * std::sin(kPiD * y / h); };
  const double expected = 2 * kPiD * (1 - std::sqrt(1 - 1.0 / 16));
  const ChannelMoments forward = moments(image, 0, solid_angle), left = moments(image, 1, solid_angle),
                       up = moments(image, 2, solid_angle);
  for (const ChannelMoments& sphere : {forward, left, up})
    EXPECT_NEAR(sphere.weighted_sum, expected, 0.01 * expected);
  EXPECT_NEAR(forward.x, w / 4, 0.1);
  EXPECT_NEAR(forward.y, h / 2, 0.1);
  EXPECT_NEAR(left.x, w / 2, 0.1);
  EXPECT_NEAR(left.y, h / 2, 0.1);
  EXPECT_LT(up.y, h * 0.1);  // a cap around the pole: the top rows, across the width
  EXPECT_NEAR(up.x, w / 2, 1.0);
}

// The texture footprint's cone: one pixel's angle (or, orthographic, its width)
// across the shorter axis, narrowed by 1/√spp as pbrt-v3 narrows its rays'
// differentials.
TEST(RenderCamera, PixelConeIsAPixelNarrowedBySamples) {
  Camera camera;
  camera.fov = Real(90) * units::degree;
  EXPECT_NEAR(sg::raw(pixel_cone(camera, 64, 32, 1).spread), 2.0 / 32, 1e-7);
  EXPECT_NEAR(sg::raw(pixel_cone(camera, 64, 32, 16).spread), 2.0 / 32 / 4, 1e-7);
  camera.projection = CameraProjection::orthographic;
  camera.view_size = Real(4) * units::meter;
  const PixelCone ortho = pixel_cone(camera, 64, 32, 4);
  EXPECT_NEAR(sg::raw(ortho.width), 4.0 / 32 / 2, 1e-7);
  EXPECT_EQ(sg::raw(ortho.spread), 0.0f);
}

// The pixel steps along a camera ray are the image plane's axes off the ray,
// shrunk by d·forward: one pixel's step at the centre, at the corner of a 90°
// image √(2/3)/√3 ≈ 0.471 of it, across the ray; orthographic: the axes.
TEST(RenderCamera, PixelStepsAreTheImageAxesAlongEachRay) {
  Camera camera;
  camera.position = PointWorld(0 * units::meter, 0 * units::meter, 0 * units::meter);
  camera.look_at = PointWorld(0 * units::meter, 0 * units::meter, -1 * units::meter);
  camera.up = DirectionWorld(0, 1, 0);
  camera.fov = Real(90) * units::degree;
  const CameraRays rays(camera, 64, 64);
  auto [centre_x, centre_y] = rays.pixel_steps(DirectionWorld(0, 0, -1));
  EXPECT_NEAR(sg::raw(centre_x).x, 1.0f, 1e-6f);
  EXPECT_NEAR(sg::raw(centre_y).y, 1.0f, 1e-6f);
  const DirectionWorld corner = sg::normalize(sg::from_raw<ConeStep>(glm::vec3(1, 1, -1)));
  auto [corner_x, corner_y] = rays.pixel_steps(corner);
  EXPECT_NEAR(glm::length(sg::raw(corner_x)), std::sqrt(2.0 / 3) / std::sqrt(3.0), 1e-6);
  EXPECT_NEAR(glm::dot(sg::raw(corner_x), sg::raw(corner)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(sg::raw(corner_y), sg::raw(corner)), 0.0f, 1e-6f);
  camera.projection = CameraProjection::orthographic;
  camera.view_size = Real(2) * units::meter;
  auto [ortho_x, ortho_y] = CameraRays(camera, 64, 64).pixel_steps(DirectionWorld(0, 0, -1));
  EXPECT_EQ(sg::raw(ortho_x), glm::vec3(1, 0, 0));
  EXPECT_EQ(sg::raw(ortho_y), glm::vec3(0, 1, 0));
}

// Past specular surfaces the cone bends as paraxial optics says: a ball lens
// (n = 1.5, r = 1) focuses a parallel beam at its back focal length, n·2r /
// (4 (n − 1)) − r = 0.5 behind it; a convex mirror's reflection seems to
// diverge from r/2 behind the mirror, so the beam is twice as wide r/2 in front.
TEST(RenderCamera, ThePixelConeBendsAsALensBendsABeam) {
  const Length r = Real(1) * units::meter;
  const PixelCone beam{Real(0.01) * units::meter, sg::zero};
  const PixelCone inside = beam.refracted(1.5f, r).after(2 * r);
  const PixelCone out = inside.refracted(1 / 1.5f, -r);
  EXPECT_NEAR(sg::raw(out.after(Real(0.5) * r).width), 0.0, 1e-8);
  EXPECT_GT(sg::raw(out.after(Real(0.4) * r).width), 0.0f);  // before it
  EXPECT_LT(sg::raw(out.after(Real(0.6) * r).width), 0.0f);  // past the focus
  EXPECT_NEAR(sg::raw(beam.reflected(r).after(Real(0.5) * r).width), 0.02, 1e-8);
  EXPECT_NEAR(sg::raw(beam.reflected(-r).after(Real(0.5) * r).width), 0.0, 1e-8);  // a concave one focuses at r/2
  // Flat surfaces: a mirror keeps the cone; a refraction narrows its angle by η, not its width.
  const PixelCone spreading{Real(0.01) * units::meter, Real(0.002) * units::radian};
  EXPECT_EQ(sg::raw(spreading.reflected(std::nullopt).spread), 0.002f);
  EXPECT_NEAR(sg::raw(spreading.refracted(2, std::nullopt).spread), 0.001, 1e-9);
  EXPECT_EQ(sg::raw(spreading.refracted(2, std::nullopt).width), 0.01f);
}

}  // namespace
}  // namespace safegi::render
