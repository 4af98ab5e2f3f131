#include "program_loader.hpp"

#include <gtest/gtest.h>
#include <safegi/compiler/compile.hpp>
#include <safegi/compiler/spirv.hpp>
#include <safegi/runtime_gl/context.hpp>
#include <safegi/runtime_gl/runtime_gl.hpp>

#include <cmath>
#include <cstdio>

#include "safegi/cpu_renderer/scene_loader.hpp"
#include "safegi/preview/preview.hpp"

namespace safegi::preview {
namespace {

// A physics error in an annotated shader stops loading with the compiler's
// diagnostic, located in the user's file, before any GL call.
TEST(ProgramLoader, AnnotationErrorsComeBackAsDiagnostics) {
  const std::string fragment =
      "#version 330 core\n"
      "#include <safegi/prelude.sgl>\n"
      "uniform spectrum<radiance> Le;\n"
      "uniform float<area> A;\n"
      "out vec4 color;\n"
      "void main() {\n"
      "    spectrum<intensity> I = Le * A;\n"
      "    color = vec4(vec3<1>(I), 1.0);\n"
      "}\n";
  try {
    load_program({{"emitter.sgl.frag", fragment}}, {}, "emitter");
    FAIL() << "a missing cosine was accepted";
  } catch (const ShaderLoadError& error) {
    std::string message = error.what();
    EXPECT_NE(message.find("emitter.sgl.frag:7:29: error: cannot initialize 'I' of type spectrum<intensity>"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("missing cosine factor"), std::string::npos) << message;
  }
}

TEST(ProgramLoader, UnknownEmbeddedShaderIsNamed) {
  EXPECT_FALSE(embedded_shader("nope.sgl.frag").has_value());
  EXPECT_TRUE(embedded_shader("shade.sgl.frag").has_value());
  try {
    load_embedded_program({"nope.sgl.frag"}, {}, "nope");
    FAIL();
  } catch (const ShaderLoadError& error) {
    EXPECT_STREQ(error.what(), "safegi-preview: error: no embedded shader named 'nope.sgl.frag'");
  }
}

// The compiler describes projmap<A, B> as kind projective_map, so the typed
// library's projective_map binds and an affine map does not.
TEST(ProgramLoader, ProjectionUniformsBindAsProjectiveMaps) {
  gl::Context context;
  gl::Program program = load_embedded_program({"scene.sgl.vert", "shade.sgl.frag"}, {{"POINT_LIGHT", "1"}}, "point");
  EXPECT_NO_THROW((program.uniform<projective_map<spaces::world, spaces::clip>>("clipFromWorld")));
#if !SAFEGI_GL_UNCHECKED
  EXPECT_THROW((program.uniform<map<spaces::world, spaces::clip>>("clipFromWorld")), gl::BindingError);
#endif
}

// The same preview with its shaders loaded as SPIR-V (glslang, OpenGL target,
// through GL_ARB_gl_spirv) draws the GLSL image: every program kind (emission,
// point light, area-light samples, shadow depth) is bound by name through the
// modules' locations. Tolerance: the driver turns GLSL and SPIR-V into its IR
// by different front ends, which may round a float operation differently, and
// Phong's cosⁿ multiplies a relative difference in cos by n: with phong.json's
// largest exponent, 1000, one float rounding (6e-8) becomes 6e-5. So 2.5e-4
// relative (about two roundings after cos¹⁰⁰⁰) plus 1e-6; measured: 6.6e-5
// at most, on a highlight of 1.1, when this was written.
TEST(ProgramLoader, SpirvProgramsDrawTheGlslImage) {
  gl::Context context;
  if (!gl::spirv_programs_supported())
    GTEST_SKIP() << "the driver (" << gl::describe(context.info())
                 << ") does not offer GL_ARB_gl_spirv: SPIR-V loading is not tested here";
  const render::Scene scene = render::load_scene(std::string(SAFEGI_SCENES_DIR) + "/phong.json");
  PreviewOptions options;
  options.width = 50;
  options.height = 20;
  options.light_samples = 4;
  options.passes = 2;
  const render::Image glsl = Preview(scene, options).render();
  options.spirv_shaders = true;
  const render::Image spirv = Preview(scene, options).render();
  ASSERT_EQ(glsl.rgb.size(), spirv.rgb.size());
  double largest = 0, mean = 0;
  for (std::size_t i = 0; i < glsl.rgb.size(); ++i) {
    EXPECT_NEAR(spirv.rgb[i], glsl.rgb[i], 1e-6 + 2.5e-4 * std::fabs(glsl.rgb[i])) << "channel value " << i;
    largest = std::max(largest, static_cast<double>(std::fabs(spirv.rgb[i] - glsl.rgb[i])));
    mean += glsl.rgb[i] / static_cast<double>(glsl.rgb.size());
  }
  EXPECT_GT(mean, 0.01) << "a black image proves nothing";
  std::printf("SPIR-V vs GLSL: largest difference %.3g (mean value %.3g)\n", largest, mean);
}

// SPIR-V and GLSL stages do not mix in one program (GL cannot link them).
TEST(ProgramLoader, AProgramIsAllSpirvOrAllGlsl) {
  gl::Context context;
  if (!gl::spirv_programs_supported()) GTEST_SKIP() << "no GL_ARB_gl_spirv";
  gl::Program glsl = load_embedded_program({"shadow_depth.sgl.vert", "shadow_depth.sgl.frag"}, {}, "depth");
  (void)glsl;
  std::vector<ShaderFile> files;
  for (const char* name : {"shadow_depth.sgl.vert", "shadow_depth.sgl.frag"})
    files.push_back({std::string("preview/shaders/") + name, std::string(*embedded_shader(name))});
  std::vector<ShaderSource> sources;
  for (const ShaderFile& f : files) sources.push_back({f.path, f.text, std::nullopt});
  CompileResult compiled = compile(sources);
  ASSERT_TRUE(compiled.success);
  SpirvResult modules = to_spirv(compiled, {.client = SpirvClient::opengl});
  ASSERT_TRUE(modules.success) << modules.log;
  std::vector<gl::ProgramSource> stages = {{gl::Stage::vertex, compiled.stages[0].glsl, compiled.symbols, modules.modules[0].words},
                                           {gl::Stage::fragment, compiled.stages[1].glsl, compiled.symbols}};
  try {
    gl::Program mixed(stages, "mixed");
    FAIL() << "a SPIR-V vertex stage linked with a GLSL fragment stage";
  } catch (const gl::ShaderError& error) {
    EXPECT_STREQ(error.what(), "mixed: error: a program is either all SPIR-V or all GLSL (GL links no mix of the two)");
  }
}

}  // namespace
}  // namespace safegi::preview
