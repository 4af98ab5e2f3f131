// Erasure: the driver sees the user's own lines with the annotations blanked.
#include <gtest/gtest.h>

#include "glslang_check.hpp"
#include "safegi/compiler/compile.hpp"

namespace safegi {
namespace {

std::string elide_ok(const std::string& source, Stage stage = Stage::fragment) {
  ShaderSource s{"e.sgl", source, stage};
  CompileResult r = compile({s});
  EXPECT_TRUE(r.success) << r.diagnostics_text();
  if (!r.success) return {};
  testing::GlslangVerdict v = testing::glslang_validate(r.stages[0].glsl, stage);
  EXPECT_TRUE(v.accepted) << v.log << "\n" << r.stages[0].glsl;
  return r.stages[0].glsl;
}

std::size_t lines(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

TEST(Elide, AnnotationsBecomeSpacesAndLinesStay) {
  const std::string src = "#version 330 core\n#include <safegi/prelude.sgl>\nuniform float<length> d;\n"
                          "uniform spectrum<radiance> L;\nout vec4 c;\nvoid main() { c = vec4(L * d, 1.0); }\n";
  const std::string out = elide_ok(src);
  EXPECT_EQ(out, "#version 330 core\n                             \nuniform float         d;\n"
                 "uniform vec3               L;\nout vec4 c;\nvoid main() { c = vec4(L * d, 1.0); }\n");
  EXPECT_EQ(lines(out), lines(src));
}

TEST(Elide, DeclarationsAndTemplateHeadersVanish) {
  const std::string src = "#version 330 core\ndimension length;\ndimension area = length^2;\nspace world;\n"
                          "unit cm : length = 0.01;\n"
                          "template<dimension D>\nfloat<D> twice(float<D> x) { return 2.0 * x; }\n"
                          "out vec4 c;\nvoid main() { float<length> r = 3.0 * cm; c = vec4(twice(r)); }\n";
  const std::string out = elide_ok(src);
  EXPECT_EQ(lines(out), lines(src));
  EXPECT_EQ(out.find("dimension"), std::string::npos) << out;
  EXPECT_EQ(out.find("template"), std::string::npos) << out;
  EXPECT_NE(out.find("3.0 * (0.01)"), std::string::npos) << out;
  EXPECT_NE(out.find("float    twice(float    x)"), std::string::npos) << out;
}

TEST(Elide, GeometricOperationsBecomePlainGlsl) {
  const std::string src =
      "#version 330 core\n#include <safegi/prelude.sgl>\nspace object;\nspace world;\nspace clip;\n"
      "uniform map<object, world> M;\nuniform projmap<world, clip> P;\nin point<object> p;\n"
      "in vector<object> v;\nin normal<object> n;\n"
      "void main() {\n"
      "  point<world> q = M * p;\n"
      "  vector<world> w = transform(M, v);\n"
      "  normal<world> m = M * n;\n"
      "  hpoint<clip> h = P * q;\n"
      "  point<clip> r = homogenize(h);\n"
      "  gl_Position = vec4(r, 1.0) + vec4(w.x, m.x, 0.0, 0.0);\n"  // a clip point plus a world vector would be refused
      "}\n";
  const std::string out = elide_ok(src, Stage::vertex);
  EXPECT_NE(out.find("vec3         q = (M * vec4(p, 1.0)).xyz;"), std::string::npos) << out;
  EXPECT_NE(out.find("(mat3(M) * v)"), std::string::npos) << out;
  EXPECT_NE(out.find("(transpose(inverse(mat3(M))) * n)"), std::string::npos) << out;
  EXPECT_NE(out.find("(P * vec4(q, 1.0))"), std::string::npos) << out;
  EXPECT_NE(out.find("(h.xyz / h.w)"), std::string::npos) << out;
  EXPECT_EQ(lines(out), lines(src));
}

TEST(Elide, HelperOnlyWhenAnOperandIsNotAVariable) {
  const std::string src =
      "#version 330 core\n#include <safegi/prelude.sgl>\nspace world;\nspace clip;\n"
      "uniform projmap<world, clip> P;\nin point<world> p;\n"
      "void main() {\n  point<clip> r = homogenize(P * p);\n  gl_Position = vec4(r, 1.0);\n}\n";
  const std::string out = elide_ok(src, Stage::vertex);
  EXPECT_EQ(out.rfind("#version 330 core\nvec3 safegi_homogenize(vec4 h) { return h.xyz / h.w; }\n#line 2\n", 0), 0u) << out;
  EXPECT_NE(out.find("safegi_homogenize((P * vec4(p, 1.0)))"), std::string::npos) << out;
}

TEST(Elide, PlainGlslIsUnchanged) {
  const std::string src = "#version 450\n// a comment <float>\nlayout(location = 0) out vec4 c;\n"
                          "uniform sampler2D t;\nvoid main() {\n  c = texture(t, vec2(0.5)) * 2.0; /* x */\n}\n";
  EXPECT_EQ(elide_ok(src), src);
}

TEST(Elide, CastsThatOnlyChangeTheAnnotationBecomeParentheses) {
  const std::string src = "#version 330 core\n#include <safegi/prelude.sgl>\nout vec4 c;\n"
                          "void main() { float<area> a = float<area>(2.0); float<solid_angle> w = float<solid_angle>(a / (1.0 * meter * meter)); c = vec4(w); }\n";
  const std::string out = elide_ok(src);
  EXPECT_NE(out.find("float       a =            (2.0);"), std::string::npos) << out;
  EXPECT_NE(out.find("w =                   (a / (1.0                ))"), std::string::npos) << out;
  // A cast that converts the GLSL type keeps its constructor.
  const std::string converting = elide_ok("#version 330 core\nout vec4 c;\nvoid main() { int i = 2; c = vec4(float<1>(i)); }\n");
  EXPECT_NE(converting.find("vec4(float   (i))"), std::string::npos) << converting;
}

TEST(Elide, AnnotatedSamplersAndBlocks) {
  const std::string src =
      "#version 330 core\n#include <safegi/prelude.sgl>\nspace world;\nuniform sampler2D<float<length>> depth;\n"
      "layout(std140) uniform Camera { map<world, world> M; float<length> f; } camera;\n"
      "out vec4 c;\nvoid main() { c = vec4(texture(depth, vec2(0.5)).r * camera.f); }\n";
  const std::string out = elide_ok(src);
  EXPECT_NE(out.find("uniform sampler2D                depth;"), std::string::npos) << out;
  EXPECT_NE(out.find("{ mat4              M; float         f; }"), std::string::npos) << out;
}

}  // namespace
}  // namespace safegi
