// GLSL's own rules, as a driver would report them.

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

using Messages = std::vector<std::string>;

Messages plain(std::string_view source, Stage stage = Stage::fragment) {
  return check_source(source, {.stage = stage, .prelude = false})->messages();
}

TEST(Glsl, Names) {
  EXPECT_EQ(plain("void main() { float x = y; }"), Messages{"error: use of undeclared identifier 'y'"});
  EXPECT_EQ(plain("void main() { float x = 1.0; float x = 2.0; }"), Messages{"error: redefinition of 'x'"});
  EXPECT_EQ(plain("void main() { float x = 1.0; { float x = 2.0; } }"), Messages{});
  EXPECT_EQ(plain("void main() { foo(1.0); }"), Messages{"error: use of undeclared function 'foo'"});
  EXPECT_EQ(plain("void main() { float f = 1.0; f(2.0); }"), Messages{"error: called object 'f' is not a function"});
}

TEST(Glsl, Calls) {
  EXPECT_EQ(plain("float f(float a, float b) { return a + b; } void main() { float x = f(1.0); }"),
            Messages{"error: no matching function for call to 'f(float<1>)'"});
  EXPECT_EQ(plain("float f(float a) { return a; } float f(vec2 a) { return a.x; } void main() { float x = f(vec2(1.0)) + f(1); }"),
            Messages{});
  EXPECT_EQ(plain("void main() { float x = max(vec2(1.0), vec3(1.0)).x; }"),
            Messages{"error: no matching overload for call to 'max(vec2<1>, vec3<1>)'"});
  EXPECT_EQ(plain("void main() { float x = sqrt(1.0, 2.0); }"), Messages{"error: no matching overload for call to 'sqrt(float<1>, float<1>)'"});
  EXPECT_EQ(plain("void f(out float x) { x = 1.0; } void main() { f(2.0); }"),
            Messages{"error: argument 1 of 'f' is an out parameter and needs a writable variable"});
  EXPECT_EQ(plain("float f(float a) { return a; } float f(float a) { return a; } void main() {}"),
            Messages{"error: redefinition of 'f'"});
}

TEST(Glsl, ReadOnly) {
  EXPECT_EQ(plain("uniform float u; void main() { u = 1.0; }"), Messages{"error: cannot assign to read-only variable 'u'"});
  EXPECT_EQ(plain("void main() { const float c = 1.0; c += 1.0; }"), Messages{"error: cannot assign to read-only variable 'c'"});
  EXPECT_EQ(plain("out vec4 o; void main() { gl_FragCoord = vec4(1.0); o = gl_FragCoord; }"),
            Messages{"error: cannot assign to read-only variable 'gl_FragCoord'"});
  EXPECT_EQ(plain("in vec3 n; void main() { n.x = 1.0; }"), Messages{"error: cannot assign to read-only variable 'n'"});
  EXPECT_EQ(plain("void main() { vec3 v = vec3(1.0); v.xx = vec2(1.0); }"), Messages{"error: expression is not assignable"});
  EXPECT_EQ(plain("void main() { 1.0 = 2.0; }"), Messages{"error: expression is not assignable"});
}

TEST(Glsl, StageBuiltins) {
  EXPECT_EQ(plain("void main() { gl_Position = vec4(float(gl_VertexID)); gl_PointSize = 1.0; }", Stage::vertex), Messages{});
  // A built-in of another stage is rejected; gl_* names no stage has are left to the driver
  // (extensions and compatibility state are not modelled).
  EXPECT_EQ(plain("void main() { gl_Position = vec4(1.0); }", Stage::fragment),
            Messages{"error: 'gl_Position' is not available in fragment shaders"});
  EXPECT_EQ(plain("void main() { gl_Position = gl_FragCoord; }", Stage::vertex),
            Messages{"error: 'gl_FragCoord' is not available in vertex shaders"});
  EXPECT_EQ(plain("void main() { vec4 c = gl_Color + vec4(gl_FogFragCoord + gl_FooEXT); }", Stage::fragment), Messages{});
  EXPECT_EQ(plain("void main() { gl_Position = gl_in[0].gl_Position; }", Stage::vertex),
            Messages{"error: 'gl_in' is not available in vertex shaders"});
  EXPECT_EQ(plain("layout(vertices = 3) out; void main() { gl_out[gl_InvocationID].gl_Position = gl_in[0].gl_Position; }",
                  Stage::tess_control),
            Messages{});
  EXPECT_EQ(plain("layout(local_size_x = 8) in; void main() { uvec3 id = gl_GlobalInvocationID; }", Stage::compute), Messages{});
  EXPECT_EQ(plain("void main() { discard; }", Stage::vertex), Messages{"error: 'discard' is only allowed in fragment shaders"});
}

TEST(Glsl, StageBuiltinRendering) {
  auto c = check_source("out vec4 color;\nvoid main() {\n  gl_Position = vec4(1.0);\n}\n", {.stage = Stage::fragment, .prelude = false});
  EXPECT_EQ(c->rendered(),
            "test.frag:3:3: error: 'gl_Position' is not available in fragment shaders [E-STAGE-BUILTIN]\n"
            "  gl_Position = vec4(1.0);\n"
            "  ^~~~~~~~~~~\n"
            "help: 'gl_Position' is a built-in of vertex, tessellation control, tessellation evaluation and geometry shaders\n");
  auto v = check_source("void main() {\n  gl_Position = gl_FragCoord;\n}\n", {.stage = Stage::vertex, .prelude = false});
  EXPECT_EQ(v->rendered(),
            "test.frag:2:17: error: 'gl_FragCoord' is not available in vertex shaders [E-STAGE-BUILTIN]\n"
            "  gl_Position = gl_FragCoord;\n"
            "                ^~~~~~~~~~~~\n"
            "help: 'gl_FragCoord' is a built-in of fragment shaders\n");
}

TEST(Glsl, ExtensionsAreLeftToTheDriver) {
  // Built-ins and types of extensions this checker does not model are not reported.
  EXPECT_EQ(plain("void main() { float s = subgroupAdd(1.0); int64_t big = int64_t(1); float t = fooEXT(s); }"), Messages{});
  EXPECT_EQ(plain("layout(origin_upper_left) in vec4 gl_FragCoord; layout(origin_upper_left) in vec4 gl_FragCoord;"
                  "out vec4 o; void main() { o = gl_FragCoord; }"),
            Messages{});
  EXPECT_EQ(plain("void main() { float s = subgroupAdd(undeclared); }"), Messages{"error: use of undeclared identifier 'undeclared'"});
}

TEST(Glsl, TypesAndConversions) {
  EXPECT_EQ(plain("void main() { float x = 1; double d = x; int i = 2; uint u = i; vec3 v = ivec3(1); }"), Messages{});
  EXPECT_EQ(plain("void main() { int i = 1.0; }"),
            Messages{"error: cannot initialize 'i' of type int with a value of type float<1>"});
  EXPECT_EQ(plain("void main() { vec3 v = vec2(1.0); }"),
            Messages{"error: cannot initialize 'v' of type vec3 with a value of type vec2<1>"});
  EXPECT_EQ(plain("void main() { vec3 v = vec3(1.0) + vec2(1.0); }"),
            Messages{"error: invalid operands to binary expression (vec3<1> and vec2<1>)"});
  EXPECT_EQ(plain("void main() { mat4 m = mat4(1.0); vec4 v = m * vec4(1.0); vec3 w = mat3(m) * v.xyz; mat2x3 a = mat2x3(1.0); vec3 b = a * vec2(1.0); }"),
            Messages{});
  EXPECT_EQ(plain("void main() { mat4 m = mat4(1.0); vec4 v = m * vec3(1.0); }"),
            Messages{"error: invalid operands to binary expression (mat4 and vec3<1>)"});
}

TEST(Glsl, Constructors) {
  EXPECT_EQ(plain("void main() { vec4 a = vec4(vec2(1.0), 0.0, 1.0); vec3 b = vec3(a); float c[2] = float[2](1.0, 2.0); }"), Messages{});
  EXPECT_EQ(plain("void main() { vec4 a = vec4(1.0, 2.0); }"), Messages{"error: too few components to construct vec4 (2 of 4)"});
  EXPECT_EQ(plain("void main() { vec2 a = vec2(1.0, 2.0, 3.0); }"), Messages{"error: too many arguments to constructor of vec2"});
  EXPECT_EQ(plain("struct S { float a; vec2 b; }; void main() { S s = S(1.0, vec2(0.0)); float x = s.b.y + s.a; S t = S(1.0); }"),
            Messages{"error: constructor of 'S' needs 2 arguments, found 1"});
}

TEST(Glsl, MembersSwizzlesIndexing) {
  EXPECT_EQ(plain("struct S { float a; }; void main() { S s = S(1.0); float x = s.b; }"), Messages{"error: no member named 'b' in 'S'"});
  EXPECT_EQ(plain("void main() { vec2 v = vec2(1.0); float x = v.z; }"), Messages{"error: invalid swizzle 'z' on vec2<1>"});
  EXPECT_EQ(plain("void main() { vec4 v = vec4(1.0); vec2 x = v.xg; }"), Messages{"error: invalid swizzle 'xg' on vec4<1>"});
  EXPECT_EQ(plain("void main() { float a[3]; float x = a[3]; float y = a[1.0]; }"),
            (Messages{"error: index 3 is out of range for float[3]", "error: array subscript is not an integer: float<1>"}));
  EXPECT_EQ(plain("void main() { float a[3]; int n = a.length(); vec4 v = vec4(1.0); float x = v[2] + float(v.length()); }"), Messages{});
}

TEST(Glsl, Statements) {
  EXPECT_EQ(plain("void main() { if (1.0) {} }"), Messages{"error: condition must be a bool, found float<1>"});
  EXPECT_EQ(plain("void main() { break; }"), Messages{"error: 'break' outside of a loop"});
  EXPECT_EQ(plain("void main() { for (int i = 0; i < 4; ++i) { if (i == 2) continue; } int k = 0; while (k < 3) k++; }"), Messages{});
  EXPECT_EQ(plain("float f() { return; } void g() { return 1.0; } void main() {}"),
            (Messages{"error: non-void function 'f' must return a value", "error: void function 'g' cannot return a value"}));
  EXPECT_EQ(plain("void main() { switch (1.0) { default: break; } }"), Messages{"error: switch selector must be int or uint, found float<1>"});
}

TEST(Glsl, Textures) {
  EXPECT_EQ(plain("uniform sampler2D t; uniform sampler2DShadow s; uniform samplerCube c; uniform isampler3D i; in vec2 uv;"
                  "void main() { vec4 a = texture(t, uv); float b = texture(s, vec3(uv, 0.5)); vec4 d = textureLod(c, vec3(1.0), 0.0);"
                  "ivec4 e = texelFetch(i, ivec3(0), 0); ivec2 sz = textureSize(t, 0); vec4 g = texture2D(t, uv); }"),
            Messages{});
  EXPECT_EQ(plain("uniform sampler2D t; void main() { float a = texture(t, vec2(0.0)); }"),
            Messages{"error: cannot initialize 'a' of type float with a value of type vec4"});
  EXPECT_EQ(plain("void main() { vec4 a = texture(vec2(0.0), vec2(0.0)); }"),
            Messages{"error: no matching overload for call to 'texture(vec2, vec2)'"});
}

// A local that starts at zero is an accumulator, but its GLSL type is still checked (piglit's
// initialization-incompatible-type-propagation-1.frag).
TEST(Glsl, ZeroStartKeepsGlslTypes) {
  EXPECT_EQ(plain("void main() { vec4 a = vec2(0.0); }"),
            Messages{"error: cannot initialize 'a' of type vec4 with a value of type vec2"});
  EXPECT_EQ(plain("void main() { vec3 a = vec3(0.0); a += vec3(1.0); }"), Messages{});
}

// GL_EXT_shader_explicit_arithmetic_types: glslang's conversions, literal suffixes, built-ins at every width.
TEST(Glsl, ExplicitArithmeticTypes) {
  // (check_source's words are GLSL 4.60's with every extension group: the types are keywords.)
  auto check = [&](const std::string& body) { return plain("void main() { " + body + " }"); };
  EXPECT_EQ(check("int8_t a = int8_t(1); int16_t b = a; int c = b; int64_t d = c; uint64_t e = d; double f = e;"), Messages{});
  EXPECT_EQ(check("uint8_t a = uint8_t(1); int b = a; uint16_t c = a; float16_t h = c; float f = h; double d = h;"), Messages{});
  EXPECT_EQ(check("int64_t a = 1l; uint64_t b = 1ul; int16_t c = 1s; uint16_t d = 1us; float16_t h = 1.0hf; double x = 1.0lf;"),
            Messages{});
  EXPECT_EQ(check("float16_t h = 1.0;"), Messages{"error: cannot initialize 'h' of type float16_t with a value of type float<1>"});
  EXPECT_EQ(check("int64_t a = 1l; int b = a;"), Messages{"error: cannot initialize 'b' of type int with a value of type int64_t<1>"});
  EXPECT_EQ(check("uint8_t u = uint8_t(1); int i = 2; uint r = i + u; int64_t q = i * 2l;"), Messages{});
  EXPECT_EQ(check("int64_t q = 1l; float f = 2.0; double d = f + q;"),
            Messages{"error: invalid operands to binary expression (float<1> and int64_t<1>)"});
  EXPECT_EQ(check("f16vec3 v = f16vec3(1.0hf); float16_t l = length(v); f16vec3 m = max(v, f16vec3(0.0hf)); i16vec3 e; v = frexp(v, e);"),
            Messages{});
  // A fixed parameter keeps its type (bitfieldExtract's int offsets); the result takes the call's width.
  EXPECT_EQ(check("int16_t a = 1s; int16_t b = bitfieldExtract(a, 0, 3); float16_t d = dot(f16vec2(1.0hf), f16vec2(2.0hf));"),
            Messages{});
  EXPECT_EQ(check("i64vec2 v = i64vec2(1l); i64vec2 a = abs(v); int64_t m = min(v.x, 3l);"), Messages{});
  // Folding wraps at 64 bits instead of trapping (glslang's constFoldIntMin.frag).
  EXPECT_EQ(plain("const int64_t a = -9223372036854775808L; const int64_t b = a / -1L; const int64_t c = a % -1L;"
                  "const int64_t d = a * a - a; const int64_t e = -a; const int64_t f = 1l << 63l; void main() {}"),
            Messages{});
  EXPECT_EQ(check("f16mat2x3 m = f16mat2x3(1.0hf); f16vec3 c = m[0]; f64vec2 d = dvec2(1.0lf); i32vec2 i = ivec2(1);"), Messages{});
}

}  // namespace
}  // namespace safegi::testing
