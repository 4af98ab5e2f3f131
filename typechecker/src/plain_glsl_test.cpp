// Plain GLSL that glslang accepts must check clean ("zero false positives",
// docs/typechecker.md): one case per false positive the external corpus found.

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

using Messages = std::vector<std::string>;

Messages plain(std::string_view source, Stage stage = Stage::fragment) {
  return check_source(source, {.stage = stage, .prelude = false})->messages();
}

TEST(PlainGlsl, DoubleMatrices) {  // glslang Test/matrixCompMult.vert
  EXPECT_EQ(plain("void main() { dmat2 a = dmat2(1.0), b = dmat2(2.0); dmat2 c = matrixCompMult(a, b);"
                  "dmat3x2 t = transpose(dmat2x3(1.0)); double d = determinant(a); dmat2 i = inverse(b);"
                  "dmat3x2 o = outerProduct(dvec2(1.0), dvec3(1.0)); }",
                  Stage::vertex),
            Messages{});
  EXPECT_EQ(plain("void main() { dmat2 a = dmat2(1.0); float d = determinant(a); }", Stage::vertex),
            Messages{"error: cannot initialize 'd' of type float with a value of type double"});
}

TEST(PlainGlsl, ArbTextureQueryLod) {  // glslang Test/textureQueryLOD.frag
  EXPECT_EQ(plain("uniform sampler2DShadow s; void main() { vec2 a = textureQueryLOD(s, vec2(0.0)); vec2 b = textureQueryLod(s, vec2(0.0)); }"),
            Messages{});
}

TEST(PlainGlsl, CompatibilityStateTypes) {  // piglit glsl-1.40/compiler/ARB_compatibility/gl_*Parameters.vert
  EXPECT_EQ(plain("void main() { gl_LightSourceParameters l = gl_LightSource[0]; gl_Position = l.position; }", Stage::vertex),
            Messages{});
}

TEST(PlainGlsl, LegacyShadowFunctionsReturnVec4) {
  EXPECT_EQ(plain("uniform sampler2DShadow s; void main() { vec4 a = shadow2D(s, vec3(0.0)); float b = shadow2D(s, vec3(0.0)).r; }"),
            Messages{});
}

TEST(PlainGlsl, TextureRectangleFunctions) {  // piglit glsl-1.50/compiler/arb_texture_rectangle.geom
  EXPECT_EQ(plain("uniform sampler2DRect r; uniform sampler2DRectShadow s; void main() {"
                  "vec4 a = texture2DRect(r, vec2(0.0)) + texture2DRectProj(r, vec3(1.0));"
                  "vec4 b = shadow2DRect(s, vec3(0.0)) + shadow2DRectProj(s, vec4(1.0)); }"),
            Messages{});
}

TEST(PlainGlsl, GatherWithOffsetArray) {  // piglit arb_gpu_shader5 builtin-functions/fs-gatherOffsets.frag
  EXPECT_EQ(plain("uniform sampler2D s; const ivec2 offsets[4] = ivec2[](ivec2(0), ivec2(1), ivec2(2), ivec2(3));"
                  "void main() { vec4 g = textureGatherOffsets(s, vec2(0.0), offsets); }"),
            Messages{});
  EXPECT_EQ(plain("uniform sampler2D s; const float bad[4] = float[](0.0, 1.0, 2.0, 3.0);"
                  "void main() { vec4 g = textureGatherOffsets(s, vec2(0.0), bad); }"),
            Messages{"error: no matching overload for call to 'textureGatherOffsets(sampler2D, vec2, float[4])'"});
}

TEST(PlainGlsl, BindlessHandles) {  // piglit arb_bindless_texture/compiler/samplers/arith-bound-sampler-texture2D.frag
  EXPECT_EQ(plain("uniform sampler2D tex; void main() { uvec2 h = uvec2(tex); vec4 c = texture2D(sampler2D(h + uvec2(1u)), vec2(0.0)); }"),
            Messages{});
  EXPECT_EQ(plain("uniform sampler2D tex; void main() { ivec2 h = ivec2(tex); }"),
            Messages{"error: cannot use sampler2D to construct ivec2"});
  // glslang's Test/GL_ARB_bindless_texture.frag: an ivec2 handle converts to uvec2 implicitly.
  EXPECT_EQ(plain("uniform ivec2 h; void main() { vec4 c = texture(sampler2D(h), vec2(0.0)); }"), Messages{});
  EXPECT_EQ(plain("uniform vec2 h; void main() { vec4 c = texture(sampler2D(h), vec2(0.0)); }"),
            Messages{"error: cannot construct sampler2D"});
}

TEST(PlainGlsl, UnsizedArrayRedeclaredWithASize) {  // piglit glsl-1.20 array-redeclaration-01.vert (GLSL 1.20 §4.1.9)
  EXPECT_EQ(plain("float x[]; void f() { x[1] = 2.0; } float x[] = float[2](1.0, 2.0);"
                  "void main() { vec4 a[]; a[0] = vec4(0.0); vec4 a[6]; f(); gl_Position = a[0] * x[0]; }",
                  Stage::vertex),
            Messages{});
  EXPECT_EQ(plain("void main() { vec4 a[]; vec3 a[6]; }", Stage::vertex), Messages{"error: redefinition of 'a'"});
  EXPECT_EQ(plain("void main() { vec4 a[2]; vec4 a[6]; }", Stage::vertex), Messages{"error: redefinition of 'a'"});
}

}  // namespace
}  // namespace safegi::testing
