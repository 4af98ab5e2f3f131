// Zero-cost evidence: one frame loop written once against the typed API, built
// checked and unchecked (SAFEGI_GL_UNCHECKED) and linked with a glad loader
// whose every GL entry point reports its name. The two builds must print the
// same call trace; compare_traces.cmake diffs them under ctest.
#include <array>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "safegi/runtime_gl/gl.hpp"
#include "safegi/runtime_gl/runtime_gl.hpp"
#include "emission_scene.hpp"
#include "test_support.hpp"
#include "test_types.hpp"

namespace {

using namespace safegi::gl;
using testing::radiance_rgb;
using testing::unitless_rgb;

std::vector<std::string> trace;
bool recording = false;

void record(const char* name, GLADapiproc, int, ...) {
  if (recording) trace.emplace_back(name);
}
void ignore(void*, const char*, GLADapiproc, int, ...) {}

ProgramSource stage(Stage which, const char* glsl, const char* table) {
  return {which, testing::read_testdata(glsl), parse_symbol_table(testing::read_testdata(table), table)};
}

std::vector<radiance_rgb> frame_loop(int frames) {
  Program program({stage(Stage::vertex, "emission.vert.glsl", "emission.vert.json"),
                   stage(Stage::fragment, "emission.frag.glsl", "emission.frag.json")},
                  "emission");
  const auto le = program.uniform<radiance_rgb>("Le");
  const auto exposure = program.uniform<float>("exposure");
  const auto tint = program.uniform_array<unitless_rgb>("tint");
  const auto environment = program.sampler<radiance_rgb>("environment");

  using Scene = testing::EmissionScene;
  Scene scene(program);
  texture2d<radiance_rgb> image(8, 8);
  framebuffer target(8, 8);
  target.attach(program.output<radiance_rgb>("color"), image);

  for (int frame = 0; frame < frames; ++frame) {
    target.bind();
    program.use();
    program.bind(environment, scene.sky_texture, 0);
    program.set(le, radiance_rgb{1.0f, 2.0f, static_cast<float>(frame)});
    program.set(exposure, Scene::exposure);
    program.set(tint, std::span(Scene::tints));
    scene.triangle.draw_triangles(0, 3);
  }
  return image.read_back();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: " << argv[0] << " <trace-output>\n";
    return 2;
  }
  try {
    Context context(ContextOptions{Platform::osmesa});
    gladSetGLPreCallback(record);
    gladSetGLPostCallback(ignore);
    recording = true;
    const std::vector<radiance_rgb> pixels = frame_loop(3);
    recording = false;
    std::ofstream out(argv[1]);
    for (const auto& call : trace) out << call << '\n';
    out << "pixel " << pixels[0].r << ' ' << pixels[0].g << ' ' << pixels[0].b << '\n';
    std::cout << (SAFEGI_GL_UNCHECKED ? "unchecked" : "checked") << ": " << trace.size() << " GL calls\n";
  } catch (const std::exception& error) {
    std::cerr << error.what() << '\n';
    return 1;
  }
  return 0;
}
