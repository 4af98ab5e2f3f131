// Zero-cost evidence: one frame loop written once against the typed API with
// the typed library's types, built checked (SafeGI::typed) and unchecked
// (SafeGI::typed_unchecked), each linked with a glad loader whose every GL
// entry point reports its name. The two builds must print the same call trace;
// compare_traces.cmake diffs them under ctest.
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "safegi/runtime_gl/gl.hpp"
#include "safegi/runtime_gl/runtime_gl.hpp"
#include "read_testdata.hpp"
#include "typed_emission_scene.hpp"

namespace {

using namespace safegi::gl;
using Scene = testing::TypedEmissionScene;

std::vector<std::string> trace;
bool recording = false;

void record(const char* name, GLADapiproc, int, ...) {
  if (recording) trace.emplace_back(name);
}
void ignore(void*, const char*, GLADapiproc, int, ...) {}

ProgramSource stage(Stage which, const char* glsl, const char* table) {
  return {which, testing::read_testdata(glsl), parse_symbol_table(testing::read_testdata(table), table)};
}

glm::vec3 frame_loop(int frames) {
  Program program({stage(Stage::vertex, "emission.vert.glsl", "emission.vert.json"),
                   stage(Stage::fragment, "emission.frag.glsl", "emission.frag.json")},
                  "emission");
  const auto le = program.uniform<Scene::radiance>("Le");
  Scene scene(program);
  texture2d<Scene::radiance> image(8, 8);
  framebuffer target(8, 8);
  target.attach(program.output<Scene::radiance>("color"), image);
  for (int frame = 0; frame < frames; ++frame) {
    target.bind();
    program.use();
    scene.set_uniforms(program, 0);
    program.set(le, Scene::rgb(1.0f, 2.0f, static_cast<float>(frame)));
    scene.triangle.draw_triangles(0, 3);
  }
  return safegi::raw(image.read_back().front());
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
    const glm::vec3 pixel = frame_loop(3);
    recording = false;
    std::ofstream out(argv[1]);
    for (const auto& call : trace) out << call << '\n';
    out << "pixel " << pixel.r << ' ' << pixel.g << ' ' << pixel.b << '\n';
    std::cout << (build_mode::checks ? "checked" : "unchecked") << ": " << trace.size() << " GL calls\n";
  } catch (const std::exception& error) {
    std::cerr << error.what() << '\n';
    return 1;
  }
  return 0;
}
