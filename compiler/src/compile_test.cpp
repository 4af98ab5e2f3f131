// safegi::compile as a library: stages, program mode, diagnostics as values,
// the built-in prelude, options, and concurrent use.
#include <gtest/gtest.h>

#include <thread>

#include "glslang_check.hpp"
#include "safegi/compiler/cli.hpp"
#include "safegi/compiler/compile.hpp"

namespace safegi {
namespace {

const char* kFrag = R"(#version 330 core
#include <safegi/prelude.sgl>
uniform spectrum<radiance> Le;
uniform float<1> gain;
out vec4 color;
void main() {
    spectrum<radiance> L = Le * gain;
    color = vec4(L, 1.0);
}
)";

TEST(StageFromPath, ExtensionsWithAndWithoutTheAnnotatedSuffix) {
  EXPECT_EQ(stage_from_path("a/light.sgl.frag"), Stage::fragment);
  EXPECT_EQ(stage_from_path("light.frag"), Stage::fragment);
  EXPECT_EQ(stage_from_path("light.vert.sgl"), Stage::vertex);
  EXPECT_EQ(stage_from_path("x.comp"), Stage::compute);
  EXPECT_EQ(stage_from_path("x.tesc"), Stage::tess_control);
  EXPECT_EQ(stage_from_path("x.tese"), Stage::tess_evaluation);
  EXPECT_EQ(stage_from_path("x.geom"), Stage::geometry);
  EXPECT_EQ(stage_from_path("x.glsl"), std::nullopt);
  EXPECT_EQ(stage_from_path("frag"), std::nullopt);
  EXPECT_EQ(stage_from_name("fragment"), Stage::fragment);
  EXPECT_EQ(stage_from_name("vert"), Stage::vertex);
  EXPECT_EQ(stage_from_name("pixel"), std::nullopt);
}

TEST(StageFromPath, VulkanStagesByTheirExtensionsAndNames) {
  EXPECT_EQ(stage_from_path("scene.rgen"), Stage::ray_generation);
  EXPECT_EQ(stage_from_path("scene.sgl.rchit"), Stage::closest_hit);
  EXPECT_EQ(stage_from_path("scene.rahit"), Stage::any_hit);
  EXPECT_EQ(stage_from_path("scene.rint"), Stage::intersection);
  EXPECT_EQ(stage_from_path("scene.rmiss"), Stage::miss);
  EXPECT_EQ(stage_from_path("scene.rcall"), Stage::callable);
  EXPECT_EQ(stage_from_path("meshlet.mesh"), Stage::mesh);
  EXPECT_EQ(stage_from_path("meshlet.task"), Stage::task);
  EXPECT_EQ(stage_from_name("raygen"), Stage::ray_generation);
  EXPECT_EQ(stage_from_name("rchit"), Stage::closest_hit);
  for (const StageInfo& s : stage_table()) {
    EXPECT_EQ(stage_from_name(s.extension), s.stage) << s.extension;
    EXPECT_EQ(stage_from_path(std::string("x.") + s.extension), s.stage) << s.extension;
    ASSERT_EQ(to_table_stage(s.stage).has_value(), true) << s.extension;
    EXPECT_EQ(stage_from_name(gl::to_string(*to_table_stage(s.stage))), s.stage) << s.extension;  // "tess_control"
  }
}

// docs/safeglslc.md lists the stages' extensions as stages.def has them.
TEST(StageFromPath, TheDocsListEveryStageExtension) {
  const std::string doc = testing::read_text_file(SAFEGI_DOCS_DIR "/safeglslc.md");
  const std::string sentence = "The stage comes from the last extension: `" + stage_extension_list(" ", ".") + "`";
  std::string flat = doc;
  for (std::size_t at = flat.find('\n'); at != std::string::npos; at = flat.find('\n', at)) flat[at] = ' ';
  EXPECT_NE(flat.find(sentence), std::string::npos) << "docs/safeglslc.md should say: " << sentence;
  const std::string flag = "stage of every input: `" + stage_extension_list(" ") + "`";
  EXPECT_NE(flat.find(flag), std::string::npos) << "docs/safeglslc.md should say: " << flag;
}

TEST(Compile, KeepsTheAnalysisOnlyWhenAskedEvenWithTypeErrors) {
  EXPECT_EQ(compile({{"light.sgl.frag", kFrag}}).stages.at(0).analysis, nullptr);
  CompileOptions options;
  options.keep_analysis = true;
  std::string wrong = kFrag;
  wrong.replace(wrong.find("Le * gain"), 9, "gain");  // a type error: the stage is still checked
  CompileResult r = compile({{"light.sgl.frag", wrong}}, options);
  ASSERT_FALSE(r.success);
  const StageAnalysis* a = r.stages.at(0).analysis.get();
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(r.sources->path(a->file), "light.sgl.frag");
  bool found = false;
  for (const SymbolOccurrence& o : a->checked.symbols)
    if (o.name == "gain" && !o.is_declaration) {
      found = true;
      EXPECT_EQ(o.type_text, "float<dimensionless>");
      EXPECT_EQ(o.declaration.begin.line, 4u);
    }
  EXPECT_TRUE(found);
  // A syntax error: nothing was checked, so there is nothing to keep.
  EXPECT_EQ(compile({{"light.sgl.frag", "void main( {}"}}, options).stages.at(0).analysis, nullptr);
}

TEST(Compile, OneShaderGivesGlslTheDriverAcceptsAndAShaderTable) {
  CompileResult r = compile({{"light.sgl.frag", kFrag}});
  ASSERT_TRUE(r.success) << r.diagnostics_text();
  ASSERT_EQ(r.stages.size(), 1u);
  EXPECT_EQ(r.stages[0].stage, Stage::fragment);
  testing::GlslangVerdict v = testing::glslang_validate(r.stages[0].glsl, Stage::fragment);
  EXPECT_TRUE(v.accepted) << v.log << r.stages[0].glsl;
  EXPECT_EQ(r.symbols.mode, gl::TableMode::shader);
  ASSERT_EQ(r.symbols.stages.size(), 1u);
  const gl::Symbol* le = r.symbols.stages[0].find(gl::Storage::uniform, "Le");
  ASSERT_NE(le, nullptr);
  EXPECT_EQ(le->type.kind, gl::Kind::spectrum);
  EXPECT_EQ(le->type.dimension.name, "radiance");
  EXPECT_EQ(le->declared_at.line, 3);
  // What we write is what the runtime reads.
  gl::SymbolTable back = gl::parse_symbol_table(r.symbols_json());
  EXPECT_EQ(gl::to_json(back), r.symbols_json());
}

// The symbol table kinds of docs/symbol-table.md: an affine map, a rigid one
// and a projective one are told apart, so runtime_gl binds each to its C++ type.
TEST(Compile, MapsKeepTheirKindInTheSymbolTable) {
  CompileResult r = compile({{"maps.sgl.vert", R"(#version 330 core
#include <safegi/prelude.sgl>
space object;
space world;
space clip;
uniform map<object, world> worldFromObject;
uniform rigidmap<object, world> rigidWorldFromObject;
uniform projmap<world, clip> clipFromWorld;
in point<object> p;
void main() { gl_Position = clipFromWorld * (worldFromObject * p); }
)"}});
  ASSERT_TRUE(r.success) << r.diagnostics_text();
  const gl::StageSymbols& stage = r.symbols.stages.at(0);
  auto kind_of = [&](const char* name) {
    const gl::Symbol* symbol = stage.find(gl::Storage::uniform, name);
    EXPECT_NE(symbol, nullptr) << name;
    return symbol ? symbol->type.kind : gl::Kind::plain;
  };
  EXPECT_EQ(kind_of("worldFromObject"), gl::Kind::map);
  EXPECT_EQ(kind_of("rigidWorldFromObject"), gl::Kind::map);
  EXPECT_EQ(kind_of("clipFromWorld"), gl::Kind::projective_map);
  EXPECT_EQ(stage.find(gl::Storage::uniform, "clipFromWorld")->type.spaces,
            (std::vector<std::string>{"world", "clip"}));
}

// Shader storage blocks are part of the interface a host sees; shared
// variables are workgroup memory and are not.
TEST(Compile, StorageBlocksAreListedAndSharedVariablesAreNot) {
  CompileResult r = compile({{"photons.sgl.comp", R"(#version 430 core
#include <safegi/prelude.sgl>
layout(local_size_x = 64) in;
layout(std430, binding = 2) buffer Photons { spectrum<power> flux[]; } photons;
shared spectrum<power> partial[64];
void main() { partial[gl_LocalInvocationIndex] = photons.flux[gl_GlobalInvocationID.x]; }
)"}});
  ASSERT_TRUE(r.success) << r.diagnostics_text();
  const gl::StageSymbols& stage = r.symbols.stages.at(0);
  ASSERT_EQ(stage.symbols.size(), 1u);
  const gl::Symbol& block = stage.symbols[0];
  EXPECT_EQ(block.name, "Photons");
  EXPECT_EQ(block.storage, gl::Storage::buffer);
  EXPECT_EQ(block.type.kind, gl::Kind::block);
  EXPECT_EQ(block.instance_name, "photons");
  EXPECT_EQ(block.binding, 2);
  ASSERT_EQ(block.members.size(), 1u);
  EXPECT_EQ(block.members[0].name, "flux");
  EXPECT_EQ(block.members[0].type.kind, gl::Kind::spectrum);
  EXPECT_EQ(block.members[0].printed_type, "spectrum<power>");
  EXPECT_FALSE(block.members[0].array_size.has_value());
  EXPECT_TRUE(block.members[0].unsized);
}

TEST(Compile, DiagnosticsAreValuesWithLocations) {
  CompileResult r = compile({{"bad.frag", "#version 330 core\n#include <safegi/prelude.sgl>\n"
                                          "void main() { float<length> d = 1.0 * meter; float<time> t = d; }\n"}});
  EXPECT_FALSE(r.success);
  ASSERT_GE(r.error_count(), 1u);
  EXPECT_EQ(r.diagnostics[0].range.begin.line, 3u);
  EXPECT_NE(r.diagnostics_text().find("bad.frag:3:"), std::string::npos) << r.diagnostics_text();
  EXPECT_TRUE(r.stages[0].glsl.empty());
  EXPECT_TRUE(r.symbols.stages.empty());
}

TEST(Compile, UnknownStageIsAnError) {
  CompileResult r = compile({{"shader.glsl", kFrag}});
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.diagnostics_text().find("cannot tell the shader stage"), std::string::npos);
}

TEST(Compile, ProgramModeChecksStagesAgainstEachOther) {
  const char* vert = "#version 330 core\n#include <safegi/prelude.sgl>\nout spectrum<irradiance> L;\n"
                     "void main() { L = spectrum<irradiance>(0.0); gl_Position = vec4(0.0); }\n";
  const char* frag = "#version 330 core\n#include <safegi/prelude.sgl>\nin spectrum<radiance> L;\nout vec4 c;\n"
                     "void main() { c = vec4(L, 1.0); }\n";
  CompileResult r = compile({{"p.sgl.vert", vert}, {"p.sgl.frag", frag}});
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.diagnostics_text().find("p.sgl.frag:3"), std::string::npos) << r.diagnostics_text();

  const char* good_vert = "#version 330 core\n#include <safegi/prelude.sgl>\nout spectrum<radiance> L;\n"
                          "void main() { L = spectrum<radiance>(0.0); gl_Position = vec4(0.0); }\n";
  CompileResult ok = compile({{"p.sgl.vert", good_vert}, {"p.sgl.frag", frag}});
  ASSERT_TRUE(ok.success) << ok.diagnostics_text();
  EXPECT_EQ(ok.symbols.mode, gl::TableMode::program);
  EXPECT_EQ(ok.symbols.stages.size(), 2u);
}

TEST(Compile, ProgramModeMatchesByLocationAndByBlock) {
  const char* vert = "#version 410 core\n#include <safegi/prelude.sgl>\nspace world;\n"
                     "layout(location = 2) out float<length> depth;\n"
                     "out Surface { point<world> P; } vs_out;\n"
                     "void main() { depth = 0.0; vs_out.P = point<world>(0.0); gl_Position = vec4(0.0); }\n";
  const char* frag = "#version 410 core\n#include <safegi/prelude.sgl>\nspace world;\n"
                     "layout(location = 2) in float<time> t;\n"
                     "in Surface { point<world> P; } fs_in;\n"
                     "out vec4 c;\nvoid main() { c = vec4(fs_in.P, t / second); }\n";
  CompileResult r = compile({{"p.sgl.vert", vert}, {"p.sgl.frag", frag}});
  EXPECT_FALSE(r.success);
  EXPECT_EQ(r.diagnostics_text(),
            "p.sgl.frag:4:37: error: input 't' has type float<time> but the vertex stage's output 'depth' (matched by "
            "location 2) has type float<length> [E-STAGE-MISMATCH]\n"
            "layout(location = 2) in float<time> t;\n"
            "                                    ^\n"
            "p.sgl.vert:4:40: note: output 'depth' declared here as float<length>\n"
            "layout(location = 2) out float<length> depth;\n"
            "                                       ^~~~~\n");
}

TEST(Compile, TwoShadersOfOneStageAreRefused) {
  CompileResult r = compile({{"a.frag", kFrag}, {"b.frag", kFrag}});
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.diagnostics_text().find("at most one frag stage"), std::string::npos) << r.diagnostics_text();
}

TEST(Compile, IncludesComeFromTheCallersReader) {
  CompileOptions options;
  options.include_paths = {"inc"};
  options.read_file = [](const std::string& path) -> std::optional<std::string> {
    if (path == "inc/common.glsl") return std::string("float twice(float x) { return 2.0 * x; }\n");
    return std::nullopt;
  };
  CompileResult r = compile({{"m.frag", "#version 330 core\n#include \"common.glsl\"\nout vec4 c;\n"
                                        "void main() { c = vec4(twice(1.0)); }\n"}},
                            options);
  ASSERT_TRUE(r.success) << r.diagnostics_text();
  const std::string& glsl = r.stages[0].glsl;
  EXPECT_NE(glsl.find("#line 1 1\nfloat twice"), std::string::npos) << glsl;
  EXPECT_NE(glsl.find("#line 3 0\nout vec4 c;"), std::string::npos) << glsl;
  EXPECT_TRUE(testing::glslang_validate(glsl, Stage::fragment).accepted) << glsl;
  ASSERT_EQ(r.symbols.stages[0].source_files.size(), 2u);
  EXPECT_EQ(r.symbols.stages[0].source_files[1], "inc/common.glsl");
  EXPECT_EQ(r.dependencies, (std::vector<std::string>{"m.frag", "inc/common.glsl"}));  // what -MD writes
}

TEST(Compile, DefinesReachTheDriverToo) {
  CompileOptions options;
  options.defines = {{"USE_GAIN", "1"}};
  CompileResult r = compile({{"d.frag", "#version 330 core\nout vec4 c;\nvoid main() {\n#ifdef USE_GAIN\n"
                                        "  c = vec4(2.0);\n#else\n  c = vec4(float<length>(1.0));\n#endif\n}\n"}},
                            options);
  ASSERT_TRUE(r.success) << r.diagnostics_text();
  EXPECT_EQ(r.stages[0].glsl.rfind("#version 330 core\n#define USE_GAIN 1\n#line 2\nout vec4 c;", 0), 0u)
      << r.stages[0].glsl;
}

TEST(Compile, WerrorAndErrorLimit) {
  CompileOptions options;
  options.strict = true;
  CompileResult warn = compile({{"w.frag", "#version 330 core\nuniform float gain;\nout vec4 c;\nvoid main() { c = vec4(gain); }\n"}},
                               options);
  EXPECT_TRUE(warn.success);
  EXPECT_GE(warn.warning_count(), 1u);
  options.diagnostics.warnings_as_errors = true;
  EXPECT_FALSE(compile({{"w.frag", "#version 330 core\nuniform float gain;\nvoid main() {}\n"}}, options).success);

  CompileOptions limited;
  limited.diagnostics.error_limit = 1;
  CompileResult many = compile({{"e.frag", "#version 330 core\nvoid main() { a = 1; b = 2; c = 3; }\n"}}, limited);
  EXPECT_LE(many.error_count(), 2u);
}

TEST(Compile, IsSafeFromSeveralThreads) {
  std::vector<std::string> outputs(8);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < outputs.size(); ++i)
    threads.emplace_back([&outputs, i] { outputs[i] = compile({{"light.sgl.frag", kFrag}}).stages[0].glsl; });
  for (std::thread& t : threads) t.join();
  for (const std::string& o : outputs) EXPECT_EQ(o, outputs[0]);
  EXPECT_FALSE(outputs[0].empty());
}

}  // namespace
}  // namespace safegi
