// What a Vulkan host binds by, in the symbol table: descriptor sets and
// bindings, push-constant and buffer member offsets, strides, and the ids of
// specialization constants. Each is checked against what glslang put in the
// SPIR-V module of the same shader (its decorations), so the table and the
// module cannot disagree.
#include <gtest/gtest.h>

#include <map>
#include <span>
#include <tuple>

#include "safegi/compiler/compile.hpp"
#include "safegi/compiler/spirv.hpp"
#include "safegi/symbol_table/spirv_interface.hpp"

namespace safegi {
namespace {

// From the SPIR-V specification (unified 1.6), sections 3.20 and 3.32.
constexpr std::uint32_t kOpName = 5, kOpMemberName = 6, kOpTypeStruct = 30, kOpDecorate = 71, kOpMemberDecorate = 72;
constexpr std::uint32_t kSpecId = 1, kArrayStride = 6, kMatrixStride = 7, kRowMajor = 4, kBinding = 33,
                        kDescriptorSet = 34, kOffset = 35;

// The decorations of a module, by the names glslang keeps (-V keeps OpName).
struct Decorations {
  std::map<std::uint32_t, std::string> names;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::string> member_names;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> on;  // (id, decoration) -> value
  std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, std::uint32_t> on_member;  // (struct, member, decoration)
  std::map<std::uint32_t, std::vector<std::uint32_t>> member_types;  // struct -> its members' type ids

  std::uint32_t id_named(const std::string& name) const {
    for (const auto& [id, text] : names)
      if (text == name) return id;
    ADD_FAILURE() << "no OpName " << name;
    return 0;
  }
  // The member decoration of `member` of the struct named `type`, or -1.
  long long member(const std::string& type, const std::string& member, std::uint32_t decoration) const {
    const std::uint32_t id = id_named(type);
    for (const auto& [key, text] : member_names)
      if (key.first == id && text == member) {
        const auto found = on_member.find({id, key.second, decoration});
        return found == on_member.end() ? -1 : static_cast<long long>(found->second);
      }
    ADD_FAILURE() << "no member " << member << " in " << type;
    return -1;
  }
  // The ArrayStride of the type of `member` (arrays carry it on their type, not on the member).
  long long array_stride(const std::string& type, const std::string& member) const {
    const std::uint32_t id = id_named(type);
    for (const auto& [key, text] : member_names)
      if (key.first == id && text == member) {
        const auto found = on.find({member_types.at(id).at(key.second), kArrayStride});
        return found == on.end() ? -1 : static_cast<long long>(found->second);
      }
    return -1;
  }
  long long decoration(const std::string& name, std::uint32_t decoration) const {
    const auto found = on.find({id_named(name), decoration});
    return found == on.end() ? -1 : static_cast<long long>(found->second);
  }
};

Decorations decorations_of(const std::vector<std::uint32_t>& words) {
  Decorations d;
  gl::for_each_spirv_instruction(words, "module", [&d](std::uint32_t opcode, std::span<const std::uint32_t> operands) {
    if (opcode == kOpName) d.names[operands[0]] = gl::spirv_literal_string(operands.subspan(1));
    if (opcode == kOpTypeStruct) d.member_types[operands[0]].assign(operands.begin() + 1, operands.end());
    if (opcode == kOpMemberName) d.member_names[{operands[0], operands[1]}] = gl::spirv_literal_string(operands.subspan(2));
    if (opcode == kOpDecorate) d.on[{operands[0], operands[1]}] = operands.size() > 2 ? operands[2] : 1;
    if (opcode == kOpMemberDecorate)
      d.on_member[{operands[0], operands[1], operands[2]}] = operands.size() > 3 ? operands[3] : 1;
  });
  return d;
}

struct VulkanStage {
  gl::StageSymbols symbols;
  Decorations module;
};

VulkanStage compile_for_vulkan(const std::string& path, const std::string& text) {
  CompileOptions options;
  options.vulkan = 100;
  CompileResult compiled = compile({{path, text}}, options);
  EXPECT_TRUE(compiled.success) << compiled.diagnostics_text();
  SpirvOptions spirv_options;
  spirv_options.vulkan_minor = 2;
  SpirvResult spirv = to_spirv(compiled, spirv_options);
  EXPECT_TRUE(spirv.success) << spirv.log;
  if (!compiled.success || !spirv.success) return {};
  return {compiled.symbols.stages.at(0), decorations_of(spirv.modules.at(0).words)};
}

const gl::Symbol& symbol(const gl::StageSymbols& stage, const std::string& name) {
  for (const gl::Symbol& s : stage.symbols)
    if (s.name == name) return s;
  throw std::runtime_error("no symbol " + name);
}

// Every member with an offset in the table has glslang's Offset (and strides).
void expect_members_match(const gl::Symbol& block, const Decorations& module) {
  ASSERT_FALSE(block.members.empty());
  for (const gl::Symbol& m : block.members) {
    SCOPED_TRACE(block.name + "." + m.name);
    ASSERT_TRUE(m.offset.has_value());
    EXPECT_EQ(*m.offset, module.member(block.name, m.name, kOffset));
    if (m.array_stride) {
      EXPECT_EQ(*m.array_stride, module.array_stride(block.name, m.name));
    }
    if (m.matrix_stride) {
      EXPECT_EQ(*m.matrix_stride, module.member(block.name, m.name, kMatrixStride));
    }
    if (m.row_major) {
      EXPECT_EQ(module.member(block.name, m.name, kRowMajor), 1);
    }
  }
}

constexpr const char* kFragment = R"(#version 460
#extension GL_EXT_scalar_block_layout : require
#include <safegi/prelude.sgl>
space world;
layout(constant_id = 3) const int kSamples = 4;
layout(constant_id = 7) const float kScale = 1.5;
layout(push_constant) uniform Push {
  layout(offset = 16) float<1> roughness;
  spectrum<radiance> L;
  mat3 tilt;
} pc;
layout(set = 1, binding = 2) uniform Camera { mat3 basis; float<length> aperture[3]; point<world> eye; } cam;
layout(binding = 1) uniform sampler2D albedoTex;
layout(std430, set = 2, binding = 0) buffer Lights { layout(row_major) mat2x3 frame; spectrum<radiance> power[]; } lights;
layout(scalar, set = 2, binding = 1) buffer Packed { vec3 a; float b; vec2 c[2]; } packed_data;
layout(location = 0) in normal<world> N;
layout(location = 0) out vec4 color;
layout(location = 1) out spectrum<radiance> radiance_out;
layout(location = 2) out float<length> aperture_out;
void main() {
  radiance_out = pc.L * float(kSamples) * kScale * pc.roughness + lights.power[0];
  aperture_out = cam.aperture[1] + distance(cam.eye, cam.eye);
  vec3 plain = pc.tilt[0] + cam.basis[1] + lights.frame[0] + packed_data.a + packed_data.c[1].xxy * packed_data.b;
  color = vec4(plain + texture(albedoTex, vec2(0)).rgb, 1.0);
}
)";

TEST(VulkanInterface, MemberOffsetsAndStridesAreTheModulesOwn) {
  const VulkanStage stage = compile_for_vulkan("v.frag", kFragment);
  ASSERT_FALSE(stage.symbols.symbols.empty());
  EXPECT_EQ(stage.symbols.client, gl::Client::vulkan);

  const gl::Symbol& push = symbol(stage.symbols, "Push");
  EXPECT_TRUE(push.push_constant);
  EXPECT_FALSE(push.set.has_value());  // a push constant is in no descriptor set
  EXPECT_EQ(push.packing, "std430");   // GL_KHR_vulkan_glsl's default for push constants
  expect_members_match(push, stage.module);
  EXPECT_EQ(push.members[0].offset, 16);
  EXPECT_EQ(push.members[1].offset, 32);  // a vec3 aligns to 16
  EXPECT_EQ(push.members[1].type.dimension.name, "radiance");
  EXPECT_EQ(push.members[2].matrix_stride, 16);
  EXPECT_EQ(push.size, 96);  // the range a host pushes: to the end of tilt, three 16-byte columns from 48

  const gl::Symbol& camera = symbol(stage.symbols, "Camera");
  EXPECT_EQ(camera.packing, "std140");  // a uniform block's default in Vulkan GLSL
  EXPECT_EQ(camera.set, 1);
  EXPECT_EQ(camera.binding, 2);
  EXPECT_EQ(stage.module.decoration("cam", kDescriptorSet), 1);
  EXPECT_EQ(stage.module.decoration("cam", kBinding), 2);
  expect_members_match(camera, stage.module);
  const gl::Symbol& aperture = camera.members[1];
  EXPECT_EQ(aperture.array_stride, 16);  // std140 rounds an array's stride up to 16
  EXPECT_EQ(aperture.size, 48);
  EXPECT_EQ(camera.members[2].offset, 96);

  const gl::Symbol& lights = symbol(stage.symbols, "Lights");
  EXPECT_EQ(lights.packing, "std430");
  expect_members_match(lights, stage.module);
  EXPECT_TRUE(lights.members[0].row_major);
  EXPECT_EQ(lights.members[1].array_stride, 16);
  EXPECT_FALSE(lights.members[1].size.has_value());  // runtime-sized: as long as the buffer bound
  EXPECT_FALSE(lights.size.has_value());

  const gl::Symbol& packed = symbol(stage.symbols, "Packed");
  EXPECT_EQ(packed.packing, "scalar");
  expect_members_match(packed, stage.module);
  EXPECT_EQ(packed.members[1].offset, 12);  // scalar layout: b packs right after a's three floats
  EXPECT_EQ(packed.members[2].array_stride, 8);
  EXPECT_EQ(packed.size, 32);

  // A resource that says no set is in set 0 (GL_KHR_vulkan_glsl), as glslang decorates it.
  const gl::Symbol& albedo = symbol(stage.symbols, "albedoTex");
  EXPECT_EQ(albedo.set, 0);
  EXPECT_EQ(stage.module.decoration("albedoTex", kDescriptorSet), 0);
  EXPECT_EQ(stage.module.decoration("albedoTex", kBinding), 1);
  EXPECT_FALSE(symbol(stage.symbols, "N").set.has_value());  // inputs are no resources

  ASSERT_EQ(stage.symbols.specialization_constants.size(), 2u);
  const gl::SpecializationConstant& samples = stage.symbols.specialization_constants[0];
  EXPECT_EQ(samples.name, "kSamples");
  EXPECT_EQ(samples.id, 3);
  EXPECT_EQ(samples.type.glsl_type, "int");
  EXPECT_EQ(samples.default_value, 4.0);
  EXPECT_EQ(stage.module.decoration("kSamples", kSpecId), 3);
  const gl::SpecializationConstant& scale = stage.symbols.specialization_constants[1];
  EXPECT_EQ(scale.id, 7);
  EXPECT_EQ(scale.default_value, 1.5);
  EXPECT_EQ(stage.module.decoration("kScale", kSpecId), 7);
}

// An array of structs in a buffer (a scene's triangles, a BVH's nodes): the table lists the
// struct's fields, annotations included, each placed from the start of the struct, as glslang
// decorates the struct type's members; nested structs likewise.
TEST(VulkanInterface, StructFieldsArePlacedAsTheModuleDecoratesThem) {
  const VulkanStage stage = compile_for_vulkan(
      "s.comp", "#version 460\n#include <safegi/prelude.sgl>\nspace world;\n"
                "struct Emitter { spectrum<radiance> Le; float<area> area; };\n"
                "struct Triangle { point<world> p0; vector<world> e1; Emitter emitter; mat2 uvs; float<length> r[2]; };\n"
                "layout(local_size_x = 1) in;\n"
                "layout(std430, set = 0, binding = 0) buffer Scene { uint count; Triangle triangles[]; } scene;\n"
                "layout(std140, set = 0, binding = 1) uniform Light { Emitter lamp; } light;\n"
                "void main() { scene.triangles[0].emitter.Le = light.lamp.Le * scene.triangles[0].r[1] / "
                "scene.triangles[0].r[0]; }\n");
  const gl::Symbol& triangles = symbol(stage.symbols, "Scene").members.at(1);
  ASSERT_EQ(triangles.fields.size(), 5u);
  for (const gl::Symbol& f : triangles.fields) {
    SCOPED_TRACE("Triangle." + f.name);
    ASSERT_TRUE(f.offset.has_value());
    EXPECT_EQ(*f.offset, stage.module.member("Triangle", f.name, kOffset));
  }
  EXPECT_EQ(triangles.fields[0].type.kind, gl::Kind::point);
  EXPECT_EQ(triangles.fields[0].type.spaces, std::vector<std::string>{"world"});
  EXPECT_EQ(triangles.fields[3].matrix_stride, stage.module.member("Triangle", "uvs", kMatrixStride));
  EXPECT_EQ(triangles.fields[4].array_stride, 4);  // std430: floats pack
  const gl::Symbol& emitter = triangles.fields[2];
  ASSERT_EQ(emitter.fields.size(), 2u);
  EXPECT_EQ(emitter.fields[0].type.dimension.name, "radiance");
  EXPECT_EQ(emitter.fields[1].offset, stage.module.member("Emitter", "area", kOffset));
  EXPECT_EQ(triangles.array_stride, stage.module.array_stride("Scene", "triangles"));

  // The same struct under std140 in a uniform block: the same field order, std140's offsets.
  const gl::Symbol& lamp = symbol(stage.symbols, "Light").members.at(0);
  ASSERT_EQ(lamp.fields.size(), 2u);
  EXPECT_EQ(lamp.fields[1].offset, 12);  // after a vec3 (12 bytes), a float packs in
}

TEST(VulkanInterface, WorkGroupSizeIdsAreSpecializationConstants) {
  const VulkanStage stage = compile_for_vulkan(
      "w.comp", "#version 450\nlayout(local_size_x_id = 4, local_size_y_id = 5) in;\n"
                "layout(set = 0, binding = 0) buffer Out { uint v[]; } o;\n"
                "void main() { o.v[gl_GlobalInvocationID.x] = gl_WorkGroupSize.x; }\n");
  ASSERT_EQ(stage.symbols.specialization_constants.size(), 2u);
  EXPECT_EQ(stage.symbols.specialization_constants[0].name, "gl_WorkGroupSize.x");
  EXPECT_EQ(stage.symbols.specialization_constants[0].id, 4);
  EXPECT_EQ(stage.symbols.specialization_constants[1].name, "gl_WorkGroupSize.y");
  EXPECT_EQ(stage.symbols.specialization_constants[1].id, 5);
}

// Offsets stop at the first member of a type the checker does not model
// (64-bit and 16-bit arithmetic types): left out, never guessed. A
// shader-record block is in no descriptor set.
TEST(VulkanInterface, SixtyFourBitMembersArePlacedAndAShaderRecordHasNoSet) {
  const VulkanStage stage = compile_for_vulkan(
      "r.rchit", "#version 460\n#extension GL_EXT_ray_tracing : require\n"
                 "#extension GL_EXT_shader_explicit_arithmetic_types : require\n"
                 "struct Node { int texture; uint64_t address; };\n"
                 "layout(set = 0, binding = 4) buffer Nodes { vec2 scale; Node nodes[]; } nodes;\n"
                 "layout(set = 0, binding = 5) buffer Address { float t; uint64_t next; f16vec3 h; } address;\n"
                 "layout(shaderRecordEXT) buffer Record { vec4 tint; };\n"
                 "layout(location = 0) rayPayloadInEXT vec3 hit;\n"
                 "void main() { hit = tint.rgb * nodes.scale.x * float(nodes.nodes[0].texture); }\n");
  const gl::Symbol& block = symbol(stage.symbols, "Nodes");
  EXPECT_EQ(block.members.at(0).offset, 0);
  EXPECT_EQ(block.members.at(1).offset, 8);  // a struct with a uint64_t aligns to 8
  EXPECT_EQ(block.members.at(1).array_stride, 16);
  EXPECT_EQ(block.members.at(1).type.glsl_type, "Node");
  EXPECT_FALSE(block.size.has_value());  // runtime-sized
  const gl::Symbol& address = symbol(stage.symbols, "Address");
  EXPECT_EQ(address.members.at(0).offset, 0);
  EXPECT_EQ(address.members.at(1).type.glsl_type, "uint64_t");
  EXPECT_EQ(address.members.at(1).offset, 8);
  EXPECT_EQ(address.members.at(1).size, 8);
  EXPECT_EQ(address.members.at(2).offset, 16);  // f16vec3: 6 bytes aligned to 8
  EXPECT_EQ(address.members.at(2).size, 6);
  EXPECT_EQ(address.size, 22);
  const gl::Symbol& record = symbol(stage.symbols, "Record");
  EXPECT_TRUE(record.shader_record);
  EXPECT_FALSE(record.set.has_value());
  EXPECT_EQ(record.members.at(0).offset, 0);
}

// GL_EXT_scalar_block_layout: 8-, 16- and 64-bit members align to their scalars.
TEST(VulkanInterface, ScalarBlocksPackSixteenBitMembers) {
  const VulkanStage stage = compile_for_vulkan(
      "s.comp", "#version 450\n#extension GL_EXT_shader_explicit_arithmetic_types : require\n"
                "#extension GL_EXT_scalar_block_layout : require\nlayout(local_size_x = 1) in;\n"
                "layout(scalar, binding = 2) buffer C { uint8_t a; f16vec3 b; int64_t c; u16vec3 d; } c;\n"
                "void main() { c.c = int64_t(c.d.x) + 3l; }\n");
  const gl::Symbol& block = symbol(stage.symbols, "C");
  EXPECT_EQ(block.packing, "scalar");
  EXPECT_EQ(block.members.at(1).offset, 2);
  EXPECT_EQ(block.members.at(2).offset, 8);
  EXPECT_EQ(block.members.at(3).offset, 16);
  EXPECT_EQ(block.size, 22);
}

// The same shader for OpenGL: no client, no sets, no push constants.
TEST(VulkanInterface, AnOpenGLStageSaysNothingOfVulkan) {
  CompileResult compiled = compile(
      {{"g.frag", "#version 450\nlayout(std140, binding = 0) uniform U { float a; vec3 b; } u;\n"
                  "out vec4 c;\nvoid main() { c = vec4(u.b, u.a); }\n"}});
  ASSERT_TRUE(compiled.success) << compiled.diagnostics_text();
  const gl::StageSymbols& stage = compiled.symbols.stages.at(0);
  EXPECT_EQ(stage.client, gl::Client::opengl);
  const gl::Symbol& block = symbol(stage, "U");
  EXPECT_FALSE(block.set.has_value());
  EXPECT_EQ(block.packing, "std140");
  EXPECT_EQ(block.members[1].offset, 16);
  EXPECT_EQ(block.size, 28);
  EXPECT_EQ(gl::to_json(compiled.symbols).find("\"client\""), std::string::npos);
}

}  // namespace
}  // namespace safegi
