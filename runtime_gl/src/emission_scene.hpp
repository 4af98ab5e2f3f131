#pragma once
// The example program's scene, shared by the typed API test and the call-trace
// program: one viewport-covering triangle with per-vertex radiance, a one-texel
// sky, and uniform values whose result is exact in binary.
#include <array>
#include <span>

#include "safegi/runtime_gl/program.hpp"
#include "safegi/runtime_gl/resources.hpp"
#include "test_types.hpp"

namespace safegi::gl::testing {

struct EmissionScene {
  static constexpr std::array<ndc_point, 3> positions{{{-1, -1, 0}, {3, -1, 0}, {-1, 3, 0}}};
  static constexpr radiance_rgb vertex_radiance{0.5f, 0.25f, 0.125f};
  static constexpr std::array<radiance_rgb, 3> vertex_le{{vertex_radiance, vertex_radiance, vertex_radiance}};
  static constexpr radiance_rgb sky{0.5f, 0.5f, 0.5f};
  static constexpr radiance_rgb le{1.0f, 2.0f, 3.0f};
  static constexpr float exposure = 2.0f;
  static constexpr std::array<unitless_rgb, 2> tints{{{1.0f, 0.5f, 0.25f}, {2.0f, 2.0f, 2.0f}}};

  // (vertexLe + Le + sky) * exposure * tint[0] * tint[1]
  static radiance_rgb expected_pixel(const radiance_rgb& uniform_le) {
    auto channel = [](float v, float l, float s, float t0, float t1) { return (v + l + s) * exposure * t0 * t1; };
    return {channel(vertex_radiance.r, uniform_le.r, sky.r, tints[0].r, tints[1].r),
            channel(vertex_radiance.g, uniform_le.g, sky.g, tints[0].g, tints[1].g),
            channel(vertex_radiance.b, uniform_le.b, sky.b, tints[0].b, tints[1].b)};
  }

  explicit EmissionScene(const Program& program)
      : position_buffer(std::span(positions)), le_buffer(std::span(vertex_le)), sky_texture(1, 1, std::span(&sky, 1)) {
    triangle.bind(program.attribute<ndc_point>("position"), position_buffer);
    triangle.bind(program.attribute<radiance_rgb>("vertexLe"), le_buffer);
  }

  vertex_buffer<ndc_point> position_buffer;
  vertex_buffer<radiance_rgb> le_buffer;
  vertex_array triangle;
  texture2d<radiance_rgb> sky_texture;
};

}  // namespace safegi::gl::testing
