#include "safegi/symbol_table/handles_header.hpp"

#include <gtest/gtest.h>

#include "safegi/symbol_table/error.hpp"
#include "read_testdata.hpp"

namespace safegi::gl {
namespace {

using testing::read_testdata;

std::string error_of(const SymbolTable& table, const HandlesHeaderOptions& options) {
  try {
    generate_handles_header(table, options);
  } catch (const SymbolTableError& error) {
    return error.what();
  }
  return "no error";
}

SymbolTable one_uniform(const std::string& kind_and_type) {
  return parse_symbol_table(R"({"format":"safegi-symbol-table","version":1,"mode":"shader","stages":[
      {"stage":"fragment","file":"f.sgl.frag","glsl_version":{"number":330},"symbols":[
        {"name":"u","storage":"uniform",)" + kind_and_type + R"(,"declared_at":{"file":"f.sgl.frag","line":2,"column":9}}
      ]}]})");
}

TEST(HandlesHeader, MatchesTheGoldenHeaderForTheExampleProgram) {
  HandlesHeaderOptions options;
  options.namespace_name = "shaders::emission";
  options.origin = "emission.program.json";
  EXPECT_EQ(generate_handles_header(parse_symbol_table(read_testdata("emission.program.json")), options),
            read_testdata("emission_handles.hpp.expected"));
}

// --api vulkan: handles for a runtime_vk compute pipeline (its use is tested in
// runtime_vk/src/handles_usage_test.cpp), refused for a table without a Vulkan compute stage.
TEST(HandlesHeader, VulkanHandlesNeedAVulkanComputeStage) {
  HandlesHeaderOptions options;
  options.api = Client::vulkan;
  options.origin = "emission.program.json";
  EXPECT_EQ(error_of(parse_symbol_table(read_testdata("emission.program.json")), options),
            "emission.program.json: error: Vulkan handles need a Vulkan compute stage (safeglslc -V or "
            "--target-env vulkan1.x)");
  const SymbolTable compute =
      parse_symbol_table(R"({"format":"safegi-symbol-table","version":2,"mode":"shader","stages":[
      {"stage":"compute","client":"vulkan","file":"c.sgl.comp","glsl_version":{"number":450},"symbols":[
        {"name":"Push","storage":"uniform","kind":"block","glsl_type":"Push","push_constant":true,"packing":"std430",
         "size":16,"declared_at":{"file":"c.sgl.comp","line":2,"column":30},"members":[
          {"name":"scale","storage":"uniform","kind":"spectrum","glsl_type":"vec3","offset":0,"size":12,
           "dimension":{"exponents":{}},"declared_at":{"file":"c.sgl.comp","line":2,"column":50}}]}
      ]}]})");
  const std::string header = generate_handles_header(compute, options);
  EXPECT_NE(header.find("safegi::vk::member_id<safegi::spectrum<safegi::dim::dimensionless>> Push_scale;"),
            std::string::npos)
      << header;
  EXPECT_NE(header.find("static constexpr std::uint32_t offset = 0, size = 12;"), std::string::npos) << header;
  EXPECT_NE(
      header.find("Push_scale(pipeline.push_constant<safegi::spectrum<safegi::dim::dimensionless>>(\"Push.scale\"))"),
      std::string::npos)
      << header;
}

TEST(HandlesHeader, SpacesAndBasesOutsideTheTypedLibraryNeedASpelling) {
  const SymbolTable table = one_uniform(R"("kind":"point","glsl_type":"vec3","spaces":["tangent"])");
  EXPECT_EQ(error_of(table, {}),
            "f.sgl.frag:2:9: error: 'u' uses the space 'tangent', which has no C++ spelling; pass --cpp "
            "tangent=<C++ type>");
  HandlesHeaderOptions options;
  options.cpp_names["tangent"] = "::my::tangent";
  EXPECT_NE(generate_handles_header(table, options).find("using u_type = safegi::point<::my::tangent>;"),
            std::string::npos);
  EXPECT_EQ(error_of(one_uniform(R"("kind":"scalar","glsl_type":"float","dimension":{"exponents":{"pixel":1}})"), {}),
            "f.sgl.frag:2:9: error: 'u' uses the base dimension 'pixel', which has no C++ spelling; pass --cpp "
            "pixel=<C++ type>");
}

TEST(HandlesHeader, NamesUnnamedDimensionsByNumber) {
  const std::string header = generate_handles_header(
      one_uniform(R"("kind":"scalar","glsl_type":"float","dimension":{"exponents":{"length":3,"time":-1}})"), {});
  EXPECT_NE(header.find("using dimension_0 = safegi::dim::product<safegi::dim::pow<safegi::dim::length, 3>, "
                        "safegi::dim::pow<safegi::dim::time, -1>>;"),
            std::string::npos)
      << header;
  EXPECT_NE(header.find("using u_type = safegi::quantity<dimensions::dimension_0>;"), std::string::npos);
}

}  // namespace
}  // namespace safegi::gl
