// The downstream program: host code with the typed library (the irradiance a
// small emitter gives, E = Le · cos θ · A / r², with its dimensions checked by
// the C++ compiler), the shader safegi_add_shaders() compiled at build time,
// and the same shader compiled again in process with safegi::compile.
#include <cstdio>
#include <fstream>
#include <sstream>

#include <safegi/compiler/compile.hpp>
#include <safegi/typed.hpp>

namespace sg = safegi;
using namespace sg;

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

int main() {
  const spectrum<dim::radiance> Le(10.0f * units::radiance_unit);
  const quantity<dim::area> area = 4.0f * units::square_millimetre;
  const quantity<dim::length> distance = 2.0f * units::centimetre;
  const quantity<dim::proj> cos_theta = 0.5f * units::proj;
  const quantity<dim::solid_angle> subtended = area / (distance * distance) * units::steradian;
  const spectrum<dim::irradiance> E = Le * cos_theta * subtended;
  std::printf("irradiance %.4f W/m^2\n", in(E.r(), units::watt_per_square_metre));

  // What the build produced from the annotated shader.
  const std::string glsl = read(SHADER_DIR "/emitter.frag.glsl");
  const std::string table = read(SHADER_DIR "/emitter.frag.json");
  if (glsl.find("uniform vec3") == std::string::npos || table.find("\"irradiance\"") == std::string::npos) {
    std::fprintf(stderr, "downstream: the build-time shader outputs are missing or wrong\n");
    return 1;
  }
  // The library: the same source, in process.
  sg::CompileResult result = sg::compile({{"emitter.sgl.frag", read(SHADER_SOURCE)}});
  if (!result.success || result.stages.at(0).glsl != glsl) {
    std::fprintf(stderr, "downstream: safegi::compile disagrees with the build:\n%s", result.diagnostics_text().c_str());
    return 1;
  }
  std::printf("shader emitter.sgl.frag: %zu bytes of GLSL, %zu uniforms in the symbol table\n", glsl.size(),
              result.symbols.stages.at(0).symbols.size() - 1);
  return 0;
}
