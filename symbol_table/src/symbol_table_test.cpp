#include "safegi/symbol_table/symbol_table.hpp"

#include <gtest/gtest.h>

#include "safegi/symbol_table/error.hpp"
#include "read_testdata.hpp"

namespace safegi::gl {
namespace {

using testing::read_testdata;

std::string error_of(std::string_view json) {
  try {
    parse_symbol_table(json, "t.json");
  } catch (const SymbolTableError& error) {
    return error.what();
  }
  return "no error";
}

TEST(SymbolTable, ParsesTheFragmentExample) {
  SymbolTable table = parse_symbol_table(read_testdata("emission.frag.json"), "emission.frag.json");
  EXPECT_EQ(table.version, 2);
  EXPECT_EQ(table.mode, TableMode::shader);
  ASSERT_EQ(table.stages.size(), 1u);
  const StageSymbols& stage = table.stages[0];
  EXPECT_EQ(stage.stage, Stage::fragment);
  EXPECT_EQ(stage.file, "emission.sgl.frag");
  EXPECT_EQ(stage.glsl_version, 330);
  EXPECT_EQ(stage.glsl_profile, "core");

  const Symbol* le = stage.find(Storage::uniform, "Le");
  ASSERT_NE(le, nullptr);
  EXPECT_EQ(le->type.kind, Kind::spectrum);
  EXPECT_EQ(le->type.glsl_type, "vec3");
  EXPECT_EQ(le->type.dimension.name, "radiance");
  EXPECT_EQ(le->type.dimension.exponents,
            (DimensionExponents{{"energy", 1}, {"length", -2}, {"proj", -1}, {"solid_angle", -1}, {"time", -1}}));
  EXPECT_EQ(to_string(le->declared_at), "emission.sgl.frag:6:28");

  const Symbol* tint = stage.find(Storage::uniform, "tint");
  ASSERT_NE(tint, nullptr);
  EXPECT_EQ(tint->array_size, 2);
  EXPECT_TRUE(tint->type.dimension.exponents.empty());

  const Symbol* environment = stage.find(Storage::uniform, "environment");
  ASSERT_NE(environment, nullptr);
  EXPECT_EQ(environment->type.kind, Kind::sampler);
  ASSERT_TRUE(environment->texel.has_value());
  EXPECT_EQ(environment->texel->kind, Kind::spectrum);

  const Symbol* map = stage.find(Storage::uniform, "cameraFromWorld");
  ASSERT_NE(map, nullptr);
  EXPECT_EQ(map->type.spaces, (std::vector<std::string>{"world", "camera"}));

  const Symbol* focal = stage.find(Storage::uniform, "Camera.focalLength");
  ASSERT_NE(focal, nullptr);
  EXPECT_EQ(focal->block, "Camera");
  EXPECT_EQ(focal->offset, 64);  // after a std140 mat4
  EXPECT_EQ(stage.find(Storage::uniform, "focalLength"), focal);

  const Symbol* color = stage.find(Storage::output, "color");
  ASSERT_NE(color, nullptr);
  EXPECT_EQ(color->location, 0);
  EXPECT_EQ(stage.find(Storage::uniform, "color"), nullptr);
}

TEST(SymbolTable, ProgramModeHoldsEveryStageAndTheVocabularyItUses) {
  SymbolTable table = parse_symbol_table(read_testdata("emission.program.json"));
  EXPECT_EQ(table.mode, TableMode::program);
  ASSERT_NE(table.stage(Stage::vertex), nullptr);
  ASSERT_NE(table.stage(Stage::fragment), nullptr);
  EXPECT_EQ(table.stage(Stage::geometry), nullptr);
  // The prelude is named by its hash; of its base dimensions, units and spaces only those the
  // symbols and the derived dimensions use are listed (no angle, no unit), each without a line in it.
  EXPECT_EQ(table.vocabulary.name, "safegi/prelude.sgl");
  EXPECT_EQ(table.vocabulary.hash.rfind("fnv1a64:", 0), 0u);
  EXPECT_EQ(table.base_dimensions.size(), 5u);
  EXPECT_EQ(table.base_dimensions.front().declared_at.file, "<builtin>");
  EXPECT_EQ(table.base_dimensions.front().declared_at.line, 0);
  EXPECT_TRUE(table.units.empty());
  EXPECT_EQ(table.spaces.size(), 3u);  // the program's own, used or not
  EXPECT_EQ(table.namer().name({{{"energy", 1}, {"length", -2}, {"proj", -1}, {"solid_angle", -1}, {"time", -1}}, ""}),
            "radiance");
  // Every derived dimension stays, used or not: a host's value is named by it ("the host uses spectrum<irradiance>").
  EXPECT_EQ(table.namer().name({{{"energy", 1}, {"length", -2}, {"time", -1}}, ""}), "irradiance");
}

// gl::Stage is made from stages.def, as the checker's Stage is; a table names a stage by its id,
// the names tables have always had (a renamed id would break every reader).
TEST(SymbolTable, StagesAreStagesDefsAndKeepTheirNames) {
  const std::vector<std::string> ids = {
#define SAFEGI_STAGE(id, ...) #id,
#include "safegi/symbol_table/stages.def"
  };
  const std::vector<std::string> names = {"vertex",         "tess_control", "tess_evaluation", "geometry", "task",
                                          "mesh",           "fragment",     "compute",         "ray_generation",
                                          "intersection",   "any_hit",      "closest_hit",     "miss",     "callable"};
  EXPECT_EQ(ids, names);
  for (const std::string& id : ids) {
    const std::optional<Stage> stage = stage_from_string(id);
    ASSERT_TRUE(stage) << id;
    EXPECT_EQ(to_string(*stage), id);
  }
  EXPECT_FALSE(stage_from_string("vert"));  // the file extension is safeglslc's spelling, not the table's
}

TEST(SymbolTable, WritesWhatItReads) {
  const std::string text = read_testdata("emission.program.json");
  SymbolTable table = parse_symbol_table(text);
  EXPECT_EQ(to_json(parse_symbol_table(to_json(table))), to_json(table));
  EXPECT_EQ(to_json(table), text);  // the example is in canonical form
}

TEST(SymbolTable, RejectsInvalidJson) {
  EXPECT_EQ(error_of("{").substr(0, 30), "t.json: error: not valid JSON:");
}

TEST(SymbolTable, NamesThePlaceOfEveryStructuralError) {
  EXPECT_EQ(error_of("[]"), "t.json: error: /: expected an object, found array");
  EXPECT_EQ(error_of(R"({"format":"x"})"), "t.json: error: /format: expected \"safegi-symbol-table\"");
  EXPECT_EQ(error_of(R"({"format":"safegi-symbol-table","version":3})"),
            "t.json: error: /version: unsupported version 3 (this runtime reads 1 to 2)");
  EXPECT_EQ(error_of(R"({"format":"safegi-symbol-table","version":0})"),
            "t.json: error: /version: unsupported version 0 (this runtime reads 1 to 2)");
  EXPECT_EQ(error_of(R"({"format":"safegi-symbol-table","version":1,"mode":"shader"})"),
            "t.json: error: /: missing required member \"stages\"");
  EXPECT_EQ(error_of(R"({"format":"safegi-symbol-table","version":1,"mode":"shader","stages":[
                 {"stage":"pixel","file":"a","glsl_version":{"number":330},"symbols":[]}]})"),
            "t.json: error: /stages/0/stage: unknown stage \"pixel\"");
  EXPECT_EQ(error_of(R"({"format":"safegi-symbol-table","version":1,"mode":"shader","stages":[
                 {"stage":"vertex","file":"a","glsl_version":{"number":330},"symbols":[
                   {"name":"p","storage":"in","kind":"point","glsl_type":"vec3","declared_at":{"file":"a","line":1}}]}]})"),
            "t.json: error: /stages/0/symbols/0: a point needs 1 space(s), found 0");
  EXPECT_EQ(error_of(R"({"format":"safegi-symbol-table","version":1,"mode":"shader","stages":[
                 {"stage":"vertex","file":"a","glsl_version":{"number":330},"symbols":[
                   {"name":"p","storage":"in","kind":"plain","glsl_type":"vec3","array_size":"2",
                    "declared_at":{"file":"a","line":1}}]}]})"),
            "t.json: error: /stages/0/symbols/0/array_size: expected an integer, found string");
  EXPECT_EQ(error_of(R"({"format":"safegi-symbol-table","version":1,"mode":"shader","stages":[
                 {"stage":"vertex","file":"a","glsl_version":{"number":330},"symbols":[
                   {"name":"s","storage":"uniform","kind":"sampler","glsl_type":"sampler2D",
                    "declared_at":{"file":"a","line":1}}]}]})"),
            "t.json: error: /stages/0/symbols/0: a sampler needs a \"texel\" type");
  EXPECT_EQ(error_of(R"({"format":"safegi-symbol-table","version":1,"mode":"shader","stages":[
                 {"stage":"compute","file":"a","glsl_version":{"number":430},"symbols":[
                   {"name":"v","storage":"shared","kind":"plain","glsl_type":"float",
                    "declared_at":{"file":"a","line":1}}]}]})"),
            "t.json: error: /stages/0/symbols/0/storage: unknown storage \"shared\" (expected uniform, in, out or buffer)");
  EXPECT_EQ(error_of(R"({"format":"safegi-symbol-table","version":1,"mode":"shader","stages":[]})"),
            "t.json: error: /stages: a shader-mode table has exactly one stage, found 0");
}

TEST(SymbolTable, ReadsAndWritesShaderStorageBlocks) {
  const std::string text = R"({"format":"safegi-symbol-table","version":1,"mode":"shader","stages":[
      {"stage":"compute","file":"c.comp","glsl_version":{"number":430,"profile":"core"},"symbols":[
        {"name":"Photons","storage":"buffer","kind":"block","glsl_type":"Photons","binding":2,
         "declared_at":{"file":"c.comp","line":3,"column":30},"members":[
           {"name":"flux","storage":"buffer","kind":"spectrum","glsl_type":"vec3","block":"Photons",
            "dimension":{"name":"power","exponents":{"energy":1,"time":-1}},"unsized":true,
            "declared_at":{"file":"c.comp","line":3,"column":55}}]}]}]})";
  SymbolTable table = parse_symbol_table(text, "c.json");
  const Symbol* block = table.stages.at(0).find(Storage::buffer, "Photons");
  ASSERT_NE(block, nullptr);
  EXPECT_EQ(block->binding, 2);
  ASSERT_EQ(block->members.size(), 1u);
  EXPECT_EQ(block->members[0].storage, Storage::buffer);
  EXPECT_TRUE(block->members[0].unsized);
  EXPECT_EQ(table.stages.at(0).find(Storage::uniform, "Photons"), nullptr);
  EXPECT_EQ(to_json(parse_symbol_table(to_json(table))), to_json(table));
}

// Schema v2: what a Vulkan host binds by.
TEST(SymbolTable, ReadsAndWritesWhatAVulkanHostBindsBy) {
  const std::string text = R"({"format":"safegi-symbol-table","version":2,"mode":"shader","stages":[
      {"stage":"fragment","client":"vulkan","file":"v.frag","glsl_version":{"number":460},"symbols":[
        {"name":"Push","storage":"uniform","kind":"block","glsl_type":"Push","push_constant":true,"packing":"std430",
         "size":28,"declared_at":{"file":"v.frag","line":3},"members":[
           {"name":"L","storage":"uniform","kind":"spectrum","glsl_type":"vec3","offset":16,"size":12,
            "dimension":{"name":"radiance","exponents":{"energy":1}},"declared_at":{"file":"v.frag","line":3}}]},
        {"name":"Lights","storage":"buffer","kind":"block","glsl_type":"Lights","set":2,"binding":0,"packing":"std430",
         "declared_at":{"file":"v.frag","line":4},"members":[
           {"name":"frame","storage":"buffer","kind":"plain","glsl_type":"mat2x3","offset":0,"size":32,
            "matrix_stride":16,"row_major":true,"set":2,"binding":0,"declared_at":{"file":"v.frag","line":4}},
           {"name":"power","storage":"buffer","kind":"plain","glsl_type":"vec3","offset":32,"array_stride":16,
            "unsized":true,"set":2,"binding":0,"declared_at":{"file":"v.frag","line":4}}]}],
       "specialization_constants":[
         {"name":"kSamples","id":3,"kind":"plain","glsl_type":"int","type":"int","default":4,
          "declared_at":{"file":"v.frag","line":2}}]}]})";
  SymbolTable table = parse_symbol_table(text, "v.json");
  const StageSymbols& stage = table.stages.at(0);
  EXPECT_EQ(stage.client, Client::vulkan);
  const Symbol* push = stage.find(Storage::uniform, "Push");
  ASSERT_NE(push, nullptr);
  EXPECT_TRUE(push->push_constant);
  EXPECT_FALSE(push->shader_record);
  EXPECT_EQ(push->packing, "std430");
  EXPECT_EQ(push->size, 28);
  EXPECT_EQ(push->members.at(0).offset, 16);
  const Symbol* lights = stage.find(Storage::buffer, "Lights");
  ASSERT_NE(lights, nullptr);
  EXPECT_EQ(lights->set, 2);
  EXPECT_EQ(lights->members.at(0).matrix_stride, 16);
  EXPECT_TRUE(lights->members.at(0).row_major);
  EXPECT_EQ(lights->members.at(1).array_stride, 16);
  ASSERT_EQ(stage.specialization_constants.size(), 1u);
  EXPECT_EQ(stage.specialization_constants[0].id, 3);
  EXPECT_EQ(stage.specialization_constants[0].default_value, 4.0);
  EXPECT_EQ(to_json(parse_symbol_table(to_json(table))), to_json(table));
  EXPECT_NE(to_json(table).find("\"default\": 4,"), std::string::npos);  // an int's default stays an integer

  auto with = [&](std::string_view from, std::string_view to) {
    std::string changed = text;
    changed.replace(changed.find(from), from.size(), to);
    return error_of(changed);
  };
  EXPECT_EQ(with(R"("client":"vulkan")", R"("client":"metal")"),
            "t.json: error: /stages/0/client: expected \"opengl\" or \"vulkan\"");
  EXPECT_EQ(with(R"("push_constant":true,"packing":"std430")", R"("push_constant":true,"packing":"shared")"),
            "t.json: error: /stages/0/symbols/0/packing: unknown packing \"shared\" (expected std140, std430 or scalar)");
  EXPECT_EQ(with(R"("offset":16)", R"("offset":-16)"),
            "t.json: error: /stages/0/symbols/0/members/0/offset: a byte count from 0 to 2^62");
  EXPECT_EQ(with(R"("id":3)", R"("id":-3)"),
            "t.json: error: /stages/0/specialization_constants/0/id: a constant id is not negative");
}

}  // namespace
}  // namespace safegi::gl
