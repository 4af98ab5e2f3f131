// The public API: results for every expression and declaration, interface
// variables, cross-stage matching, and the exact rendering of a diagnostic.

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

TEST(Checker, PlainGlslChecksClean) {
  auto c = check_source(R"(uniform sampler2D tex;
uniform mat4 mvp;
in vec2 uv;
out vec4 color;
float luma(vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }
void main() {
  vec4 t = texture(tex, uv);
  float l = luma(t.rgb);
  vec3 n = normalize(vec3(uv, 1.0));
  color = vec4(mix(t.rgb, vec3(l), 0.5) * max(n.z, 0.0), 1.0);
  if (l < 0.1) discard;
}
)", {.prelude = false});
  EXPECT_EQ(c->rendered(), "");
}

TEST(Checker, DirectLightingShaderChecksClean) {
  auto c = check_source(R"(
space world;
uniform point<world> lightPos;
uniform spectrum<intensity> lightI;
in point<world> P;
in normal<world> N;
in spectrum<brdf> Kd;
out vec4 fragColor;
void main() {
  vector<world> toLight = lightPos - P;
  float<length> d = length(toLight);
  direction<world> wi = normalize(toLight);
  float<proj> cosTheta = max(dot(normalize(N), wi), 0.0);
  spectrum<radiance> L = Kd * lightI * cosTheta * float<solid_angle / (area * proj)>(1.0 / (d * d));
  fragColor = vec4(L, 1.0);
}
)");
  EXPECT_EQ(c->rendered(), "");
  EXPECT_EQ(declared_type(*c, "toLight"), "vector<world>");
  EXPECT_EQ(declared_type(*c, "cosTheta"), "float<proj>");
}

TEST(Checker, InterfaceVariablesAreListedWithTheirAnnotations) {
  auto c = check_source(R"(
space world;
layout(location = 2) in point<world> P;
uniform Light { spectrum<radiance> Le; float<area> A; } light;
uniform sampler2D<float<length>> shadowMap;
layout(binding = 3) uniform sampler2D plain;
out vec4 color;
void main() { color = vec4(0.0); }
)");
  ASSERT_EQ(c->rendered(), "");
  std::vector<std::string> got;
  for (const InterfaceVariable& v : c->result.interface)
    got.push_back(v.name + " : " + v.type_text + " @" + std::to_string(v.location) + "/" + std::to_string(v.binding) +
                  (v.annotated ? " annotated" : ""));
  EXPECT_EQ(got, (std::vector<std::string>{"P : point<world> @2/-1 annotated", "light.Le : spectrum<radiance> @-1/-1 annotated",
                                           "light.A : float<area> @-1/-1 annotated",
                                           "shadowMap : sampler2D<float<length>> @-1/-1 annotated",
                                           "plain : sampler2D @-1/3", "color : vec4 @-1/-1"}));
}

TEST(Checker, EveryExpressionHasAType) {
  auto c = check_source("void main() { float<length> d = 2.0 * meter; float<area> a = d * d; }");
  ASSERT_EQ(c->rendered(), "");
  std::size_t typed = 0;
  for (const auto& [node, type] : c->result.types)
    if (ast::isa<ast::Expr>(node) && !type.is_error()) ++typed;
  EXPECT_EQ(typed, 6u);  // 2.0, meter, 2.0 * meter, d, d, d * d
}

TEST(Checker, StrictModeWarnsOnUnannotatedInterfaceVariables) {
  auto c = check_source("uniform float exposure; uniform float<1> gain; in vec3 color; void main() {}", {.strict = true});
  EXPECT_EQ(c->messages(), (std::vector<std::string>{"warning: interface variable 'exposure' has no annotation",
                                                     "warning: interface variable 'color' has no annotation"}));
  auto lax = check_source("uniform float exposure; void main() {}");
  EXPECT_EQ(lax->rendered(), "");
}

TEST(Checker, RendersCaretsNotesAndHint) {
  auto c = check_source(R"(void main() {
  spectrum<radiance> Li = spectrum<radiance>(1.0);
  spectrum<brdf> f = spectrum<brdf>(0.3);
  float<solid_angle> dw = float<solid_angle>(0.1);
  spectrum<radiance> Lo = f * Li * dw;
}
)");
  EXPECT_EQ(c->rendered(),
            "test.frag:5:27: error: cannot initialize 'Lo' of type spectrum<radiance> with a value of type "
            "spectrum<energy·length⁻²·time⁻¹·solid_angle⁻¹·proj⁻²> [E-DIMENSION-MISMATCH]\n"
            "  spectrum<radiance> Lo = f * Li * dw;\n"
            "                     ~~   ^~~~~~~~~~~\n"
            "help: the value lacks a factor of proj: missing cosine factor, e.g. max(dot(n, wi), 0.0)?\n"
            "test.frag:5:22: note: 'Lo' declared here\n"
            "  spectrum<radiance> Lo = f * Li * dw;\n"
            "                     ^~\n");
}

}  // namespace
}  // namespace safegi::testing
