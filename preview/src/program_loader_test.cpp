#include "program_loader.hpp"

#include <gtest/gtest.h>
#include <safegi/runtime_gl/context.hpp>
#include <safegi/runtime_gl/runtime_gl.hpp>

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

}  // namespace
}  // namespace safegi::preview
