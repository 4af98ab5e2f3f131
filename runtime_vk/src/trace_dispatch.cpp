// Zero-cost evidence: one compute loop written once against the typed API with
// the typed library's types, built checked (SafeGI::runtime_vk) and unchecked
// (SafeGI::runtime_vk_unchecked). Every Vulkan call runtime_vk makes is
// recorded (set_call_trace: name, scalar arguments, hashes of the bytes handed
// over); the two builds must write the same trace, and compare_traces.cmake
// diffs them under ctest.
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "safegi/runtime_vk/runtime_vk.hpp"
#include "test_shaders.hpp"
#include "test_types.hpp"

namespace {

using namespace safegi;
using namespace safegi::vk;
using namespace safegi::vk::testing;

glm::vec3 compute_loop(Context& context, int frames) {
  ComputePipeline pipeline(context, test_shader("scale"),
                           Specialization().set("gl_WorkGroupSize.x", 4u).set("exposure", 0.5f).set(2u, 2u));
  const std::vector<radiance> input = {rgb(1, 2, 3), rgb(4, 5, 6), rgb(7, 8, 9), rgb(10, 11, 12)};
  storage_buffer<radiance> source(context, input), target(context, input.size());
  image2d<glm::vec4> image(context, 2, 2);
  pipeline.bind(pipeline.storage_array<radiance>("Input.values"), source);
  pipeline.bind(pipeline.storage_array<radiance>("Output.scaled"), target);
  pipeline.bind(pipeline.image<glm::vec4>("image"), image);
  block_data params = pipeline.block("Params");
  const auto tint = pipeline.member<radiance>("Params.tint");
  params.set(pipeline.array_member<float>("Params.weights"), std::vector<float>{1.0f, 1.0f});
  block_buffer params_buffer(context, params);
  pipeline.bind(pipeline.block_binding("Params"), params_buffer);
  const auto factor = pipeline.push_constant<float>("factor");
  block_data push = pipeline.push_constants();
  push.set(pipeline.push_constant<std::uint32_t>("count"), 4u);
  for (int frame = 0; frame < frames; ++frame) {
    params.set(tint, rgb(0, 0, static_cast<float>(frame)));
    params_buffer.update(params);
    push.set(factor, static_cast<float>(frame + 1));
    pipeline.dispatch(push, 1);
  }
  return glm::vec3(image.read_back().back()) + raw(target.read_back().front());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: " << argv[0] << " <trace-output>\n";
    return 2;
  }
  try {
    Context context;
    std::vector<std::string> trace;
    set_call_trace([&trace](std::string_view line) { trace.emplace_back(line); });
    const glm::vec3 result = compute_loop(context, 3);
    set_call_trace(nullptr);
    std::ofstream out(argv[1]);
    for (const auto& call : trace) out << call << '\n';
    out << "result " << result.r << ' ' << result.g << ' ' << result.b << '\n';
    std::cout << (build_mode::checks ? "checked" : "unchecked") << ": " << trace.size() << " Vulkan calls\n";
  } catch (const std::exception& error) {
    std::cerr << error.what() << '\n';
    return 1;
  }
  return 0;
}
