// Lights::may_be_hit, the test before a paired BSDF sample is traced: never
// false for a ray that reaches the light, false for most that do not.
#include "lights/lights.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "safegi/cpu_renderer/scene_loader.hpp"

namespace safegi::render {
namespace {

TEST(Lights, MayBeHitNeverMissesARayThatReachesTheLight) {
  // An emitting sphere of 0.5 m around (0, 2, 0) (light 0) and a 2 m × 1 m emitting quad at z = 0 (light 1).
  const std::string sphere =
      R"j({"type": "sphere", "center": ["0 m", "2 m", "0 m"], "radius": "0.5 m", "emission": "1 W/(m2 sr)"})j";
  const std::string quad = R"j({"type": "quad", "origin": ["-1 m", "-1 m", "0 m"], "edge_u": ["2 m", "0 m", "0 m"],)j"
                           R"j( "edge_v": ["0 m", "1 m", "0 m"], "emission": "1 W/(m2 sr)"})j";
  const std::string camera = R"({"position": ["0 m", "0 m", "5 m"], "look_at": ["0 m", "0 m", "0 m"], "up": [0, 1, 0], "fov": "40 deg"})";
  Scene scene = parse_scene(R"({"camera": )" + camera + R"(, "shapes": [)" + sphere + ", " + quad + "]}", "test.json", ".");
  Lights lights(scene);
  ASSERT_EQ(lights.size(), 2u);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int quad_hits = 0, sphere_hits = 0, rejected = 0, misses = 0;
  for (int i = 0; i < 200000; ++i) {
    const double ox = 4 * u(rng), oy = 4 * u(rng), oz = 4 * u(rng);
    double dx = u(rng), dy = u(rng), dz = u(rng);
    const double norm = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (norm < 1e-3 || norm > 1) continue;
    dx /= norm, dy /= norm, dz /= norm;
    const PointWorld origin = from_kernel<PointWorld>(Real3{Real(ox), Real(oy), Real(oz)});
    const DirectionWorld direction = from_kernel<DirectionWorld>(Real3{Real(dx), Real(dy), Real(dz)});
    // The quad: where the ray crosses z = 0, ahead of its origin.
    const double t = -oz / dz;
    const double x = ox + t * dx, y = oy + t * dy;
    const bool reaches_quad = t > 0 && x >= -1 && x <= 1 && y >= -1 && y <= 0;
    // The sphere: the line's distance to its centre, the centre's projection ahead or the origin inside.
    const double cx = -ox, cy = 2 - oy, cz = -oz, along = cx * dx + cy * dy + cz * dz;
    const double centre2 = cx * cx + cy * cy + cz * cz;
    const bool reaches_sphere = centre2 - along * along <= 0.25 && (along > 0 || centre2 <= 0.25);
    for (auto [light, reaches, hits] : {std::tuple{1u, reaches_quad, &quad_hits}, std::tuple{0u, reaches_sphere, &sphere_hits}}) {
      const bool may = lights.may_be_hit(light, origin, direction);
      if (reaches) {
        ++*hits;
        EXPECT_TRUE(may) << "light " << light << " from (" << ox << ", " << oy << ", " << oz << ") along (" << dx << ", "
                         << dy << ", " << dz << ")";
      } else {
        ++misses;
        rejected += !may;
      }
    }
  }
  EXPECT_GT(quad_hits, 500);
  EXPECT_GT(sphere_hits, 500);
  EXPECT_GT(rejected, misses * 8 / 10);  // most rays that miss are turned away without a trace
}

}  // namespace
}  // namespace safegi::render
