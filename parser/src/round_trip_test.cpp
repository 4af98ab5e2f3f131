// Round trip: parse -> print -> parse gives the same tree (compared as
// dumps), and glslang accepts the printed GLSL.

#include <cstdio>
#include <sstream>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

struct Sample {
  const char* name;
  const char* stage;
  const char* source;  // without #version: the preamble adds "#version 460"
  const char* extensions = "";  // #extension lines for glslang (the raw lexer of the tests skips no directives)
};

const Sample kSamples[] = {
    {"vertex_interface", "vert", R"(
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(std140, binding = 0) uniform Camera { mat4 view; mat4 projection; } camera;
out VertexData { smooth vec3 n; flat int id; noperspective vec2 uv; } vd;
invariant gl_Position;
void main() {
    vd.n = mat3(camera.view) * normal;
    vd.id = gl_VertexID;
    vd.uv = position.xy * 0.5 + 0.5;
    gl_Position = camera.projection * camera.view * vec4(position, 1.0);
}
)"},
    {"fragment_everything", "frag", R"(
precision highp float;
struct Material { vec3 albedo; float roughness[2]; };
struct { int a; } anonymous;
const float table[3] = float[3](1.0, 2.0, 3.0);
const vec2 pairs[2] = {vec2(0.0), vec2(1.0, 2.0)};
uniform Material materials[4];
uniform sampler2D tex;
uniform sampler2DShadow shadow;
layout(location = 0) out vec4 color;
in vec2 uv;
float helper(in float x, out float y, inout float z);
float helper(in float x, out float y, inout float z) { y = x; z += x; return x * y; }
int bits(uint u, int s) { return int(u >> 2u) << s | s & 3 ^ ~s; }
void main() {
    float acc = 0.0, unused;
    int i = 0;
    for (int k = 0; k < 4; ++k) {
        if (k == 2) continue;
        else if (k > 10) break;
        acc += materials[k].roughness[1];
    }
    while (acc > 10.0) acc -= 1.0;
    do { i++; } while (i < 3);
    switch (i) {
    case 0:
    case 1 + 2:
        acc *= 2.0;
        break;
    default:
        acc /= 2.0;
    }
    float y, z = 1.0;
    acc = helper(acc, y, z);
    bool b = acc > 1.0 ^^ y < 2.0 || !(z == 0.0) && true;
    acc = b ? acc : -acc;
    acc = (acc, acc + 1.0);
    vec4 t = texture(tex, uv) + vec4(texture(shadow, vec3(uv, 0.5)));
    color = vec4(materials[0].albedo * acc, 1.0) + t * float(table.length()) + vec4(pairs[1], 0.0, 0.0);
    if (color.a < 0.0) discard;
    color.rgb = - -color.bgr;
    i = bits(3u, i) % 7;
}
)"},
    {"compute_buffers_images", "comp", R"(
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(std430, binding = 1) restrict buffer Data { uint count; float values[]; } data;
layout(binding = 2, rgba32f) uniform coherent writeonly image2D result;
layout(binding = 3, r32ui) uniform uimage2D counters;
shared float cache[64];
void main() {
    uvec2 id = gl_GlobalInvocationID.xy;
    cache[gl_LocalInvocationIndex] = data.values[id.x];
    memoryBarrierShared();
    barrier();
    uint old = imageAtomicAdd(counters, ivec2(id), 1u);
    imageStore(result, ivec2(id), vec4(cache[0], float(old), float(data.values.length()), 1.0));
    atomicAdd(data.count, 1u);
}
)"},
    {"geometry_arrays", "geom", R"(
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in VertexData { vec3 n; } inData[];
out vec3 gn;
float grid[2][3];
void main() {
    for (int i = 0; i < gl_in.length(); i++) {
        gn = inData[i].n + vec3(grid[1][2]);
        gl_Position = gl_in[i].gl_Position;
        EmitVertex();
    }
    EndPrimitive();
}
)"},
    {"tessellation_control", "tesc", R"(
layout(vertices = 3) out;
patch out vec4 extra;
void main() {
    gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
    gl_TessLevelOuter[0] = 1.0;
    gl_TessLevelInner[0] = 1.0;
    extra = vec4(1.0);
}
)"},
    {"debug_printf", "frag", R"(
in float x;
void main() { debugPrintfEXT("x = %f", x); }
)", "#extension GL_EXT_debug_printf : enable\n"},
    // glslang does not implement subroutines, so they are tested in parse_decl_test only.
    {"precise", "frag", R"(
in vec3 n;
out vec4 c;
precise float p;
void main() {
    precise vec4 q = vec4(n, 1.0);
    c = q;
    p = 1.0;
}
)"},
    // Issue 46: GL_EXT_control_flow_attributes and GL_EXT_null_initializer.
    {"control_flow_attributes_and_null_initializers", "frag", R"(
in float x;
out vec4 c;
struct S { float a; vec2 b; };
void main() {
    S s = {};
    float t = {};
    [[unroll]] for (int i = 0; i < 4; ++i) t += x;
    [[dont_unroll, dependency_length(2 + 2)]] while (t > 9.0) t -= 1.0;
    [[loop]] do { t *= 0.5; } while (t > 2.0);
    [[flatten]] if (x > 0.5) t += 1.0; else [[branch]] if (x < 0.1) t -= 1.0;
    [[branch]] switch (int(x)) { case 0: t += 2.0; break; default: break; }
    c = vec4(s.b, s.a, t);
}
)", "#extension GL_EXT_control_flow_attributes : enable\n#extension GL_EXT_null_initializer : enable\n"},
    {"doubles_and_literals", "frag", R"(
out vec4 c;
void main() {
    double d = 1.0lf + 2.5LF;
    dvec2 v = dvec2(d);
    uint u = 0xFFu + 017u + 0u;
    int i = 0x7f - 010;
    float f = 1e3 + 1.5E-2 + .5 + 3. + 2.0f;
    c = vec4(float(v.x), float(u), float(i), f);
}
)"},
};

void PrintTo(const Sample& sample, std::ostream* os) { *os << sample.name; }

class RoundTrip : public ::testing::TestWithParam<Sample> {};

TEST_P(RoundTrip, PrintThenParseGivesTheSameTree) {
  const Sample& sample = GetParam();
  auto first = parse_text(sample.source);
  ASSERT_FALSE(first->diagnostics.has_errors()) << first->errors();
  std::string printed = first->glsl();
  auto second = parse_text(printed);
  ASSERT_FALSE(second->diagnostics.has_errors()) << second->errors() << printed;
  EXPECT_EQ(first->dump(), second->dump()) << printed;
  EXPECT_EQ(second->glsl(), printed);  // printing is a fixed point after one round
}

TEST_P(RoundTrip, GlslangAcceptsTheOriginalAndThePrintedGlsl) {
  const Sample& sample = GetParam();
  std::string log;
  std::string preamble = std::string("#version 460\n") + sample.extensions;
  ASSERT_TRUE(glslang_accepts(preamble + sample.source, sample.stage, &log)) << log;
  auto parsed = parse_text(sample.source);
  PrintOptions options;
  options.preamble = preamble;
  EXPECT_TRUE(glslang_accepts(print_glsl(parsed->unit(), options), sample.stage, &log)) << log;
}

// Every node carries a range, and begin <= end.
TEST_P(RoundTrip, EveryNodeHasASourceRange) {
  auto parsed = parse_text(GetParam().source);
  DumpOptions options;
  options.ranges = true;
  std::istringstream dump(dump_ast(parsed->unit(), options));
  int nodes = 0;
  for (std::string line; std::getline(dump, line);) {
    std::size_t at = line.find(" @");
    ASSERT_NE(at, std::string::npos) << line;
    unsigned l1 = 0, c1 = 0, l2 = 0, c2 = 0;
    ASSERT_EQ(std::sscanf(line.c_str() + at + 2, "%u:%u-%u:%u", &l1, &c1, &l2, &c2), 4) << line;
    EXPECT_GT(l1, 0u) << line;
    EXPECT_GT(c1, 0u) << line;
    EXPECT_TRUE(l1 < l2 || (l1 == l2 && c1 <= c2)) << line;
    ++nodes;
  }
  EXPECT_GT(nodes, 5);
}

INSTANTIATE_TEST_SUITE_P(Samples, RoundTrip, ::testing::ValuesIn(kSamples),
                         [](const auto& info) { return std::string(info.param.name); });

constexpr const char* kAnnotatedShader = R"(
dimension length; dimension time; dimension energy; dimension angle; dimension solid_angle; dimension proj;
dimension area = length^2;
dimension power = energy / time;
dimension intensity = power / solid_angle;
dimension irradiance = power / area;
dimension radiance = irradiance / (solid_angle * proj);
dimension brdf = 1 / (solid_angle * proj);
unit centimeter : length = 0.01;
space world;
space light_s;
space clip;
uniform map<world, light_s> lightFromWorld;
uniform projmap<light_s, clip> clipFromLight;
uniform point<world> lightPos;
uniform spectrum<intensity> lightI;
uniform sampler2D<float<length>> shadowMap;
in point<world> P;
in normal<world> N;
in spectrum<brdf> Kd;
out vec4 fragColor;
template<dimension D>
spectrum<D> attenuate(spectrum<D> x, float<1> visibility) { return x * visibility; }
void main() {
    vector<world> toLight = lightPos - P;
    float<length> d = length(toLight) + 2.0 * centimeter;
    direction<world> wi = normalize(toLight);
    float<proj> cosTheta = max(dot(normalize(N), wi), 0.0);
    spectrum<irradiance> E = lightI * float<solid_angle>(1.0 / (d * d)) * cosTheta / float<solid_angle * proj>(1.0);
    float<length> occluder = texture(shadowMap, vec2(0.5)).r;
    spectrum<radiance> L = attenuate(Kd * E, occluder > d ? 1.0 : 0.0);
    fragColor = vec4(L, 1.0);
}
)";

TEST(RoundTripAnnotated, PrintThenParseGivesTheSameTree) {
  auto first = parse_text(kAnnotatedShader);
  ASSERT_FALSE(first->diagnostics.has_errors()) << first->errors();
  auto second = parse_text(first->glsl());
  ASSERT_FALSE(second->diagnostics.has_errors()) << second->errors() << first->glsl();
  EXPECT_EQ(first->dump(), second->dump());
}

TEST(RoundTripAnnotated, PrintedWithoutAnnotationsIsPlainGlslThatGlslangAccepts) {
  auto parsed = parse_text(kAnnotatedShader);
  PrintOptions options;
  options.annotations = false;
  options.preamble = "#version 330 core\n";
  std::string plain = print_glsl(parsed->unit(), options);
  std::string log;
  EXPECT_TRUE(glslang_accepts(plain, "frag", &log)) << log;
  EXPECT_EQ(plain.find("dimension"), std::string::npos) << plain;
  EXPECT_EQ(plain.find("template"), std::string::npos) << plain;
  EXPECT_NE(plain.find("uniform mat4 lightFromWorld;"), std::string::npos) << plain;
  EXPECT_NE(plain.find("uniform sampler2D shadowMap;"), std::string::npos) << plain;
  EXPECT_NE(plain.find("2.0 * (0.01)"), std::string::npos) << plain;
}

TEST(Printer, LayoutOfPrintedGlsl) {
  auto parsed = parse_text(
      "layout(std140) uniform B { mat4 m; } b; struct S { float x; };"
      "float f(float a) { if (a > 0.0) return a; else if (a < -1.0) { a = 1.0; } else a = 2.0;"
      " switch (int(a)) { case 1: a = - -a; break; default: break; } for (int i = 0; i < 2; ++i) a += 1.0;"
      " do a *= 2.0; while (a < 8.0); return a; }");
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
  EXPECT_EQ(parsed->glsl(),
            "layout(std140) uniform B {\n"
            "    mat4 m;\n"
            "} b;\n"
            "struct S {\n"
            "    float x;\n"
            "};\n"
            "float f(float a) {\n"
            "    if (a > 0.0)\n"
            "        return a;\n"
            "    else if (a < -1.0) {\n"
            "        a = 1.0;\n"
            "    }\n"
            "    else\n"
            "        a = 2.0;\n"
            "    switch (int(a)) {\n"
            "        case 1:\n"
            "            a = - -a;\n"
            "            break;\n"
            "        default:\n"
            "            break;\n"
            "    }\n"
            "    for (int i = 0; i < 2; ++i)\n"
            "        a += 1.0;\n"
            "    do\n"
            "        a *= 2.0;\n"
            "    while (a < 8.0);\n"
            "    return a;\n"
            "}\n");
}

}  // namespace
}  // namespace safegi::testing
