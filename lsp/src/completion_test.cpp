// Completion inside annotations: what is expected where, and the names offered.
#include "completion.hpp"

#include <gtest/gtest.h>

#include <set>

#include <safegi/dimension_algebra/registry.hpp>

#include "in_process.hpp"

namespace safegi::lsp {
namespace {

using testing::at;
using testing::InProcess;
using testing::json;

// The context at the `|` of `text`.
CompletionContext context(std::string text) {
  const std::size_t at = text.find('|');
  text.erase(at, 1);
  return completion_context(text, at);
}

TEST(CompletionContext, KindAwareInsideAnnotations) {
  const std::pair<const char*, Expected> cases[] = {
      {"float<|", Expected::dimension},
      {"uniform spectrum<rad|", Expected::dimension},
      {"vec3<length / |", Expected::dimension},
      {"float<solid_angle / (area * |", Expected::dimension},
      {"point<|", Expected::space},
      {"in normal< w|", Expected::space},
      {"map<object, |", Expected::space},
      {"projmap<object, cl|", Expected::space},
      {"vector<|", Expected::space},
      {"vector<world, |", Expected::dimension},
      {"vector<world, length, |", Expected::orientation},
      {"in point<world, |", Expected::orientation},
      {"direction<world, aw|", Expected::orientation},
      {"uniform sampler2D<|", Expected::type},
      {"uniform sampler2D<float<|", Expected::dimension},
      {"template<|", Expected::template_parameter_kind},
      {"template<dimension D, |", Expected::template_parameter_kind},
      {"map<spectrum<radiance>, |", Expected::space},  // the nested list is skipped, commas counted outside it
      {"dimension area = len|", Expected::dimension},
      {"unit inch : len|", Expected::dimension},
      {"float<length> r = 3.0 * cent|", Expected::unit},
      {"x = d / |", Expected::unit},
      {"unit inch : length = 0.0|", Expected::nothing},
      {"if (a <|", Expected::nothing},
      {"if (a < b|", Expected::nothing},
      {"float<length> d; x|", Expected::nothing},
      {"|", Expected::nothing},
      {"foo(float<length> a) { return a + |", Expected::nothing},
  };
  for (const auto& [text, expected] : cases) EXPECT_EQ(context(text).expected, expected) << text;
  EXPECT_EQ(context("uniform spectrum<rad|").prefix, "rad");
  EXPECT_EQ(context("float<|").prefix, "");
}

std::set<std::string> labels(const json& list) {
  std::set<std::string> out;
  for (const json& item : list["items"]) out.insert(item["label"].get<std::string>());
  return out;
}

const std::string kUri = "file:///tmp/complete/c.sgl.frag";

class Completion : public ::testing::Test {
 protected:
  void SetUp() override { s.initialize(); }
  // Opens `text` with `|` removed; the items at the `|`.
  json complete(std::string text) {
    const std::size_t offset = text.find('|');
    text.erase(offset, 1);
    s.open(kUri, text);
    const std::string before = text.substr(0, offset);
    const int line = static_cast<int>(std::count(before.begin(), before.end(), '\n'));
    const int character = static_cast<int>(offset - (before.rfind('\n') == std::string::npos ? 0 : before.rfind('\n') + 1));
    return s.request("textDocument/completion", at(kUri, line, character))["result"];
  }
  InProcess s;
};

TEST_F(Completion, DimensionsFromThePreludeAndTheDocument) {
  const json list = complete("#include <safegi/prelude.sgl>\ndimension pixel;\ndimension pixel_area = pixel^2;\nspace world;\nuniform float<|");
  const std::set<std::string> got = labels(list);
  for (const char* name : {"length", "radiance", "brdf", "proj", "pixel", "pixel_area"}) EXPECT_TRUE(got.count(name)) << name;
  EXPECT_FALSE(got.count("world"));   // a space
  EXPECT_FALSE(got.count("meter"));   // a unit: annotations name dimensions
  EXPECT_EQ(got.size(), 26u);         // the prelude's 24 and the document's 2
  for (const json& item : list["items"]) {
    EXPECT_EQ(item["kind"], 7);
    if (item["label"] == "radiance") {
      EXPECT_EQ(item["detail"], "dimension");  // never checked yet: no units
    }
  }
}

TEST_F(Completion, SpacesWhereASpaceIsExpected) {
  const json list = complete("#include <safegi/prelude.sgl>\nspace world;\nspace object;\nuniform map<object, |");
  EXPECT_EQ(labels(list), (std::set<std::string>{"object", "world"}));
  EXPECT_EQ(list["items"][0]["kind"], 9);
}

TEST_F(Completion, OrientationWordsWhereOneMayEndTheAnnotation) {
  const std::string head = "#include <safegi/prelude.sgl>\nspace world;\n";
  EXPECT_EQ(labels(complete(head + "in point<world, |")), (std::set<std::string>{"shaded"}));
  EXPECT_EQ(labels(complete(head + "uniform direction<world, |")), (std::set<std::string>{"away", "toward"}));
  const std::set<std::string> vector = labels(complete(head + "uniform vector<world, |"));  // a dimension or the orientation
  EXPECT_TRUE(vector.count("away") && vector.count("toward") && vector.count("length"));
  EXPECT_FALSE(labels(complete(head + "uniform normal<world, |")).count("away"));
}

TEST_F(Completion, DetailsFromTheLastCheckedText) {
  s.open(kUri, "#include <safegi/prelude.sgl>\nvoid main() {}\n");  // checks: the registry is known
  const std::string text = "#include <safegi/prelude.sgl>\nvoid main() {}\nuniform spectrum<";
  s.notify("textDocument/didChange", {{"textDocument", {{"uri", kUri}, {"version", 2}}}, {"contentChanges", {{{"text", text}}}}});
  const json list = s.request("textDocument/completion", at(kUri, 2, 17))["result"];
  std::map<std::string, std::string> details;
  for (const json& item : list["items"]) details[item["label"]] = item.value("detail", "");
  EXPECT_EQ(details["radiance"], "dimension — W·m⁻²·sr⁻¹");
  EXPECT_EQ(details["length"], "base dimension — m");
}

TEST_F(Completion, TemplateParametersInsideTheirFunctionOnly) {
  const std::string head = "#include <safegi/prelude.sgl>\ntemplate<dimension D, space S>\nfloat<D> f(point<S> p, float<";
  EXPECT_TRUE(labels(complete(head + "|")).count("D"));
  const json spaces = complete("#include <safegi/prelude.sgl>\nspace world;\ntemplate<space S>\nfloat<length> f(point<|");
  EXPECT_EQ(labels(spaces), (std::set<std::string>{"S", "world"}));
  const json after = complete("#include <safegi/prelude.sgl>\ntemplate<dimension D>\nfloat<D> f(float<D> x) { return x; }\nuniform float<|");
  EXPECT_FALSE(labels(after).count("D"));
}

TEST_F(Completion, UnitsAfterAProductInAnExpression) {
  const json list = complete("#include <safegi/prelude.sgl>\nvoid main() { float<length> r = 3.0 * |");
  const std::set<std::string> got = labels(list);
  EXPECT_EQ(got.size(), DimensionRegistry::rendering_prelude().units().size());  // the prelude's units, in both spellings
  EXPECT_TRUE(got.count("centimeter"));
  EXPECT_TRUE(got.count("centimetre"));
  EXPECT_EQ(list["items"][0]["kind"], 11);
}

TEST_F(Completion, NothingOutsideAnnotations) {
  EXPECT_EQ(complete("void main() { float x = 1.0; x|")["items"], json::array());
  // A comment is not parsed: harmless. The items are the prelude's dimensions.
  const DimensionRegistry vocabulary = DimensionRegistry::rendering_prelude();
  EXPECT_EQ(complete("#include <safegi/prelude.sgl>\n// float<|")["items"].size(),
            vocabulary.bases().size() + vocabulary.derived().size());
}

TEST_F(Completion, TemplateHeadersAndSamplers) {
  EXPECT_EQ(labels(complete("template<|")), (std::set<std::string>{"dimension", "space"}));
  EXPECT_TRUE(labels(complete("uniform sampler2D<|")).count("spectrum"));
}

}  // namespace
}  // namespace safegi::lsp
