// safegi::to_spirv: program-wide locations, messages at the annotated lines,
// and runtime_gl's reading of a module's interface. The bundled shaders'
// modules are compared with glslangValidator's by ctest spirv.matches_glslangValidator.
#include "safegi/compiler/spirv.hpp"

#include <gtest/gtest.h>

#include <thread>

#include <safegi/symbol_table/error.hpp>
#include <safegi/symbol_table/spirv_interface.hpp>

#include "glslang_check.hpp"

namespace safegi {
namespace {

const SpirvOptions kOpenGL{.client = SpirvClient::opengl};

std::vector<gl::SpirvInterface> interfaces(const SpirvResult& result) {
  std::vector<gl::SpirvInterface> out;
  for (const SpirvModule& module : result.modules) out.push_back(gl::read_spirv_interface(module.words, module.path));
  return out;
}

CompileResult compiled(const std::vector<ShaderSource>& sources) {
  CompileResult r = compile(sources);
  EXPECT_TRUE(r.success) << r.diagnostics_text();
  return r;
}

// glslang numbers each stage's uniforms from 0; GL has one location space per
// program. A uniform of both stages gets one location, the others distinct
// ones; outputs and the next stage's inputs match by name, whatever the order
// of their declarations.
TEST(Spirv, LocationsAreProgramWide) {
  const std::string vertex =
      "#version 330 core\n"
      "uniform mat4 clipFromObject;\n"
      "uniform float scale;\n"
      "layout(location = 0) in vec3 position;\n"
      "out vec3 a;\n"
      "out vec2 b;\n"
      "void main() { a = position; b = position.xy * scale; gl_Position = clipFromObject * vec4(position, 1.0); }\n";
  const std::string fragment =
      "#version 330 core\n"
      "uniform vec3 tint[3];\n"
      "uniform float scale;\n"
      "uniform sampler2D image;\n"
      "in vec2 b;\n"
      "in vec3 a;\n"
      "out vec4 color;\n"
      "void main() { color = texture(image, b) * vec4(a * tint[1] * scale, 1.0); }\n";
  CompileResult r = compiled({{"p.vert", vertex}, {"p.frag", fragment}});
  SpirvResult spirv = to_spirv(r, kOpenGL);
  ASSERT_TRUE(spirv.success) << spirv.log;
  ASSERT_EQ(spirv.modules.size(), 2u);
  const std::vector<gl::SpirvInterface> io = interfaces(spirv);
  const auto& v = io[0].uniforms;
  const auto& f = io[1].uniforms;
  EXPECT_EQ(v.at("clipFromObject"), 0);
  EXPECT_EQ(v.at("scale"), 1);
  EXPECT_EQ(f.at("scale"), 1);   // shared: one location
  EXPECT_EQ(f.at("tint"), 2);    // three locations, 2..4
  EXPECT_EQ(f.at("image"), 5);
  EXPECT_EQ(io[0].outputs.at("a"), io[1].inputs.at("a"));
  EXPECT_EQ(io[0].outputs.at("b"), io[1].inputs.at("b"));
  EXPECT_NE(io[1].inputs.at("a"), io[1].inputs.at("b"));
  EXPECT_EQ(io[0].inputs.at("position"), 0);
}

// Explicit locations are kept, and the others step around them.
TEST(Spirv, ExplicitUniformLocationsAreKept) {
  const std::string fragment =
      "#version 430 core\n"
      "uniform float first;\n"
      "layout(location = 1) uniform vec3 pinned;\n"
      "uniform vec2 pair[2];\n"
      "out vec4 color;\n"
      "void main() { color = vec4(pinned * first, pair[1].x); }\n";
  SpirvResult spirv = to_spirv(compiled({{"x.frag", fragment}}), kOpenGL);
  ASSERT_TRUE(spirv.success) << spirv.log;
  const gl::SpirvInterface io = interfaces(spirv)[0];
  EXPECT_EQ(io.uniforms.at("first"), 0);
  EXPECT_EQ(io.uniforms.at("pinned"), 1);
  EXPECT_EQ(io.uniforms.at("pair"), 2);
}

// glslang's complaint about the plain GLSL points at the annotated file and
// line, or at the #include'd file it came from.
TEST(Spirv, GlslangMessagesPointAtTheAnnotatedSources) {
  CompileOptions options;
  options.read_file = [](const std::string& path) -> std::optional<std::string> {
    if (path == "lights.glsl") return std::string("// lights\nuniform vec3 lightColor;\n");
    return std::nullopt;
  };
  const std::string fragment =
      "#version 450\n"
      "#include <safegi/prelude.sgl>\n"
      "#include \"lights.glsl\"\n"
      "layout(location = 0) out vec4 color;\n"
      "void main() { color = vec4(lightColor, 1.0); }\n";
  CompileResult r = compile({{"shade.sgl.frag", fragment}}, options);
  ASSERT_TRUE(r.success) << r.diagnostics_text();
  SpirvResult vulkan = to_spirv(r, {});
  EXPECT_FALSE(vulkan.success);
  EXPECT_EQ(vulkan.log,
            "lights.glsl:2: error: 'non-opaque uniforms outside a block' : not allowed when using GLSL for Vulkan [E-SPIRV]\n")
      << vulkan.log;
  SpirvResult relaxed = to_spirv(r, {.auto_map_bindings = true, .relaxed_vulkan_rules = true});
  EXPECT_TRUE(relaxed.success) << relaxed.log;
}

// A struct-typed uniform (whose size the table does not give) is left to
// glslang, after the others; several threads may compile at once.
TEST(Spirv, StructUniformsAndThreads) {
  const std::string fragment =
      "#version 330 core\n"
      "struct Light { vec3 position; vec3 color; };\n"
      "uniform float gain;\n"
      "uniform Light light;\n"
      "uniform vec3 material;\n"
      "out vec4 color;\n"
      "void main() { color = vec4(light.color * material * gain + light.position, 1.0); }\n";
  CompileResult r = compiled({{"s.frag", fragment}});
  SpirvResult once = to_spirv(r, kOpenGL);
  ASSERT_TRUE(once.success) << once.log;
  const gl::SpirvInterface io = interfaces(once)[0];
  // One stage: glslang's numbering, glslangValidator -G --aml's (declaration order; the struct takes
  // a location per member).
  EXPECT_EQ(io.uniforms.at("gain"), 0);
  EXPECT_EQ(io.uniforms.at("light"), 1);
  EXPECT_EQ(io.uniforms.at("material"), 3);  // "material" is no matrix type
  std::vector<std::thread> threads;
  std::vector<SpirvResult> results(4);
  for (SpirvResult& each : results) threads.emplace_back([&each, &r] { each = to_spirv(r, kOpenGL); });
  for (std::thread& t : threads) t.join();
  for (const SpirvResult& each : results) EXPECT_EQ(each.modules.at(0).words, once.modules.at(0).words);
}

TEST(Spirv, NeedsASuccessfulCompile) {
  CompileResult r = compile({{"bad.frag", "#version 450\nvoid main() { undeclared = 1.0; }\n"}});
  ASSERT_FALSE(r.success);
  SpirvResult spirv = to_spirv(r, kOpenGL);
  EXPECT_FALSE(spirv.success);
  EXPECT_TRUE(spirv.modules.empty());
}

TEST(Spirv, TargetEnvironments) {
  SpirvOptions options;
  EXPECT_TRUE(apply_target_env("opengl", options));
  EXPECT_EQ(options.client, SpirvClient::opengl);
  EXPECT_TRUE(apply_target_env("vulkan1.3", options));
  EXPECT_EQ(options.client, SpirvClient::vulkan);
  EXPECT_EQ(options.vulkan_minor, 3);
  EXPECT_TRUE(apply_target_env("spirv1.4", options));
  EXPECT_EQ(options.spirv_minor, 4);
  EXPECT_FALSE(apply_target_env("vulkan1.4", options));
  EXPECT_FALSE(apply_target_env("spirv1.7", options));
  EXPECT_FALSE(apply_target_env("opengl450", options));
  options.vulkan_minor = 4;
  EXPECT_FALSE(to_spirv(compiled({{"e.frag", "#version 450\nvoid main() {}\n"}}), options).success);
}

// Words become the little-endian bytes of a .spv file: the magic first.
TEST(Spirv, BytesAreLittleEndian) {
  EXPECT_EQ(spirv_bytes({0x07230203u, 0x00010000u}), std::string("\x03\x02\x23\x07\x00\x00\x01\x00", 8));
}

TEST(Spirv, ReadingSomethingElseIsAnError) {
  const std::vector<std::uint32_t> glsl_bytes = {0x73726576u, 0x206e6f69u, 0x0a303534u, 0u, 0u};
  EXPECT_THROW(gl::read_spirv_interface(glsl_bytes, "x.spv"), gl::ShaderError);
  const std::vector<std::uint32_t> truncated = {0x07230203u, 0x00010000u, 0u, 10u, 0u, (9u << 16) | 5u, 1u};
  try {
    gl::read_spirv_interface(truncated, "t.spv");
    FAIL();
  } catch (const gl::ShaderError& error) {
    EXPECT_STREQ(error.what(), "t.spv: error: truncated SPIR-V instruction at word 5");
  }
}

}  // namespace
}  // namespace safegi
