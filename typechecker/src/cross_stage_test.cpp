// Cross-stage interface matching (check_interface_match): by name, by
// layout(location), interface blocks by block name; per-vertex array levels.
// The rendered text with both file:line:col is pinned by the golden cases
// testsuite/golden/cases/typechecker/cross_stage_*.

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

using Messages = std::vector<std::string>;

// Every "message / note" the match reports between two stages.
Messages match(std::string_view producer, Stage producer_stage, std::string_view consumer, Stage consumer_stage) {
  auto p = check_source(producer, {.stage = producer_stage});
  auto c = check_source(consumer, {.stage = consumer_stage});
  EXPECT_EQ(p->rendered() + c->rendered(), "");
  DiagnosticEngine diags;
  check_interface_match(p->result, c->result, diags);
  Messages out;
  for (const Diagnostic& d : diags.diagnostics()) {
    out.push_back(d.message);
    for (const Diagnostic& n : d.notes) out.push_back("note: " + n.message);
  }
  return out;
}

TEST(CrossStage, ByName) {
  EXPECT_EQ(match("space world; out point<world> P; out spectrum<radiance> L; void main() {}", Stage::vertex,
                  "space world; space object; in point<object> P; in spectrum<radiance> L; void main() {}", Stage::fragment),
            (Messages{"input 'P' has type point<object> but the vertex stage's output 'P' has type point<world>",
                      "note: output 'P' declared here as point<world>"}));
  EXPECT_EQ(match("space world; out point<world> P; void main() {}", Stage::vertex,
                  "space world; in point<world> P; in vec3 unmatched; void main() {}", Stage::fragment),
            Messages{});
}

TEST(CrossStage, AnUnannotatedSideIsADifferentType) {
  // The consumer relies on the annotation; `?` does not stand in for it across stages.
  EXPECT_EQ(match("out vec3 L; void main() {}", Stage::vertex, "in spectrum<radiance> L; void main() {}", Stage::fragment),
            (Messages{"input 'L' has type spectrum<radiance> but the vertex stage's output 'L' has type vec3",
                      "note: output 'L' declared here as vec3"}));
}

TEST(CrossStage, ByLocation) {
  EXPECT_EQ(match("layout(location = 1) out spectrum<radiance> radianceOut; void main() {}", Stage::vertex,
                  "layout(location = 1) in spectrum<irradiance> E; void main() {}", Stage::fragment),
            (Messages{"input 'E' has type spectrum<irradiance> but the vertex stage's output 'radianceOut' (matched by location 1) "
                      "has type spectrum<radiance>",
                      "note: output 'radianceOut' declared here as spectrum<radiance>"}));
  // Same name, different locations: not a pair.
  EXPECT_EQ(match("layout(location = 0) out float<length> d; void main() {}", Stage::vertex,
                  "layout(location = 2) in float<time> d; void main() {}", Stage::fragment),
            Messages{});
}

TEST(CrossStage, BlocksByBlockName) {
  EXPECT_EQ(match("space world; out VertexData { point<world> P; float<length> r; } vs_out; void main() {}", Stage::vertex,
                  "space world; in VertexData { point<world> P; float<time> r; } fs_in; void main() {}", Stage::fragment),
            (Messages{"input 'fs_in.r' has type float<time> but the vertex stage's output 'vs_out.r' (matched by block VertexData) "
                      "has type float<length>",
                      "note: output 'vs_out.r' declared here as float<length>"}));
  EXPECT_EQ(match("out Other { float<length> r; } a; void main() {}", Stage::vertex,
                  "in VertexData { float<time> r; } b; void main() {}", Stage::fragment),
            Messages{});
}

TEST(CrossStage, PerVertexArrays) {
  EXPECT_EQ(match("space world; out point<world> P; void main() {}", Stage::vertex,
                  "layout(triangles) in; layout(triangle_strip, max_vertices = 3) out; space world; in point<world> P[]; void main() {}",
                  Stage::geometry),
            Messages{});
  EXPECT_EQ(match("space world; out point<world> P; void main() {}", Stage::vertex,
                  "layout(triangles) in; layout(triangle_strip, max_vertices = 3) out; space object; in point<object> P[]; void main() {}",
                  Stage::geometry),
            (Messages{"input 'P' has type point<object> but the vertex stage's output 'P' has type point<world>",
                      "note: output 'P' declared here as point<world>"}));
}

}  // namespace
}  // namespace safegi::testing
