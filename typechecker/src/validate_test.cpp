// The validating rules (validate_*.cpp, docs/typechecker.md "Validation"):
// what GL drivers reject beyond the type rules, one test per rule, exact
// messages. Each case names the GLSL version it is checked at.

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

using Messages = std::vector<std::string>;

struct At {
  int version = 460;
  bool es = false;
  std::vector<std::string> extensions = {};
  bool compatibility = false;
};

Messages errors(std::string_view source, Stage stage, At at = {}) {
  LanguageLevel level{at.version, at.es, at.extensions, at.compatibility};
  return check_source(source, {.stage = stage, .prelude = false, .language = level})->messages();
}

Messages frag(std::string_view source, At at = {}) { return errors(source, Stage::fragment, at); }
Messages vert(std::string_view source, At at = {}) { return errors(source, Stage::vertex, at); }

TEST(Validate, QualifierCounts) {
  EXPECT_EQ(vert("in in float x; void main() {}"), Messages{"error: 'in' is given twice"});
  EXPECT_EQ(vert("const in float x = 1.0; void main() {}"),
            Messages{"error: a declaration takes at most one storage qualifier: 'const' and 'in'"});
  EXPECT_EQ(vert("flat smooth out float x; void main() {}"),
            Messages{"error: a declaration takes at most one interpolation qualifier (smooth, flat, noperspective): 'flat' and "
                     "'smooth'"});
  EXPECT_EQ(frag("centroid centroid in float x; void main() {}"), Messages{"error: 'centroid' is given twice"});
  EXPECT_EQ(vert("void f(in in float x) {} void main() {}"), Messages{"error: 'in' is given twice"});
  // The two pairs GLSL has: `varying out` (GL_EXT_gpu_shader4) and a parameter's `const in`.
  EXPECT_EQ(frag("varying out vec4 c; void main() { c = vec4(1.0); }", {110, false, {"GL_EXT_gpu_shader4"}}), Messages{});
  EXPECT_EQ(vert("float f(const in float x) { return x; } void main() {}"), Messages{});
}

TEST(Validate, QualifierOrderBefore420) {
  EXPECT_EQ(vert("smooth invariant out float x; void main() {}", {130}),
            Messages{"error: 'invariant' must come before 'smooth': before #version 420 (or GL_ARB_shading_language_420pack) "
                     "the order is invariant, interpolation, storage, precision"});
  EXPECT_EQ(vert("float f(highp in float x) { return x; } void main() {}", {130}),
            Messages{"error: 'in' must come before 'highp': before #version 420 (or GL_ARB_shading_language_420pack) the "
                     "order is invariant, interpolation, storage, precision"});
  EXPECT_EQ(vert("smooth invariant out float x; void main() {}", {420}), Messages{});
  EXPECT_EQ(vert("smooth invariant out float x; void main() {}", {130, false, {"GL_ARB_shading_language_420pack"}}), Messages{});
  // Interpolation and auxiliary qualifiers in either order (GL_EXT_gpu_shader4's `centroid noperspective varying`).
  EXPECT_EQ(frag("centroid noperspective in vec2 t; void main() {}", {130}), Messages{});
}

TEST(Validate, LocalsTakeOnlyConstAndPrecision) {
  EXPECT_EQ(frag("void main() { in float x; }"),
            Messages{"error: 'in' cannot qualify a local variable; locals take only 'const', 'precise' and a precision"});
  EXPECT_EQ(frag("void main() { smooth float x; }"),
            Messages{"error: 'smooth' cannot qualify a local variable; locals take only 'const', 'precise' and a precision"});
  EXPECT_EQ(vert("void main() { invariant gl_Position; }"),
            Messages{"error: 'invariant' can be applied to existing variables only at global scope"});
  EXPECT_EQ(frag("void main() { const highp float x = 1.0; precise float y = x; }"), Messages{});
  EXPECT_EQ(vert("inout float x; void main() {}"), Messages{"error: 'inout' qualifies only function parameters, not global variables"});
}

TEST(Validate, StructMembersTakeOnlyPrecision) {
  EXPECT_EQ(frag("struct S { centroid float a; }; void main() {}"),
            Messages{"error: 'centroid' cannot qualify a struct member; members take only a precision qualifier"});
  EXPECT_EQ(frag("struct S { layout(location = 0) float a; }; void main() {}"),
            Messages{"error: layout qualifiers cannot qualify a struct member; members take only a precision qualifier"});
  EXPECT_EQ(frag("struct S { struct T { float b; } t; }; void main() {}"),
            Messages{"error: a struct definition cannot be nested inside another struct"});
  EXPECT_EQ(frag("struct S { mediump float a; }; void main() {}"), Messages{});
}

TEST(Validate, Parameters) {
  EXPECT_EQ(frag("void f(const out float x) { } void main() {}"),
            Messages{"error: a 'const' parameter cannot be 'out': it could not be written"});
  EXPECT_EQ(frag("void f(centroid in float x) { } void main() {}"),
            Messages{"error: 'centroid' cannot qualify a function parameter; parameters take const, in, out, inout, precise, "
                     "memory and precision qualifiers"});
  EXPECT_EQ(frag("uniform sampler2D s; void f(out sampler2D t) { } void main() {}"),
            Messages{"error: an opaque type ('sampler2D') cannot be an 'out' parameter"});
  EXPECT_EQ(frag("uniform sampler2D s; sampler2D f() { return s; } void main() {}"),
            Messages{"error: a function cannot return an opaque type ('sampler2D')"});
  EXPECT_EQ(frag("int main() { return 0; }"), Messages{"error: 'main' must return void"});
  EXPECT_EQ(frag("void main(float x) { }"), Messages{"error: 'main' takes no parameters"});
}

TEST(Validate, OpaqueTypesAreUniformsOrParameters) {
  EXPECT_EQ(frag("sampler2D s; void main() {}"),
            Messages{"error: a variable of 'sampler2D' type must be 'uniform' (or a function parameter)"});
  EXPECT_EQ(frag("struct S { float x; sampler2D t; } g; void main() {}"),
            Messages{"error: a variable of a struct with an opaque member type must be 'uniform' (or a function parameter)"});
  EXPECT_EQ(frag("struct S { float x; sampler2D t; }; uniform S u; void main() {}"), Messages{});
  EXPECT_EQ(frag("uniform sampler2D u; void main() { sampler2D s = u; }", {450, false, {"GL_ARB_bindless_texture"}}),
            Messages{});
}

TEST(Validate, PrecisionStatements) {
  EXPECT_EQ(frag("precision mediump vec4; void main() {}"),
            Messages{"error: a default precision applies to 'float', 'int' and opaque types, not 'vec4'"});
  EXPECT_EQ(frag("precision mediump bool; void main() {}"),
            Messages{"error: a default precision applies to 'float', 'int' and opaque types, not 'bool'"});
  EXPECT_EQ(frag("precision mediump float; precision lowp sampler2D; void main() {}"), Messages{});
}

TEST(Validate, ReservedNames) {
  EXPECT_EQ(vert("out float gl_Foo; void main() {}"),
            Messages{"error: 'gl_Foo' is not a built-in variable here, and names beginning with 'gl_' are reserved"});
  EXPECT_EQ(vert("struct gl_S { float a; }; void main() {}"),
            Messages{"error: struct name 'gl_S' begins with 'gl_', which is reserved"});
  EXPECT_EQ(vert("void gl_f() {} void main() {}"), Messages{"error: function name 'gl_f' begins with 'gl_', which is reserved"});
  EXPECT_EQ(vert("out gl_B { float a; }; void main() {}"), Messages{"error: block name 'gl_B' begins with 'gl_', which is reserved"});
  EXPECT_EQ(vert("out B { float gl_a; }; void main() {}"),
            Messages{"error: member name 'gl_a' begins with 'gl_', which is reserved"});
  // Redeclaring a built-in is no reservation problem.
  EXPECT_EQ(frag("in vec4 gl_FragCoord; void main() {}"), Messages{});
}

Messages geom(std::string_view source, At at = {}) { return errors(source, Stage::geometry, at); }

TEST(Validate, InterfaceTypes) {
  EXPECT_EQ(vert("out bvec2 b; void main() {}"), Messages{"error: a shader output cannot be bool: 'b' is declared bvec2"});
  EXPECT_EQ(frag("in bool b; void main() {}"), Messages{"error: a shader input cannot be bool: 'b' is declared bool"});
  EXPECT_EQ(vert("smooth in vec4 p; void main() {}"),
            Messages{"error: 'smooth' cannot qualify a vertex shader input (vertex inputs are not interpolated)"});
  EXPECT_EQ(frag("centroid out vec4 c; void main() {}"),
            Messages{"error: 'centroid' cannot qualify a fragment shader output (fragment outputs are not interpolated)"});
  EXPECT_EQ(frag("out mat2 m; void main() {}"), Messages{"error: a fragment shader output cannot be a matrix: 'm' is declared mat2"});
  EXPECT_EQ(vert("struct S { float a; }; in S s; void main() {}"),
            Messages{"error: a vertex shader input cannot be a struct: 's' is declared S"});
  EXPECT_EQ(frag("in int i; void main() {}", {130}),
            Messages{"error: an integer or double fragment shader input must be 'flat': 'i' is declared int"});
  EXPECT_EQ(frag("flat in int i; void main() {}", {130}), Messages{});
}

TEST(Validate, VaryingTypesByVersion) {
  EXPECT_EQ(vert("varying int i; void main() {}", {120}),
            Messages{"error: integer varyings require #version 130 or GL_EXT_gpu_shader4: 'i' is declared int"});
  EXPECT_EQ(vert("attribute ivec2 a; void main() {}", {120}),
            Messages{"error: integer vertex shader inputs require #version 130 or GL_EXT_gpu_shader4: 'a' is declared ivec2"});
  EXPECT_EQ(vert("struct S { float a; }; out S s; void main() {}", {130}),
            Messages{"error: struct varyings require #version 150: 's' is declared S"});
  EXPECT_EQ(vert("out dvec2 d; void main() {}", {330}),
            Messages{"error: double-precision varyings require #version 400 or GL_ARB_gpu_shader_fp64: 'd' is declared dvec2"});
  EXPECT_EQ(vert("struct S { float a; }; out S s; flat out int i; void main() {}", {150}), Messages{});
  EXPECT_EQ(vert("flat varying int i; void main() {}", {110, false, {"GL_EXT_gpu_shader4"}}), Messages{});
}

TEST(Validate, InterfaceBlocks) {
  EXPECT_EQ(vert("in B { float a; }; void main() {}", {150}),
            Messages{"error: a vertex shader has no input blocks: vertex inputs are single variables"});
  EXPECT_EQ(frag("out B { vec4 a; }; void main() {}", {150}),
            Messages{"error: a fragment shader has no output blocks: fragment outputs are single variables"});
  EXPECT_EQ(vert("out B { float a; }; void main() {}", {140}), Messages{"error: 'out' blocks require #version 150 or GL_EXT_shader_io_blocks"});
  EXPECT_EQ(frag("uniform B { float a; }; void main() {}", {130}),
            Messages{"error: uniform blocks require #version 140 or GL_ARB_uniform_buffer_object"});
  EXPECT_EQ(frag("uniform B { float a; }; void main() {}", {130, false, {"GL_ARB_uniform_buffer_object"}}), Messages{});
  EXPECT_EQ(vert("uniform B { in float a; }; void main() {}", {150}),
            Messages{"error: member storage 'in' contradicts the block's 'uniform'"});
  EXPECT_EQ(vert("uniform B { sampler2D s; }; void main() {}", {150}),
            Messages{"error: a block member cannot have an opaque type ('sampler2D')"});
  EXPECT_EQ(vert("uniform B { struct S { float x; } s; }; void main() {}", {150}),
            Messages{"error: a struct cannot be defined inside a block"});
  EXPECT_EQ(geom("layout(points) in; in gl_PerVertex { vec4 gl_Position; } gl_in[]; void main() {}", {150}), Messages{});
}

TEST(Validate, ConstantExpressions) {
  EXPECT_EQ(vert("uniform int n; float a[n]; void main() {}"),
            Messages{"error: an array size must be a constant integer expression; 'n' is not constant"});
  EXPECT_EQ(vert("float a[2.0]; void main() {}"), Messages{"error: an array size must be a constant integer expression, not float"});
  EXPECT_EQ(vert("int f() { return 2; } float a[f()]; void main() {}"),
            Messages{"error: an array size must be a constant integer expression; the call of 'f' is not constant"});
  EXPECT_EQ(vert("float a[(5, 3)]; void main() {}", {120}),
            Messages{"error: an array size must be a constant integer expression; the comma operator is not constant"});
  EXPECT_EQ(vert("const int n = 2; const int m = n * 3; float a[m + int(abs(-1.0))]; void main() {}"), Messages{});
  EXPECT_EQ(vert("uniform float u; const float c = u; void main() {}"),
            Messages{"error: the initializer of const 'c' must be a constant expression; 'u' is not constant"});
  EXPECT_EQ(vert("uniform float u; void main() { const float c = u; }", {130}),
            Messages{"error: the initializer of const 'c' must be a constant expression; 'u' is not constant"});
  EXPECT_EQ(vert("uniform float u; void main() { const float c = u; }", {420}), Messages{});
  // GLSL ES 1.00 alone counts the comma operator as constant (Mesa).
  EXPECT_EQ(vert("const float f = (1.0, 2.0); void main() {}", {100, true}), Messages{});
  // GLSL ES initializes globals only with constants.
  EXPECT_EQ(vert("uniform float u; float g = u; void main() {}", {300, true}),
            Messages{"error: in GLSL ES the initializer of global 'g' must be a constant expression; 'u' is not constant"});
  EXPECT_EQ(vert("uniform float u; float g = u; void main() {}", {300, true, {"GL_EXT_shader_non_constant_global_initializers"}}),
            Messages{});
  EXPECT_EQ(vert("uniform float u; float g = u; void main() {}", {330}), Messages{});
}

TEST(Validate, SwitchBodies) {
  EXPECT_EQ(vert("void main() { int x = 1; switch (x) { x = 2; case 1: break; } }"),
            Messages{"error: a switch body must begin with a 'case' or 'default' label"});
  EXPECT_EQ(vert("void main() { switch (1) { case 0: } }"),
            Messages{"error: the last label of a switch must be followed by a statement"});
  EXPECT_EQ(vert("void main() { switch (1) { default: break; default: break; } }"),
            Messages{"error: a switch has at most one 'default' label"});
  EXPECT_EQ(vert("void main() { switch (1) { case 1: break; case 2 - 1: break; } }"), Messages{"error: duplicate case value 1"});
  EXPECT_EQ(vert("uniform int u; void main() { switch (1) { case u: break; } }"),
            Messages{"error: a case label must be a constant integer expression"});
  EXPECT_EQ(vert("void main() { uint x = 1u; switch (x) { case 1: break; } }", {130}),
            Messages{"error: case label of type int in a switch on uint; before #version 400 the types must be the same"});
  EXPECT_EQ(vert("void main() { uint x = 1u; switch (x) { case 1: break; } }", {400}), Messages{});
}

TEST(Validate, Subroutines) {
  const At at{150, false, {"GL_ARB_shader_subroutine"}};
  EXPECT_EQ(vert("subroutine void T(float x); subroutine (T) void a(float x) {} subroutine uniform T u; subroutine uniform T v[2];"
                 "void main() { u(1.0); v[1](2.0); a(3.0); }",
                 at),
            Messages{});
  EXPECT_EQ(vert("subroutine void T(); subroutine uniform T u; void main() { u(1.0); }", at),
            Messages{"error: no matching function for call to 'u(float<1>)'"});
  EXPECT_EQ(vert("subroutine void T(); subroutine (T) int f() { return 1; } void main() {}", at),
            Messages{"error: 'f' does not match subroutine type 'T': the return type and every parameter must be the same"});
  EXPECT_EQ(vert("subroutine (bogus) void f() {} void main() {}", at), Messages{"error: 'bogus' is not a subroutine type"});
  EXPECT_EQ(vert("subroutine void T(); subroutine (T) void f(); void main() {}", at),
            Messages{"error: a function implementing a subroutine type must be defined here, not only declared"});
  EXPECT_EQ(vert("subroutine void T(); void main() { T(); }", at), Messages{"error: cannot construct subroutine T"});
}

TEST(Validate, BuiltinFunctionsByVersionAndStage) {
  EXPECT_EQ(frag("uniform sampler2D s; void main() { gl_FragColor = texture(s, vec2(0.0)); }", {120}),
            Messages{"error: 'texture' requires #version 130; the shader is #version 120"});
  EXPECT_EQ(frag("uniform sampler2D s; out vec4 c; void main() { c = texture2D(s, vec2(0.0)); }", {420}),
            Messages{"error: 'texture2D' was removed in the core profile of #version 420"});
  EXPECT_EQ(frag("uniform sampler2D s; void main() { gl_FragColor = texture2D(s, vec2(0.0)); }", {420, false, {}, true}), Messages{});
  EXPECT_EQ(vert("void main() { gl_Position = vec4(dFdx(1.0)); }", {130}),
            Messages{"error: 'dFdx' is not available in vertex shaders"});
  EXPECT_EQ(frag("precision mediump float; void main() { gl_FragColor = vec4(dFdx(1.0)); }", {100, true}),
            Messages{"error: 'dFdx' requires #version 300 es or GL_OES_standard_derivatives; the shader is #version 100 es"});
  EXPECT_EQ(frag("precision mediump float; void main() { gl_FragColor = vec4(dFdx(1.0)); }",
                 {100, true, {"GL_OES_standard_derivatives"}}),
            Messages{});
  EXPECT_EQ(vert("void main() { int b = bitCount(1); }", {330}),
            Messages{"error: 'bitCount' requires #version 400 or GL_ARB_gpu_shader5; the shader is #version 330"});
  EXPECT_EQ(errors("layout(local_size_x = 1) in; void main() { float d = dFdx(1.0); }", Stage::compute,
                   {450, false, {"GL_NV_compute_shader_derivatives"}}),
            Messages{});
  EXPECT_EQ(vert("void main() { EmitVertex(); }", {150}), Messages{"error: 'EmitVertex' is not available in vertex shaders"});
}

TEST(Validate, BuiltinVariablesByVersionAndProfile) {
  EXPECT_EQ(vert("void main() { gl_Position = gl_Vertex; }", {140}),
            Messages{"error: 'gl_Vertex' belongs to the compatibility profile, which #version 140 does not have"});
  EXPECT_EQ(vert("void main() { gl_Position = gl_Vertex; }", {140, false, {"GL_ARB_compatibility"}}), Messages{});
  EXPECT_EQ(vert("void main() { gl_Position = gl_Vertex; }", {150, false, {}, true}), Messages{});
  EXPECT_EQ(vert("void main() { gl_Position = gl_Vertex; }", {130}), Messages{});
  EXPECT_EQ(frag("uniform gl_LightSourceParameters l; void main() {}", {150}),
            Messages{"error: 'gl_LightSourceParameters' belongs to the compatibility profile, which #version 150 does not have"});
  EXPECT_EQ(frag("void main() { gl_FragColor = vec4(1.0); }", {300, true}),
            Messages{"error: 'gl_FragColor' was removed in #version 300 es"});
  EXPECT_EQ(vert("void main() { gl_ClipDistance[0] = 1.0; }", {120}),
            Messages{"error: 'gl_ClipDistance' requires #version 130; the shader is #version 120"});
  EXPECT_EQ(vert("void main() { gl_Position = vec4(gl_InstanceIDARB); }", {120}),
            Messages{"error: 'gl_InstanceIDARB' requires GL_ARB_draw_instanced; the shader is #version 120"});
  EXPECT_EQ(vert("void main() { gl_Position = vec4(gl_InstanceIDARB); }", {120, false, {"GL_ARB_draw_instanced"}}), Messages{});
}

TEST(Validate, LayoutPlacement) {
  EXPECT_EQ(vert("layout(points) in; void main() {}", {150}),
            Messages{"error: layout 'points' belongs to geometry shaders, not to vertex shaders"});
  EXPECT_EQ(geom("layout(points) in vec4 p[]; void main() {}", {150}),
            Messages{"error: layout 'points' applies only to a declaration of its own: 'layout(points) in;'"});
  EXPECT_EQ(geom("layout(max_vertices = 3) in; void main() {}", {150}),
            Messages{"error: layout 'max_vertices' applies only to a declaration of its own: 'layout(max_vertices = N) out;'"});
  EXPECT_EQ(vert("layout(location = 0) attribute vec4 p; void main() {}", {120, false, {"GL_ARB_explicit_attrib_location"}}),
            Messages{"error: layout 'location' applies to 'in' and 'out' declarations, not to 'attribute'"});
  EXPECT_EQ(vert("layout(location = 1) out vec4 v; void main() {}", {330}),
            Messages{"error: layout 'location' on a shader input or output between stages requires #version 410 or "
                     "GL_ARB_separate_shader_objects"});
  EXPECT_EQ(vert("layout(location = 1) out vec4 v; void main() {}", {410}), Messages{});
  EXPECT_EQ(frag("layout(origin_upper_left) in vec4 p; void main() {}", {150}),
            Messages{"error: layout 'origin_upper_left' applies only to a redeclaration of gl_FragCoord"});
  EXPECT_EQ(frag("layout(origin_upper_left) in vec4 gl_FragCoord; void main() {}", {150}), Messages{});
  EXPECT_EQ(vert("layout(index = 1) out vec4 v; void main() {}", {330}),
            Messages{"error: layout 'index' applies only to fragment shader outputs"});
  EXPECT_EQ(frag("layout(binding = 1) uniform float f; void main() {}", {420}),
            Messages{"error: layout 'binding' applies to uniform and buffer blocks, samplers, images and atomic counters"});
  EXPECT_EQ(vert("layout(location = 0, location = 1) in vec4 p; void main() {}", {330}),
            Messages{"error: 'location' is given twice in one layout(...); repeating an identifier requires #version 440 or "
                     "GL_ARB_enhanced_layouts"});
  EXPECT_EQ(vert("layout(location = 0) layout(component = 1) out float p; void main() {}", {410}),
            Messages{"error: a second layout(...) on one declaration requires #version 420 or GL_ARB_shading_language_420pack"});
}

TEST(Validate, LayoutValues) {
  EXPECT_EQ(vert("layout(location = 1.0) in vec4 p; void main() {}", {330}),
            Messages{"error: the value of layout 'location' must be a constant integer, not float"});
  EXPECT_EQ(vert("uniform int u; layout(location = u) in vec4 p; void main() {}", {440}),
            Messages{"error: the value of layout 'location' must be a constant expression"});
  EXPECT_EQ(vert("layout(location = -1) in vec4 p; void main() {}", {440}),
            Messages{"error: layout 'location' must be non-negative, not -1"});
  EXPECT_EQ(errors("layout(local_size_x = 0) in; void main() {}", Stage::compute, {430}),
            Messages{"error: layout 'local_size_x' must be positive, not 0"});
  EXPECT_EQ(vert("layout(location) in vec4 p; void main() {}", {330}), Messages{"error: layout 'location' needs a value: 'location = N'"});
}

TEST(Validate, StageWideLayoutsAgree) {
  EXPECT_EQ(geom("layout(points) in; layout(line_strip, max_vertices = 2) out; layout(max_vertices = 3) out; void main() {}", {150}),
            Messages{"error: the max_vertices is 3 here but 2 before; every declaration must agree"});
  EXPECT_EQ(geom("layout(points) in; layout(triangles) in; void main() {}", {150}),
            Messages{"error: the input primitive is 'triangles' here but 'points' before; every declaration must agree"});
  // With GL_ARB_enhanced_layouts an identifier may repeat in one declaration: the last one counts.
  EXPECT_EQ(geom("layout(points) in; layout(max_vertices = 2, max_vertices = 3) out; layout(max_vertices = 3) out; void main() {}",
                 {150, false, {"GL_ARB_enhanced_layouts"}}),
            Messages{});
}

TEST(Validate, BlockOffsetsAndAlignment) {
  const At at{140, false, {"GL_ARB_enhanced_layouts"}};
  EXPECT_EQ(vert("layout(std140) uniform B { layout(offset = 0) float a; layout(offset = 6) float b; }; void main() {}", at),
            Messages{"error: layout 'offset' 6 of 'b' is not a multiple of its base alignment (4 bytes)"});
  EXPECT_EQ(vert("layout(std140) uniform B { layout(offset = 0) vec4 a; layout(offset = 8) vec4 b; }; void main() {}", at),
            Messages{"error: layout 'offset' 8 of 'b' is not a multiple of its base alignment (16 bytes)"});
  EXPECT_EQ(vert("layout(std140) uniform B { layout(offset = 16) vec4 a; layout(offset = 16) vec4 b; }; void main() {}", at),
            Messages{"error: layout 'offset' 16 of 'b' lies inside the member before it, which ends at byte 32"});
  EXPECT_EQ(vert("layout(shared) uniform B { layout(align = 16) vec4 a; }; void main() {}", at),
            Messages{"error: layout 'align' requires a std140 or std430 block, not a shared one"});
  EXPECT_EQ(vert("layout(std140) uniform B { layout(align = 12) vec4 a; }; void main() {}", at),
            Messages{"error: layout 'align' must be a power of two, not 12"});
  EXPECT_EQ(vert("layout(std140, align = 16) uniform B { layout(offset = 8, align = 8) vec2 a; layout(offset = 16) float b; };"
                 "void main() {}",
                 at),
            Messages{});
}

TEST(Validate, TransformFeedbackAndComponents) {
  const At at{150, false, {"GL_ARB_enhanced_layouts"}};
  EXPECT_EQ(vert("layout(xfb_offset = 2) out vec4 v; void main() {}", at),
            Messages{"error: layout 'xfb_offset' must be a multiple of 4"});
  EXPECT_EQ(vert("layout(xfb_offset = 16, xfb_stride = 20) out vec4 v; void main() {}", at),
            Messages{"error: what layout 'xfb_offset' 16 captures (16 bytes) overflows the buffer's stride of 20 bytes"});
  EXPECT_EQ(vert("layout(xfb_stride = 20) out vec4 a; layout(xfb_buffer = 0, xfb_stride = 32) out vec4 b; void main() {}", at),
            Messages{"error: the xfb_stride of buffer 0 is 32 here but 20 before; every declaration must agree"});
  EXPECT_EQ(vert("layout(xfb_buffer = 4) out vec4 v; void main() {}", at),
            Messages{"error: layout 'xfb_buffer' must be less than gl_MaxTransformFeedbackBuffers (4)"});
  EXPECT_EQ(vert("layout(xfb_buffer = 1) out B { vec4 a; layout(xfb_buffer = 0) vec4 b; }; void main() {}", at),
            Messages{"error: a block member's xfb_buffer 0 contradicts its block's (1)"});
  const At sso{150, false, {"GL_ARB_enhanced_layouts", "GL_ARB_separate_shader_objects"}};
  EXPECT_EQ(vert("layout(location = 0, component = 3) out vec2 v; void main() {}", sso),
            Messages{"error: component 3 of vec2 overflows the four components of a location"});
  EXPECT_EQ(vert("layout(component = 1) out float v; void main() {}", sso),
            Messages{"error: layout 'component' needs a 'location' on the same declaration"});
  EXPECT_EQ(vert("layout(location = 0, component = 1) out mat2 m; void main() {}", sso),
            Messages{"error: layout 'component' does not apply to a matrix, a struct or a block"});
}

TEST(Validate, OverlappingLocations) {
  const At sso{150, false, {"GL_ARB_separate_shader_objects"}};
  EXPECT_EQ(vert("layout(location = 0) out vec4 a[2]; layout(location = 1) out vec4 b; void main() {}", sso),
            Messages{"error: location 1 is already used by output 'a'"});
  EXPECT_EQ(vert("layout(location = 0) out dvec4 a; layout(location = 1) out vec4 b; void main() {}",
                 {150, false, {"GL_ARB_separate_shader_objects", "GL_ARB_gpu_shader_fp64"}}),
            Messages{"error: location 1 is already used by output 'a'"});
  EXPECT_EQ(frag("layout(location = 0) in vec4 a; layout(location = 1) in vec4 b; void main() {}", sso), Messages{});
  // Fragment outputs are checked against each other when linking (Mesa).
  EXPECT_EQ(frag("layout(location = 0) out vec4 a; layout(location = 0) out vec4 b; void main() {}", {330}), Messages{});
}

TEST(Validate, PerVertexInputsAreArrays) {
  EXPECT_EQ(geom("layout(points) in; in vec4 c; void main() {}", {150}),
            Messages{"error: a geometry shader input holds one value per vertex: declare 'c' as an array, e.g. 'c[]'"});
  EXPECT_EQ(geom("layout(points) in; in B { vec4 c; } b; void main() {}", {150}),
            Messages{"error: a geometry shader input block holds one value per vertex: give it an array instance, e.g. '} b[];'"});
  EXPECT_EQ(errors("layout(vertices = 3) out; out vec4 c; patch out vec4 p; void main() {}", Stage::tess_control, {400}),
            Messages{"error: a tessellation control shader output holds one value per vertex: declare 'c' as an array, e.g. 'c[]'"});
  EXPECT_EQ(geom("layout(points) in; in vec4 c[]; in B { vec4 d; } b[]; void main() {}", {150}), Messages{});
}

TEST(Validate, BuiltinRedeclarations) {
  EXPECT_EQ(vert("uniform float gl_ClipDistance[4]; void main() {}", {130}),
            Messages{"error: 'gl_ClipDistance' can only be redeclared as an 'out' of a vertex shader"});
  EXPECT_EQ(frag("out float gl_ClipDistance[4]; void main() {}", {130}),
            Messages{"error: 'gl_ClipDistance' can only be redeclared as an 'in' of a fragment shader"});
  EXPECT_EQ(vert("out vec2 gl_ClipDistance[4]; void main() {}", {130}),
            Messages{"error: 'gl_ClipDistance' is redeclared as vec2[4]; it must stay an array of float"});
  EXPECT_EQ(vert("out float gl_ClipDistance[gl_MaxClipDistances + 1]; void main() {}", {130}),
            Messages{"error: 'gl_ClipDistance' is redeclared with 9 elements; it may have at most gl_MaxClipDistances (8)"});
  EXPECT_EQ(vert("out float gl_ClipDistance[4]; varying vec4 gl_TexCoord[2]; void main() {}", {130}), Messages{});
  EXPECT_EQ(frag("vec4 p = gl_FragCoord; layout(origin_upper_left) in vec4 gl_FragCoord; void main() {}", {150}),
            Messages{"error: gl_FragCoord must be redeclared before it is used"});
  EXPECT_EQ(frag("layout(origin_upper_left) in vec4 gl_FragCoord; in vec4 gl_FragCoord; void main() {}", {150}),
            Messages{"error: gl_FragCoord is redeclared with no layout, but was with layout(origin_upper_left) before; every "
                     "redeclaration must agree"});
  EXPECT_EQ(frag("layout(origin_upper_left) in vec4 gl_FragCoord; vec4 p = gl_FragCoord; "
                 "layout(origin_upper_left) in vec4 gl_FragCoord; void main() {}",
                 {150}),
            Messages{});
}

TEST(Validate, Lvalues) {
  EXPECT_EQ(vert("void main() { float a[2]; float b[2]; a = b; }", {110}),
            Messages{"error: an array cannot be assigned as a whole in GLSL 1.10"});
  EXPECT_EQ(vert("void main() { float a[2]; float b[2]; a = b; }", {120}), Messages{});
  EXPECT_EQ(vert("buffer B { readonly float f; } b; void main() { b.f = 1.0; }", {430}),
            Messages{"error: cannot assign to readonly member 'f'"});
  // The member assigned and the read-only instance it belongs to are both named.
  EXPECT_EQ(vert("readonly buffer B { float f; } b; void main() { b.f = 1.0; }", {430}),
            Messages{"error: cannot assign to 'b.f': 'b' is a read-only variable"});
  EXPECT_EQ(frag("in Surface { vec3 P[2]; } fs_in; void main() { fs_in.P[1] = vec3(0.0); }", {330}),
            Messages{"error: cannot assign to 'fs_in.P[1]': 'fs_in' is a read-only variable"});
  EXPECT_EQ(frag("void main() { gl_ClipDistance[0] = 1.0; }", {130}),
            Messages{"error: cannot assign to read-only variable 'gl_ClipDistance'"});
  EXPECT_EQ(vert("void main() { gl_MultiTexCoord4 = vec4(1.0); }", {110}),
            Messages{"error: cannot assign to read-only variable 'gl_MultiTexCoord4'"});
  const char* tesc = "layout(vertices = 3) out; out vec4 x[]; uniform int n; void main() { x[%s] = vec4(1.0); }";
  auto at = [&](const char* index) {
    std::string s = tesc;
    s.replace(s.find("%s"), 2, index);
    return errors(s, Stage::tess_control, {400});
  };
  EXPECT_EQ(at("gl_InvocationID"), Messages{});
  EXPECT_EQ(at("n"), Messages{"error: a tessellation control shader writes its per-vertex output 'x' only at [gl_InvocationID]"});
  EXPECT_EQ(errors("layout(vertices = 3) out; void main() { gl_out[0].gl_Position = vec4(1.0); }", Stage::tess_control, {400}),
            Messages{"error: a tessellation control shader writes its per-vertex output 'gl_out' only at [gl_InvocationID]"});
}

TEST(Validate, ComputeShadersNeedTheirVersion) {
  EXPECT_EQ(errors("layout(local_size_x = 1) in; void main() {}", Stage::compute, {330}),
            Messages{"error: compute shaders require #version 430 or GL_ARB_compute_shader; the shader is #version 330"});
  EXPECT_EQ(errors("layout(local_size_x = 1) in; void main() {}", Stage::compute, {330, false, {"GL_ARB_compute_shader"}}),
            Messages{});
  EXPECT_EQ(errors("layout(local_size_x = 1) in; void main() {}", Stage::compute, {310, true}), Messages{});
  // Geometry shaders are not gated (piglit's glsl-1.50/compiler/uniforms.geom has no #version).
  EXPECT_EQ(geom("void main() {}", {110}), Messages{});
}

TEST(Validate, BarrierAndInterlockPlacement) {
  const At tess{400};
  auto tesc = [&](std::string body) {
    return errors("layout(vertices = 3) out; uniform bool u; void f() {} " + body, Stage::tess_control, tess);
  };
  EXPECT_EQ(tesc("void main() { barrier(); }"), Messages{});
  EXPECT_EQ(tesc("void main() { if (u) barrier(); }"),
            Messages{"error: 'barrier()' may be called only outside control flow (if, loops, switch)"});
  EXPECT_EQ(tesc("void g() { barrier(); } void main() { g(); }"), Messages{"error: 'barrier()' may be called only in main()"});
  EXPECT_EQ(tesc("void main() { if (u) return; barrier(); }"),
            Messages{"error: 'barrier()' may be called only before a return from main()"});
  EXPECT_EQ(tesc("void main() { return; barrier(); }"), Messages{"error: 'barrier()' may be called only before a return from main()"});
  const At interlock{450, false, {"GL_ARB_fragment_shader_interlock"}};
  EXPECT_EQ(frag("void main() { beginInvocationInterlockARB(); endInvocationInterlockARB(); }", interlock), Messages{});
  EXPECT_EQ(frag("void main() { beginInvocationInterlockARB(); beginInvocationInterlockARB(); }", interlock),
            Messages{"error: 'beginInvocationInterlockARB()' may be called only once"});
  EXPECT_EQ(frag("void main() { endInvocationInterlockARB(); }", interlock),
            Messages{"error: 'endInvocationInterlockARB()' must follow beginInvocationInterlockARB()"});
  EXPECT_EQ(frag("void main() { for (int i = 0; i < 2; ++i) beginInvocationInterlockARB(); }", interlock),
            Messages{"error: 'beginInvocationInterlockARB()' may be called only outside control flow (if, loops, switch)"});
}

// Issue 46: built-ins an extension brings to a stage, and memory written through references.
TEST(Validate, LayerAndViewportIndexFromVertexShadersWithAnExtension) {
  for (const char* e : {"GL_ARB_shader_viewport_layer_array", "GL_NV_viewport_array2"}) {
    EXPECT_EQ(vert("void main() { gl_Layer = 1; gl_ViewportIndex = 2; }", {450, false, {e}}), Messages{}) << e;
    EXPECT_EQ(errors("layout(triangles) in; void main() { gl_Layer = 1; gl_ViewportIndex = 2; }", Stage::tess_evaluation,
                     {450, false, {e}}),
              Messages{})
        << e;
  }
  // Mesa's AMD extensions: one variable each, vertex shaders only.
  EXPECT_EQ(vert("void main() { gl_Layer = 1; }", {450, false, {"GL_AMD_vertex_shader_layer"}}), Messages{});
  EXPECT_EQ(vert("void main() { gl_ViewportIndex = 1; }", {450, false, {"GL_AMD_vertex_shader_layer"}}),
            Messages{"error: 'gl_ViewportIndex' in vertex shaders requires GL_ARB_shader_viewport_layer_array or "
                     "GL_NV_viewport_array2"});
  EXPECT_EQ(vert("void main() { gl_Layer = 1; }"),
            Messages{"error: 'gl_Layer' in vertex shaders requires GL_ARB_shader_viewport_layer_array or GL_NV_viewport_array2"});
  EXPECT_EQ(errors("layout(vertices = 3) out; void main() { gl_Layer = 1; }", Stage::tess_control,
                   {450, false, {"GL_ARB_shader_viewport_layer_array"}}),
            Messages{"error: 'gl_Layer' is not available in tessellation control shaders"});
}

TEST(Validate, MemoryReachedThroughAReadOnlyReferenceIsWritable) {
  const At references{460, false, {"GL_EXT_buffer_reference"}};
  const std::string blocks =
      "layout(buffer_reference) buffer Counts { uint v[]; readonly uint fixed_count; };\n"
      "layout(buffer_reference) readonly buffer Frozen { uint v[]; };\n"
      "uniform Refs { Counts counts; Frozen frozen; } refs;\n";
  auto comp = [&](const std::string& body) { return errors(blocks + "void main() { " + body + " }", Stage::compute, references); };
  EXPECT_EQ(comp("refs.counts.v[0] = 1u; refs.counts.v[1]++; atomicAdd(refs.counts.v[2], 1u);"), Messages{});
  EXPECT_EQ(comp("refs.counts.fixed_count = 1u;"),
            Messages{"error: cannot assign to 'refs.counts.fixed_count': it is readonly memory of the buffer_reference block "
                     "'Counts'"});
  EXPECT_EQ(comp("Frozen f = refs.frozen; f.v[0] = 1u;"),
            Messages{"error: cannot assign to 'f.v[0]': it is readonly memory of the buffer_reference block 'Frozen'"});
  EXPECT_EQ(comp("refs.counts = Counts(refs.frozen);"),
            Messages{"error: cannot assign to 'refs.counts': 'refs' is a read-only variable"});
}

}  // namespace
}  // namespace safegi::testing
