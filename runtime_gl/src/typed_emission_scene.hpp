#pragma once
// The example program's scene in the typed library's types, shared by the
// typed binding test and the call-trace program (both built checked and
// unchecked): a viewport-covering triangle with per-vertex radiance, a
// one-texel sky, and uniform values whose result is exact in binary.
#include <array>
#include <safegi/typed.hpp>
#include <span>

#include "safegi/runtime_gl/runtime_gl.hpp"

namespace safegi::gl::testing {

struct TypedEmissionScene {
  using radiance = spectrum<dim::radiance>;
  using tint = spectrum<dim::dimensionless>;
  using ndc_point = point<spaces::ndc>;

  static radiance rgb(float r, float g, float b) { return from_raw<radiance>(glm::vec3(r, g, b)); }

  explicit TypedEmissionScene(const Program& program)
      : corners{from_raw<ndc_point>(glm::vec3(-1, -1, 0)), from_raw<ndc_point>(glm::vec3(3, -1, 0)),
                from_raw<ndc_point>(glm::vec3(-1, 3, 0))},
        vertex_le{rgb(0.5f, 0.25f, 0.125f), rgb(0.5f, 0.25f, 0.125f), rgb(0.5f, 0.25f, 0.125f)},
        sky(rgb(0.5f, 0.5f, 0.5f)),
        tints{from_raw<tint>(glm::vec3(1, 0.5f, 0.25f)), from_raw<tint>(glm::vec3(2))},
        positions(std::span(corners)),
        le_buffer(std::span(vertex_le)),
        sky_texture(1, 1, std::span(&sky, 1)) {
    triangle.bind(program.attribute<ndc_point>("position"), positions);
    triangle.bind(program.attribute<radiance>("vertexLe"), le_buffer);
  }

  // Sets every uniform except Le, which each user varies.
  void set_uniforms(const Program& program, int sky_unit) const {
    program.bind(program.sampler<radiance>("environment"), sky_texture, sky_unit);
    program.set(program.uniform<float>("exposure"), 2.0f);
    program.set(program.uniform_array<tint>("tint"), tints);
  }

  std::array<ndc_point, 3> corners;
  std::array<radiance, 3> vertex_le;
  radiance sky;
  std::array<tint, 2> tints;
  vertex_buffer<ndc_point> positions;
  vertex_buffer<radiance> le_buffer;
  vertex_array triangle;
  texture2d<radiance> sky_texture;
};

}  // namespace safegi::gl::testing
