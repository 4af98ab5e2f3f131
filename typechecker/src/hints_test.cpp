// Hints chosen from the whole expression (issue #21): each names the cause,
// and where it offers code, that code compiles in place of the mistake.

#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "test_support.hpp"

namespace safegi {
namespace {

using testing::check_source;

struct HintCase {
  const char* name;
  std::string declarations;  // globals both programs share
  std::string mistake;       // the statement with the mistake, with @ where the mistaken expression stands
  std::string wrong;         // the mistaken expression
  std::string cause;         // what the help must say
  std::string suggestion;    // the code the help offers, x standing for `wrong` ("" when it offers none)
  std::string fixed = {};    // the mistake with the suggestion applied, when x does not stand for all of it
};

std::string program(const HintCase& c, const std::string& expression) {
  std::string statement = c.mistake;
  statement.replace(statement.find('@'), 1, expression);
  return "space world;\n" + c.declarations + "\nout vec4 color;\nvoid main() {\n  " + statement + "\n  color = vec4(0.0);\n}\n";
}

std::string first_hint(const testing::CheckedSource& c) {
  for (const Diagnostic& d : c.diagnostics.diagnostics())
    if (d.severity == Severity::error) return d.hint;
  return "(no error)";
}

class Hints : public ::testing::TestWithParam<HintCase> {};

TEST_P(Hints, NameTheCauseAndTheirCodeCompiles) {
  const HintCase& c = GetParam();
  auto wrong = check_source(program(c, c.wrong));
  ASSERT_EQ(wrong->errors(), 1u) << wrong->rendered();
  const std::string hint = first_hint(*wrong);
  EXPECT_NE(hint.find(c.cause), std::string::npos) << hint;
  if (c.suggestion.empty()) return;
  EXPECT_NE(hint.find(c.suggestion), std::string::npos) << hint;
  // The suggestion in place of the mistake: x stands for the mistaken expression, unless the case spells the fix out.
  const std::string fixed =
      c.fixed.empty() ? std::regex_replace(c.suggestion, std::regex("\\bx\\b"), "(" + c.wrong + ")") : c.fixed;
  auto right = check_source(program(c, fixed));
  EXPECT_EQ(right->errors(), 0u) << "suggested: " << fixed << "\n" << right->rendered();
}

const char* const kArcminutes = "unit arcminute : angle = degree / 60.0; uniform float<angle in arcminute> tilt;";
const char* const kShaded =
    "uniform point<world> lightPos; uniform point<world> eyePos; in point<world, shaded> P; uniform normal<world> n;"
    " uniform direction<world, away> wo;";
const char* const kModel =
    "space object; uniform map<object, world> model; uniform normal<object> nObj; uniform point<object> pObj;";
const char* const kLight = "uniform spectrum<1> albedo; uniform spectrum<brdf> specular; uniform spectrum<irradiance> E;";

INSTANTIATE_TEST_SUITE_P(
    FromTheWholeExpression, Hints,
    ::testing::Values(
        HintCase{"lambert_without_pi", kLight, "spectrum<radiance> L = (@ + specular) * E;", "albedo", "missing 1/π",
                 "x * float<brdf>(1.0 / 3.14159265)"},
        HintCase{"ggx_without_pi", "uniform float<1> a2; uniform float<1> denom;", "float<brdf> D = @;", "a2 / (denom * denom)",
                 "missing 1/π", "x * float<brdf>(1.0 / 3.14159265)"},
        HintCase{"lobe_without_pi", "uniform float<1> lobe; uniform spectrum<irradiance> E;", "spectrum<radiance> L = @;",
                 "lobe * E", "'lobe' is a plain number", "lobe * float<brdf>(1.0 / 3.14159265)",
                 "lobe * float<brdf>(1.0 / 3.14159265) * E"},
        // π to two places is no π constant (a literal kπ is: docs/language.md, "Gradual typing"), so these
        // solid angles are plain numbers that need their unit.
        HintCase{"cone_without_steradian", "uniform float<1> cosMax;", "float<solid_angle> cone = @;", "2.0 * 3.14 * (1.0 - cosMax)",
                 "give it its unit", "x * steradian"},
        HintCase{"phase_without_steradian", "uniform float<1> g; uniform float<1> hg;", "float<pdf_solid_angle> phase = @;",
                 "(1.0 - g * g) / (4.0 * 3.14 * hg)", "per steradian", "x / steradian"},
        HintCase{"jacobian_without_light_cosine",
                 "uniform float<area> lightArea; uniform float<solid_angle / (area * proj)> invR2;",
                 "float<pdf_solid_angle> pdf = @;", "1.0 / (lightArea * invR2)", "light-side cos θ", ""},
        HintCase{"area_light_as_a_point", "uniform spectrum<radiance> Le; uniform spectrum<brdf> f; uniform float<length> d;"
                 " uniform float<area> A; uniform float<proj> cosLight; uniform float<proj> cosSurf;",
                 "spectrum<radiance> L = @;", "f * Le * cosSurf * inverse_square(d)", "the emitter's projected area", ""},
        HintCase{"angle_given_its_unit_twice", "uniform float<angle in degree> coneDeg;", "float c = cos(@);", "coneDeg * degree",
                 "'coneDeg' already is angle", "coneDeg in radian",
                 "coneDeg in radian"},
        HintCase{"dimensionless_in_two_units", "uniform float<length> d; uniform float<length in centimeter> reachCm;",
                 "float<1> fade = @;", "d / reachCm", "where it enters", "x in (1)"},
        HintCase{"unit_converted_where_it_enters", "uniform float<length> d; uniform float<length in centimeter> reachCm;",
                 "float<1> fade = @;", "d / reachCm", "convert 'reachCm' where it enters", "reachCm in meter",
                 "d / (reachCm in meter)"},
        HintCase{"direction_plus_length_vector", "uniform direction<world> V; uniform vector<world> toL;",
                 "direction<world> H = normalize(@);", "V + toL", "normalize it first", "normalize(toL)",
                 "V + normalize(toL)"},
        HintCase{"unit_of_another_dimension", "", "float<length> r = @;", "5.0 * degree", "measures angle, not length",
                 "x * meter", "5.0 * meter"},
        HintCase{"intensity_without_falloff", "uniform spectrum<intensity> I; uniform float<proj> c;",
                 "spectrum<irradiance> E = @;", "I * c", "missing the inverse-square falloff", ""},
        HintCase{"solid_angle_of_the_sphere_as_a_number", "uniform spectrum<power> Phi;", "spectrum<intensity> I = @;",
                 "Phi / (4.0 * 3.14)", "written as a plain number", "x * steradian", "Phi / (4.0 * 3.14 * steradian)"},
        HintCase{"plain_number_for_a_length", "", "float<length> bias = @;", "0.05", "give it its unit", "x * meter"},
        HintCase{"angle_in_a_third_unit_into_radians", kArcminutes, "float<angle> t = @;", "radians(tilt)",
                 "an angle in arcminute converts with in", "tilt in radian", "tilt in radian"},
        HintCase{"angle_in_a_third_unit_into_degrees", kArcminutes, "float<angle in degree> t = @;", "degrees(tilt)",
                 "an angle in arcminute converts with in", "tilt in degree", "tilt in degree"},
        HintCase{"plain_radians_into_degrees", "uniform float<1> turn;", "float<angle in degree> d = @;", "degrees(turn)",
                 "give a plain number of radians its unit", "degrees(turn * radian)", "degrees(turn * radian)"},
        HintCase{"points_subtracted_the_wrong_way_round", kShaded, "vector<world, away> toLight = @;", "P - lightPos",
                 "this one points toward the shaded point P", "lightPos - P", "lightPos - P"},
        HintCase{"view_direction_reversed", kShaded, "direction<world, away> wo = @;", "normalize(P - eyePos)",
                 "the one away from it is", "normalize(eyePos - P)", "normalize(eyePos - P)"},
        HintCase{"incident_direction_stored_as_outgoing", "uniform direction<world, toward> I;", "direction<world, away> w = @;",
                 "I", "negate it to point away from the shaded point", "-I", "-I"},
        HintCase{"reflect_of_an_outgoing_direction", kShaded, "direction<world, away> wi = @;", "reflect(wo, n)",
                 "reflect(I, N) takes I toward the surface", "reflect(-wo, n)", "reflect(-wo, n)"},
        HintCase{"faceforward_by_an_outgoing_direction", kShaded, "normal<world> front = @;", "faceforward(n, wo, n)",
                 "faceforward(N, I, Nref) takes I toward the surface", "faceforward(n, -wo, n)", "faceforward(n, -wo, n)"},
        HintCase{"inverse_square_law_by_a_cast", "uniform float<length> d;", "float<solid_angle_per_projected_area> g = @;",
                 "float<solid_angle_per_projected_area>(1.0 / d * d)", "missing the inverse-square falloff", "inverse_square(d)",
                 "inverse_square(d)"},
        HintCase{"length_cast_to_a_number", "uniform float<length> d;", "float<1> x = @;", "float<1>(d)", "a count of its unit",
                 "x / meter", "d / meter"},
        HintCase{"area_pdf_in_an_mis_weight", "uniform float<pdf_solid_angle> pdfB; uniform float<pdf_area> pdfL; uniform float<area> A;",
                 "float<1> w = pdfB / (pdfB + @);", "pdfL", "convert it with the Jacobian", ""},
        HintCase{"normal_through_the_model_matrix", kModel, "vec3 nW = (@).xyz;", "model * vec4(nObj, 0.0)",
                 "carry it by the inverse transpose", "vec4(nObj, 0.0) * inverse(model)",
                 "vec4(nObj, 0.0) * inverse(model)"},
        HintCase{"normal_through_the_linear_part", kModel, "vec3 nW = @;", "mat3(model) * nObj",
                 "carry it by the inverse transpose", "transpose(inverse(mat3(model))) * nObj",
                 "transpose(inverse(mat3(model))) * nObj"},
        HintCase{"ambient_of_the_albedo", "uniform spectrum<1> albedo; uniform spectrum<radiance> ambientLight;",
                 "spectrum<radiance> ambient = @;", "0.03 * albedo", "the light it reflects is missing",
                 "ambientLight * albedo", "0.03 * ambientLight * albedo"},
        HintCase{"regularised_falloff", "uniform float<length> d;", "float<1> f = @;", "1.0 / (1.0 + d * d)",
                 "the sum would change with the unit", "1.0 * square_meter", "square_meter / (1.0 * square_meter + d * d)"},
        HintCase{"cosine_of_an_unnormalised_axis", "uniform vector<world> s; uniform direction<world> l; uniform float<1> cutOff;",
                 "bool inside = @;", "dot(-s, l) > cutOff", "normalize(-s)", "normalize(-s)", "dot(normalize(-s), l) > cutOff"},
        HintCase{"point_with_w_zero", kModel, "vec3 pW = (@).xyz;", "model * vec4(pObj, 0.0)", "for a point",
                 "vec4(p, 1.0)", "model * vec4(pObj, 1.0)"},
        HintCase{"ray_from_undivided_coordinates", "space clip; uniform hpoint<world> target;", "vec3 ray = @;",
                 "normalize(target.xyz)", "divide by w first", "normalize(target.xyz / target.w)",
                 "normalize(target.xyz / target.w)"},
        HintCase{"projection_composed_first", "space view; space clip; uniform rigidmap<world, view> viewFromWorld;"
                 " uniform projmap<view, clip> clipFromView;", "projmap<world, clip> m = @;", "viewFromWorld * clipFromView",
                 "the order is reversed", "clipFromView * viewFromWorld", "clipFromView * viewFromWorld"},
        HintCase{"angle_beside_a_fraction_of_pi", "const float PI = 3.14159265358979; uniform float<angle> a; uniform float<angle> b;",
                 "float s = @;", "a / PI + b", "an angle divided by 'PI'", "b / PI", "a / PI + b / PI"},
        HintCase{"cosine_of_an_unnormalised_light_vector_in_a_local", "uniform vector<world> toLight; uniform normal<world> n;"
                 " uniform spectrum<brdf> f; uniform spectrum<irradiance / proj> E;",
                 "float c = max(dot(n, toLight), 0.0); spectrum<radiance> L = @;", "f * E * c",
                 "takes 'toLight', a vector<world>, which is not of unit length", "",
                 "f * E * max(dot(n, normalize(toLight)), 0.0)"},
        HintCase{"interpolated_normal_in_a_cosine", "in normal<world> vN; uniform direction<world> l;", "float<proj> c = max(@, 0.0);",
                 "dot(vN, l)", "normalize it first", "normalize(vN)", "dot(normalize(vN), l)"},
        HintCase{"cosine_with_a_travel_direction", "in normal<world> vN; uniform direction<world, toward> travel;",
                 "float<proj> c = @;", "max(dot(normalize(vN), travel), 0.0)", "takes the direction away from the surface",
                 "dot(normalize(vN), -travel)", "max(dot(normalize(vN), -travel), 0.0)"},
        HintCase{"reflection_written_out_for_an_incident_direction", "uniform normal<world> n; uniform direction<world, toward> I;",
                 "vec3 r = @;", "2.0 * n * dot(n, I) - I", "the reflection of an incident direction", "reflect(I, n)",
                 "reflect(I, n)"},
        HintCase{"reflect_written_out_for_an_outgoing_direction", "uniform normal<world> n; uniform direction<world, away> l;",
                 "vec3 r = @;", "l - 2.0 * dot(n, l) * n", "the mirror image of a direction that points away", "reflect(-l, n)",
                 "reflect(-l, n)"},
        HintCase{"normal_by_the_inverse_without_its_transpose", "space view; uniform map<world, view> viewFromWorld; uniform normal<world> nW;",
                 "vec3 nV = @;", "inverse(mat3(viewFromWorld)) * nW", "missing transpose",
                 "transpose(inverse(mat3(viewFromWorld))) * nW", "transpose(inverse(mat3(viewFromWorld))) * nW"}),
    [](const ::testing::TestParamInfo<HintCase>& info) { return std::string(info.param.name); });

TEST(Hints, OneCandidateSaysWhichArgumentDoesNotFit) {
  auto c = check_source(
      "space world; uniform normal<world> n; uniform vector<world> toL; out vec4 color;\n"
      "template<space S> float<proj> cosineTo(normal<S> m, direction<S> w) { return max(dot(m, w), 0.0); }\n"
      "void main() { float<proj> c = cosineTo(n, toL); color = vec4(c); }\n");
  ASSERT_EQ(c->errors(), 1u);
  EXPECT_EQ(first_hint(*c), "argument 2 is vector<world> but the parameter is direction<S>: a vector becomes a direction only "
                            "through normalize()");
}

TEST(Hints, ANormalForADirectionParameterSaysHowToConvert) {
  auto c = check_source(
      "space world; uniform normal<world> n; out vec4 color;\n"
      "vec2 equirect(direction<world> v) { return v.xy; }\n"
      "void main() { color = vec4(equirect(n), 0.0, 1.0); }\n");
  ASSERT_EQ(c->errors(), 1u);
  EXPECT_EQ(first_hint(*c), "argument 1 is normal<world> but the parameter is direction<world>: a normal is not a direction (a map "
                            "carries it by the inverse transpose): take a normal<S> where one is meant, or convert explicitly "
                            "with direction<S>(n)");
  auto fixed = check_source(
      "space world; uniform normal<world> n; out vec4 color;\n"
      "vec2 equirect(direction<world> v) { return v.xy; }\n"
      "void main() { color = vec4(equirect(direction<world>(n)), 0.0, 1.0); }\n");
  EXPECT_EQ(fixed->errors(), 0u);
}

// normalize(name) is offered for a named vector only: an expression has no name to put in the code.
TEST(Hints, AnUnnamedVectorBesideADirectionIsNotNormalizedByAPlaceholder) {
  auto c = check_source(
      "space world; uniform normal<world> n; uniform direction<world> wo; uniform vector<world> toL; out vec4 color;\n"
      "void main() { direction<world> r = normalize(toL * dot(n, wo) - wo); color = vec4(r, 1.0); }\n");
  ASSERT_EQ(c->errors(), 1u);
  EXPECT_EQ(first_hint(*c), "a direction has unit length, the other operand is a vector of dimension length·proj: normalize it first");
}

}  // namespace
}  // namespace safegi
