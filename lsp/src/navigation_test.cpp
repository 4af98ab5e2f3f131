// Hover (types in physical words, exact text) and go to definition: into
// the document, into the prelude's file, through an #include.
#include "navigation.hpp"

#include <gtest/gtest.h>

#include <safegi/diagnostics/codes.hpp>

#include "in_process.hpp"

namespace safegi::lsp {
namespace {

using testing::at;
using testing::InProcess;
using testing::json;

TEST(PhysicalWords, TypesInUnitsAndSpaces) {
  DimensionRegistry r = DimensionRegistry::rendering_prelude();
  const SpaceId world = *r.add_space("world"), object = *r.add_space("object");
  auto typed = [&](Geometry g, std::optional<std::string_view> dim) {
    Type t = Type::vector_of(Scalar::float_, g == Geometry::hpoint ? 4 : 3);
    if (is_map(g)) t = Type::matrix_of(Scalar::float_, 4, 4);
    if (g == Geometry::none) t = Type::scalar_of(Scalar::float_);
    t.geometry = g;
    if (dim) t.dim = DimSlot::known(*r.find_dimension(*dim), std::string(*dim));
    if (has_space(g)) t.from = SpaceSlot::known(world);
    if (is_map(g)) t.from = SpaceSlot::known(object), t.to = SpaceSlot::known(world);
    return physical_words(t, type_name(t, r), r);
  };
  EXPECT_EQ(typed(Geometry::spectrum, "radiance"), "spectrum<radiance> — W·m⁻²·sr⁻¹");
  EXPECT_EQ(typed(Geometry::spectrum, "brdf"), "spectrum<brdf> — sr⁻¹");
  EXPECT_EQ(typed(Geometry::none, "pdf_area"), "float<pdf_area> — m⁻²");
  EXPECT_EQ(typed(Geometry::none, "power"), "float<power> — W");
  EXPECT_EQ(typed(Geometry::none, "proj"), "float<proj> — 1");
  EXPECT_EQ(typed(Geometry::none, "dimensionless"), "float<dimensionless> — 1 (dimensionless)");
  EXPECT_EQ(typed(Geometry::point, "length"), "point<world> — m, in space world");
  EXPECT_EQ(typed(Geometry::vector, "velocity"), "vector<world, velocity> — m·s⁻¹, in space world");
  EXPECT_EQ(typed(Geometry::direction, "dimensionless"), "direction<world> — unit vector in space world");
  EXPECT_EQ(typed(Geometry::normal, "dimensionless"), "normal<world> — unit normal in space world");
  EXPECT_EQ(typed(Geometry::hpoint, std::nullopt), "hpoint<world> — homogeneous point in space world");
  EXPECT_EQ(typed(Geometry::map, std::nullopt), "map<object, world> — map from space object to space world");
  EXPECT_EQ(typed(Geometry::projmap, std::nullopt), "projmap<object, world> — projective map from space object to space world");
  EXPECT_EQ(typed(Geometry::none, std::nullopt), "float — unannotated (plain GLSL)");
  Type sampler;
  sampler.shape = Shape::opaque;
  sampler.opaque = "sampler2D";
  Type depth = Type::scalar_of(Scalar::float_);
  depth.dim = DimSlot::known(*r.find_dimension("length"), "length");
  sampler.texel = std::make_shared<const Type>(depth);
  EXPECT_EQ(physical_words(sampler, type_name(sampler, r), r), "sampler2D<float<length>> — texels float<length> — m");
}

TEST(PhysicalWords, TheEquationShowsProjAndSaysWhyTheUnitsDoNot) {
  const DimensionRegistry r = DimensionRegistry::rendering_prelude();
  EXPECT_EQ(dimension_equation(DimSlot::known(*r.find_dimension("radiance"), "radiance"), r),
            "radiance = energy·length⁻²·time⁻¹·solid_angle⁻¹·proj⁻¹; the SI units leave out proj, the projected-cosine "
            "factor (a pure number in SI)");
  EXPECT_EQ(dimension_equation(DimSlot::known(*r.find_dimension("irradiance"), "irradiance"), r), "irradiance = energy·length⁻²·time⁻¹");
  EXPECT_EQ(dimension_equation(DimSlot::known(*r.find_dimension("length"), "length"), r), "");
  EXPECT_EQ(dimension_equation(DimSlot::known(Dimension{}), r), "");
}

const std::string kUri = "file:///tmp/nav/light.sgl.frag";
const char* kLight = R"(#version 330 core
#include <safegi/prelude.sgl>
space world;
uniform spectrum<intensity> lightI;  // W/sr — écrit en « SI »
uniform point<world> lightPos;
in point<world> P;
out vec4 color;
template<dimension D>
spectrum<D> attenuate(spectrum<D> x, float<1> v) { return x * v; }
void main() {
    float<length> d = length(lightPos - P) + 2.0 * centimeter;
    spectrum<irradiance> E = attenuate(lightI, 1.0) / (d * d) * float<solid_angle>(1.0);
    color = vec4(E, 1.0);
}
)";

class Navigation : public ::testing::Test {
 protected:
  void SetUp() override {
    ServerOptions options;
    options.prelude_file = SAFEGI_SOURCE_PRELUDE;
    s = std::make_unique<InProcess>(std::move(options));
    s->initialize();
    ASSERT_EQ(s->open(kUri, kLight)["diagnostics"], json::array());
  }
  std::string hover(int line, int character) {
    const json r = s->request("textDocument/hover", at(kUri, line, character));
    return r["result"].is_null() ? "<null>" : r["result"]["contents"]["value"].get<std::string>();
  }
  json definition(int line, int character) { return s->request("textDocument/definition", at(kUri, line, character))["result"]; }
  std::unique_ptr<InProcess> s;
};

TEST_F(Navigation, HoverOnVariablesShowsTheTypeInPhysicalWords) {
  EXPECT_EQ(hover(3, 30), "```glsl\nspectrum<intensity> lightI\n```\nspectrum<intensity> — W·sr⁻¹\n\nintensity = energy·time⁻¹·solid_angle⁻¹");
  EXPECT_EQ(hover(11, 25), "```glsl\nspectrum<irradiance> E\n```\nspectrum<irradiance> — W·m⁻²\n\nirradiance = energy·length⁻²·time⁻¹");
  EXPECT_EQ(hover(10, 30), "```glsl\npoint<world> lightPos\n```\npoint<world> — m, in space world");
  EXPECT_EQ(hover(12, 4), "```glsl\nvec4 color\n```\nvec4 — unannotated (plain GLSL)");
  EXPECT_EQ(hover(8, 58), "```glsl\nspectrum<D> x\n```\nspectrum<D> — any dimension (a template parameter)");
}

TEST_F(Navigation, HoverOnAnnotationNamesFunctionsAndBuiltins) {
  EXPECT_EQ(hover(11, 13), "```glsl\ndimension irradiance\n```\nirradiance — W·m⁻²\n\nirradiance = energy·length⁻²·time⁻¹");
  EXPECT_EQ(hover(10, 10), "```glsl\ndimension length\n```\nlength — m (a base dimension)");
  EXPECT_EQ(hover(10, 54), "```glsl\nunit centimeter : length = 0.01\n```\n1 centimeter = 0.01 m");
  EXPECT_EQ(hover(4, 15), "```glsl\nspace world\n```");
  EXPECT_EQ(hover(7, 19), "```glsl\ndimension D\n```\ntemplate parameter");
  EXPECT_EQ(hover(11, 30), "```glsl\ntemplate<dimension D> spectrum<D> attenuate(spectrum<D> x, float<dimensionless> v)\n```\n"
                           "here returns spectrum<intensity> — W·sr⁻¹");
  EXPECT_EQ(hover(10, 24), "```glsl\nlength: geo<S, D> -> float<D>\n```\nbuilt-in function; here returns float<length> — m");
  EXPECT_EQ(hover(0, 3), "<null>");   // #version
  EXPECT_EQ(hover(9, 0), "<null>");   // `void`
}

TEST_F(Navigation, HoverRangeIsTheNameInUtf16) {
  // Line 4 has « » and é before nothing of interest, line 12 is ASCII: the
  // range of `lightI` in line 12 is at its UTF-16 columns.
  const json r = s->request("textDocument/hover", at(kUri, 11, 40));
  EXPECT_EQ(r["result"]["range"], json::parse(R"({"start": {"line": 11, "character": 39}, "end": {"line": 11, "character": 45}})"));
}

TEST_F(Navigation, DefinitionInTheDocumentAndInThePrelude) {
  EXPECT_EQ(definition(11, 40), json::parse(R"j({"uri": "file:///tmp/nav/light.sgl.frag",
      "range": {"start": {"line": 3, "character": 28}, "end": {"line": 3, "character": 34}}})j"));
  EXPECT_EQ(definition(11, 30), json::parse(R"j({"uri": "file:///tmp/nav/light.sgl.frag",
      "range": {"start": {"line": 8, "character": 12}, "end": {"line": 8, "character": 21}}})j"));
  EXPECT_EQ(definition(8, 9), json::parse(R"j({"uri": "file:///tmp/nav/light.sgl.frag",
      "range": {"start": {"line": 7, "character": 19}, "end": {"line": 7, "character": 20}}})j"));
  // `irradiance` is declared on line 22 of the prelude, the file given as its copy on disk.
  const json prelude = definition(11, 13);
  EXPECT_EQ(prelude["uri"], "file://" + std::string(SAFEGI_SOURCE_PRELUDE));
  EXPECT_EQ(prelude["range"], json::parse(R"j({"start": {"line": 21, "character": 10}, "end": {"line": 21, "character": 20}})j"));
  // The #include line goes to the file.
  EXPECT_EQ(definition(1, 12)["uri"], "file://" + std::string(SAFEGI_SOURCE_PRELUDE));
  EXPECT_EQ(definition(11, 8), nullptr);  // `spectrum` is a type word, not a declared name
}

// A unit's scale prints as the checker prints numbers (DimensionRegistry::format_number), not
// as a 17-digit stream did ("9.9999999999999995e-07" for the prelude's 1e-6).
TEST_F(Navigation, HoverPrintsAUnitsScaleAsTheCheckerDoes) {
  const std::string uri = "file:///tmp/nav/micro.sgl.frag";
  ASSERT_EQ(s->open(uri, "#version 330 core\n#include <safegi/prelude.sgl>\n"
                         "void main() { float<length> d = 2.0 * micrometer; }\n")["diagnostics"],
            json::array());
  const json hovered = s->request("textDocument/hover", at(uri, 2, 42))["result"];
  EXPECT_EQ(hovered["contents"]["value"], "```glsl\nunit micrometer : length = 0.000001\n```\n1 micrometer = 0.000001 m");
}

TEST_F(Navigation, HoverOnADiagnosticExplainsItsCodeAsSafeglslcExplainDoes) {
  const std::string uri = "file:///tmp/nav/bug.sgl.frag";
  const json opened = s->open(uri, "#version 330 core\n#include <safegi/prelude.sgl>\n"
                                   "void main() { float<length> d = 2.0 * second; }\n");
  ASSERT_EQ(opened["diagnostics"].size(), 1u);
  ASSERT_EQ(opened["diagnostics"][0]["code"], "E-DIMENSION-MISMATCH");
  std::string explanation = explain_diagnostic_code("E-DIMENSION-MISMATCH");
  explanation.pop_back();  // its last newline
  // On a name inside the diagnostic's range: the name, then the explanation.
  const json on_name = s->request("textDocument/hover", at(uri, 2, 40))["result"];
  EXPECT_EQ(on_name["contents"]["value"], "```glsl\nunit second : time = 1.0\n```\n1 second = 1.0 s\n\n---\n\n" + explanation);
  // Where no name is: the explanation alone, over the diagnostic's range.
  const json on_operator = s->request("textDocument/hover", at(uri, 2, 37))["result"];
  EXPECT_EQ(on_operator["contents"]["value"], explanation);
  EXPECT_EQ(on_operator["range"], opened["diagnostics"][0]["range"]);
}

TEST(NavigationWithoutAPreludeFile, ThePreludeHasNoLocation) {
  InProcess s;
  s.initialize();
  s.open(kUri, kLight);
  EXPECT_EQ(s.request("textDocument/definition", at(kUri, 11, 13))["result"], nullptr);
  // Hover still works: it needs no file.
  EXPECT_TRUE(s.request("textDocument/hover", at(kUri, 11, 13))["result"].is_object());
}

TEST(NavigationAfterASyntaxError, GivesNothingAndNoError) {
  InProcess s;
  s.initialize();
  s.open(kUri, "void main( {\n");
  const json r = s.request("textDocument/hover", at(kUri, 0, 2));
  EXPECT_EQ(r["result"], nullptr);
  EXPECT_FALSE(r.contains("error"));
}

TEST(NavigationPlainText, WhenTheClientDoesNotTakeMarkdown) {
  InProcess s;
  s.initialize({{"textDocument", {{"hover", {{"contentFormat", {"plaintext"}}}}}}});
  s.open(kUri, kLight);
  const json r = s.request("textDocument/hover", at(kUri, 3, 30));
  EXPECT_EQ(r["result"]["contents"]["kind"], "plaintext");
  EXPECT_EQ(r["result"]["contents"]["value"], "spectrum<intensity> lightI\nspectrum<intensity> — W·sr⁻¹\nintensity = energy·time⁻¹·solid_angle⁻¹");
}

}  // namespace
}  // namespace safegi::lsp
