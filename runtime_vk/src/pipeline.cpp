#include "safegi/runtime_vk/pipeline.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "calls.hpp"
#include "context_impl.hpp"

namespace safegi::vk {
namespace detail {

constexpr const VkAllocationCallbacks* kNoAllocator = nullptr;

struct Binding {
  descriptor_slot slot;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  std::uint32_t count = 1;
  std::size_t symbol = 0;  // index in the stage's symbols
  bool bound = false;
};

struct PipelineImpl {
  ContextImpl* context = nullptr;
  std::string name;
  StageSymbols stage;
  gl::DimensionNamer namer;
  std::vector<Binding> bindings;
  std::optional<std::size_t> push_block;  // index in the stage's symbols
  std::uint32_t push_size = 0;

  VkShaderModule module = VK_NULL_HANDLE;
  std::vector<VkDescriptorSetLayout> set_layouts;  // index: set
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  std::vector<VkDescriptorSet> sets;
  VkSampler samplers[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};  // by Filter, made on first use

  ~PipelineImpl() {
    VkDevice device = context->device;
    if (pool) SAFEGI_VK(vkDestroyDescriptorPool, device, pool, kNoAllocator);  // frees the sets
    for (VkSampler sampler : samplers)
      if (sampler) SAFEGI_VK(vkDestroySampler, device, sampler, kNoAllocator);
    if (pipeline) SAFEGI_VK(vkDestroyPipeline, device, pipeline, kNoAllocator);
    if (layout) SAFEGI_VK(vkDestroyPipelineLayout, device, layout, kNoAllocator);
    for (VkDescriptorSetLayout set_layout : set_layouts)
      SAFEGI_VK(vkDestroyDescriptorSetLayout, device, set_layout, kNoAllocator);
    if (module) SAFEGI_VK(vkDestroyShaderModule, device, module, kNoAllocator);
  }

  const gl::Symbol& symbol(std::size_t index) const { return stage.symbols[index]; }
  std::string at(const gl::Symbol& s) const { return gl::to_string(s.declared_at) + ": error: "; }
  Binding* binding(descriptor_slot slot) {
    for (Binding& b : bindings)
      if (b.slot.set == slot.set && b.slot.binding == slot.binding) return &b;
    return nullptr;
  }
};

namespace {

std::optional<VkDescriptorType> descriptor_type(const gl::Symbol& s) {
  const std::string& t = s.type.glsl_type;
  if (s.type.kind == gl::Kind::block) {
    if (s.storage == gl::Storage::buffer) return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  }
  if (t.rfind("imageBuffer", 0) == 0 || t.rfind("iimageBuffer", 0) == 0 || t.rfind("uimageBuffer", 0) == 0)
    return VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
  if (t.find("image") != std::string::npos && t.find("subpass") == std::string::npos)
    return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  if (t.find("samplerBuffer") != std::string::npos) return VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
  if (t == "sampler" || t == "samplerShadow") return VK_DESCRIPTOR_TYPE_SAMPLER;
  if (t.find("sampler") != std::string::npos) return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  if (t.find("texture") != std::string::npos) return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
  return std::nullopt;
}

std::string differ_words(const std::vector<std::string>& parts) {
  std::string differ;
  for (std::size_t i = 0; i < parts.size(); ++i)
    differ += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
  return differ + (parts.size() == 1 ? " differs" : " differ");
}

void collect_bindings(PipelineImpl& p) {
  for (std::size_t i = 0; i < p.stage.symbols.size(); ++i) {
    const gl::Symbol& s = p.stage.symbols[i];
    if (s.push_constant) {
      if (!s.size)
        throw ShaderError(p.at(s) + "push-constant block '" + s.name +
                          "' has no size in the symbol table (a member of a type the checker does not model)");
      p.push_block = i;
      p.push_size = static_cast<std::uint32_t>(*s.size);
      continue;
    }
    if (!s.set || (s.storage != gl::Storage::uniform && s.storage != gl::Storage::buffer)) continue;
    const auto type = descriptor_type(s);
    if (!type)
      throw ShaderError(p.at(s) + "'" + s.name + "' is a " + s.type.glsl_type +
                        ", which runtime_vk cannot put in a descriptor set yet");
    Binding b;
    b.slot = {static_cast<std::uint32_t>(*s.set), static_cast<std::uint32_t>(s.binding.value_or(0))};
    b.type = *type;
    b.count = static_cast<std::uint32_t>(s.array_size.value_or(1));
    b.symbol = i;
    if (p.binding(b.slot))
      throw ShaderError(p.at(s) + "'" + s.name + "' shares set " + std::to_string(b.slot.set) + ", binding " +
                        std::to_string(b.slot.binding) + " with '" + p.symbol(p.binding(b.slot)->symbol).name + "'");
    p.bindings.push_back(b);
  }
}

void create_layouts(PipelineImpl& p) {
  VkDevice device = p.context->device;
  std::uint32_t set_count = 0;
  for (const Binding& b : p.bindings) set_count = std::max(set_count, b.slot.set + 1);
  for (std::uint32_t set = 0; set < set_count; ++set) {
    std::vector<VkDescriptorSetLayoutBinding> entries;
    for (const Binding& b : p.bindings)
      if (b.slot.set == set) entries.push_back({b.slot.binding, b.type, b.count, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    auto create = make<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    create.bindingCount = static_cast<std::uint32_t>(entries.size());
    create.pBindings = entries.data();
    VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
    check(SAFEGI_VK(vkCreateDescriptorSetLayout, device, &create, kNoAllocator, &set_layout),
          "vkCreateDescriptorSetLayout");
    p.set_layouts.push_back(set_layout);
  }
  VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, p.push_size};
  auto create = make<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  create.setLayoutCount = static_cast<std::uint32_t>(p.set_layouts.size());
  create.pSetLayouts = p.set_layouts.data();
  create.pushConstantRangeCount = p.push_block ? 1u : 0u;
  create.pPushConstantRanges = &range;
  check(SAFEGI_VK(vkCreatePipelineLayout, device, &create, kNoAllocator, &p.layout), "vkCreatePipelineLayout");
  if (p.set_layouts.empty()) return;
  std::map<VkDescriptorType, std::uint32_t> counts;
  for (const Binding& b : p.bindings) counts[b.type] += b.count;
  std::vector<VkDescriptorPoolSize> sizes;
  for (const auto& [type, count] : counts) sizes.push_back({type, count});
  auto pool = make<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  pool.maxSets = set_count;
  pool.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  pool.pPoolSizes = sizes.data();
  check(SAFEGI_VK(vkCreateDescriptorPool, device, &pool, kNoAllocator, &p.pool), "vkCreateDescriptorPool");
  auto allocate = make<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  allocate.descriptorPool = p.pool;
  allocate.descriptorSetCount = set_count;
  allocate.pSetLayouts = p.set_layouts.data();
  p.sets.resize(set_count);
  check(SAFEGI_VK(vkAllocateDescriptorSets, device, &allocate, p.sets.data()), "vkAllocateDescriptorSets");
}

// The constants' entries and data, each found in the table by name or id.
void resolve_specialization(const PipelineImpl& p, const Specialization& specialization,
                            std::vector<VkSpecializationMapEntry>& entries, std::vector<std::uint32_t>& data) {
  const auto& constants = p.stage.specialization_constants;
  for (const Specialization::Entry& e : specialization.entries()) {
    const gl::SpecializationConstant* found = nullptr;
    for (const auto& c : constants)
      if (e.id ? c.id == static_cast<int>(*e.id) : c.name == e.name) found = &c;
    const std::string label = e.id ? "id " + std::to_string(*e.id) : "'" + e.name + "'";
    if (!found) {
      std::string declared;
      for (const auto& c : constants)
        declared += (declared.empty() ? "" : ", ") + c.name + " (id " + std::to_string(c.id) + ")";
      throw BindingError(p.name + ": error: no specialization constant " + (e.id ? "with " : "named ") + label +
                         " in " + p.stage.file + " (it declares " + (declared.empty() ? "none" : declared) + ")");
    }
    if (e.host) {
      const auto parts = gl::differences(found->type, *e.host);
      if (!parts.empty())
        throw BindingError(gl::to_string(found->declared_at) + ": error: specialization constant '" + found->name +
                           "' is declared with type " + gl::in_words(found->type, p.namer) + " but the host uses " +
                           gl::in_words(*e.host, p.namer) + " (" + differ_words(parts) + ")");
    }
    const auto id = static_cast<std::uint32_t>(found->id);
    const auto same = std::find_if(entries.begin(), entries.end(), [id](const auto& m) { return m.constantID == id; });
    if (same != entries.end()) {
      data[same->offset / 4] = e.bits;  // the last setting wins
      continue;
    }
    entries.push_back({id, static_cast<std::uint32_t>(data.size() * 4), 4});
    data.push_back(e.bits);
  }
}

void create_pipeline(PipelineImpl& p, const std::vector<std::uint32_t>& spirv, const Specialization& specialization) {
  VkDevice device = p.context->device;
  auto module = make<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
  module.codeSize = spirv.size() * 4;
  module.pCode = spirv.data();
  trace_bytes("shader module", std::as_bytes(std::span(spirv)));
  check(SAFEGI_VK(vkCreateShaderModule, device, &module, kNoAllocator, &p.module), "vkCreateShaderModule");
  std::vector<VkSpecializationMapEntry> entries;
  std::vector<std::uint32_t> data;
  resolve_specialization(p, specialization, entries, data);
  trace_bytes("specialization", std::as_bytes(std::span(data)));
  VkSpecializationInfo info{static_cast<std::uint32_t>(entries.size()), entries.data(), data.size() * 4, data.data()};
  auto create = make<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
  create.stage = make<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
  create.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  create.stage.module = p.module;
  create.stage.pName = "main";
  create.stage.pSpecializationInfo = entries.empty() ? nullptr : &info;
  create.layout = p.layout;
  const VkResult result =
      SAFEGI_VK(vkCreateComputePipelines, device, VkPipelineCache{VK_NULL_HANDLE}, 1u,
                static_cast<const VkComputePipelineCreateInfo*>(&create), kNoAllocator, &p.pipeline);
  if (result != VK_SUCCESS)
    throw ShaderError(p.name + ": error: the driver refused the compute pipeline (" + result_name(result) + ")");
}

std::string_view lookup_words(Lookup lookup) {
  switch (lookup) {
    case Lookup::push_constant:
      return "push-constant member";
    case Lookup::member:
      return "block member";
    case Lookup::array_member:
      return "block member";
    case Lookup::storage_array:
      return "storage array";
    case Lookup::image:
      return "image";
    case Lookup::sampler:
      return "sampler";
  }
  return "name";
}

bool block_named(const gl::Symbol& s, std::string_view name) {
  return s.name == name || (!s.instance_name.empty() && s.instance_name == name);
}

// One buffer or image descriptor written into the pipeline's set at `slot`, which then counts as bound.
void write_descriptor(PipelineImpl& p, descriptor_slot slot, Binding& b, const VkDescriptorBufferInfo* buffer,
                      const VkDescriptorImageInfo* image) {
  auto write = make<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
  write.dstSet = p.sets[slot.set];
  write.dstBinding = slot.binding;
  write.descriptorCount = 1;
  write.descriptorType = b.type;
  write.pBufferInfo = buffer;
  write.pImageInfo = image;
  SAFEGI_VK(vkUpdateDescriptorSets, p.context->device, 1u, static_cast<const VkWriteDescriptorSet*>(&write), 0u,
            static_cast<const VkCopyDescriptorSet*>(nullptr));
  b.bound = true;
}

}  // namespace
}  // namespace detail

using detail::block_named;
using detail::check;
using detail::make;
using detail::PipelineImpl;

ComputePipeline::ComputePipeline(Context& context, ComputeShader shader, Specialization specialization)
    : impl_(std::make_unique<PipelineImpl>()) {
  PipelineImpl& p = *impl_;
  p.context = &context.impl();
  const StageSymbols* stage = shader.symbols.stage(Stage::compute);
  const std::string label = shader.name.empty() ? (stage ? stage->file : "compute pipeline") : shader.name;
  if (!stage) throw ShaderError(label + ": error: the symbol table has no compute stage");
  if (stage->client != gl::Client::vulkan)
    throw ShaderError(stage->file +
                      ": error: the stage was compiled for OpenGL; a Vulkan pipeline needs the table "
                      "safeglslc writes with -V or --target-env vulkan1.x");
  if (shader.spirv.size() < 5 || shader.spirv[0] != 0x07230203u)
    throw ShaderError(label + ": error: not a SPIR-V module (" + std::to_string(shader.spirv.size()) + " words)");
  p.name = label;
  p.stage = *stage;
  p.namer = shader.symbols.namer();
  detail::collect_bindings(p);
  detail::create_layouts(p);
  detail::create_pipeline(p, shader.spirv, specialization);
}

ComputePipeline::~ComputePipeline() = default;
ComputePipeline::ComputePipeline(ComputePipeline&&) noexcept = default;
ComputePipeline& ComputePipeline::operator=(ComputePipeline&&) noexcept = default;

const std::string& ComputePipeline::name() const { return impl_->name; }
const StageSymbols& ComputePipeline::stage() const { return impl_->stage; }

void ComputePipeline::expect_source_hash(std::string_view hash) const {
  const PipelineImpl& p = *impl_;
  if (p.stage.source_hash != hash)
    throw BindingError(p.stage.file +
                       ": error: the handles were generated from another version of this shader "
                       "(source hash " +
                       std::string(hash) + ", the table says " +
                       (p.stage.source_hash.empty() ? std::string("none") : p.stage.source_hash) +
                       "); regenerate them");
}

block_data ComputePipeline::push_constants() const {
  const PipelineImpl& p = *impl_;
  if (!p.push_block) throw BindingError(p.name + ": error: no push-constant block in " + p.stage.file);
  return block_data(p.symbol(*p.push_block).name, static_cast<std::uint32_t>(*p.push_block), p.push_size,
                    BufferUse::storage);
}

block_data ComputePipeline::block(std::string_view name, std::size_t runtime_count) const {
  const PipelineImpl& p = *impl_;
  for (std::size_t i = 0; i < p.stage.symbols.size(); ++i) {
    const gl::Symbol& s = p.symbol(i);
    if (s.type.kind != gl::Kind::block || s.push_constant || !block_named(s, name)) continue;
    std::size_t size = 0;
    if (s.size) {
      size = static_cast<std::size_t>(*s.size);
    } else if (!s.members.empty() && s.members.back().unsized && s.members.back().offset &&
               s.members.back().array_stride) {
      size = static_cast<std::size_t>(*s.members.back().offset + runtime_count * *s.members.back().array_stride);
    } else {
      throw BindingError(p.at(s) + "block '" + s.name +
                         "' has no size in the symbol table (a member of a type the checker does not model)");
    }
    return block_data(s.name, static_cast<std::uint32_t>(i), size,
                      s.storage == gl::Storage::buffer ? BufferUse::storage : BufferUse::uniform);
  }
  throw BindingError(p.name + ": error: no uniform or storage block named '" + std::string(name) + "' in " +
                     p.stage.file);
}

block_binding_id ComputePipeline::block_binding(std::string_view name) const {
  const PipelineImpl& p = *impl_;
  for (const detail::Binding& b : p.bindings) {
    const gl::Symbol& s = p.symbol(b.symbol);
    if (s.type.kind == gl::Kind::block && block_named(s, name)) return {b.slot, static_cast<std::uint32_t>(b.symbol)};
  }
  throw BindingError(p.name + ": error: no uniform or storage block named '" + std::string(name) + "' in " +
                     p.stage.file);
}

Location ComputePipeline::locate(Lookup lookup, std::string_view name, const detail::HostLayout* host) const {
  const PipelineImpl& p = *impl_;
  const std::string what(detail::lookup_words(lookup));
  const auto missing = [&] {
    return BindingError(p.name + ": error: no " + what + " named '" + std::string(name) + "' in " + p.stage.file);
  };
  Location location;
  if (lookup == Lookup::sampler) {
    for (const detail::Binding& b : p.bindings) {
      const gl::Symbol& s = p.symbol(b.symbol);
      if (s.name != name) continue;
      if (s.type.glsl_type != "sampler2D")
        throw BindingError(p.at(s) + "'" + s.name + "' is declared as " +
                           (s.type.kind == gl::Kind::block ? std::string("a block") : s.type.glsl_type) +
                           ", not as a sampler2D");
      if (host) {
        const gl::ValueType declared =
            s.texel ? *s.texel : gl::ValueType{gl::Kind::plain, "vec4", {}, {}};  // unannotated: what texture() returns
        const std::vector<std::string> parts = gl::differences(declared, host->type);
        if (!parts.empty())
          throw BindingError(p.at(s) + "sampler '" + s.name + "' is declared with texels of type " +
                             gl::in_words(declared, p.namer) + " but the host uses " +
                             gl::in_words(host->type, p.namer) + " (" + detail::differ_words(parts) + ")");
      }
      location.slot = b.slot;
      return location;
    }
    throw missing();
  }
  if (lookup == Lookup::image) {
    for (const detail::Binding& b : p.bindings) {
      const gl::Symbol& s = p.symbol(b.symbol);
      if (s.name != name) continue;
      if (s.type.glsl_type != "image2D" && s.type.glsl_type != "iimage2D" && s.type.glsl_type != "uimage2D")
        throw BindingError(p.at(s) + "'" + s.name + "' is declared as " +
                           (s.type.kind == gl::Kind::block ? std::string("a block") : s.type.glsl_type) +
                           ", not as a storage image2D");
      if (host) {
        const bool is_float = s.type.glsl_type == "image2D";
        const bool host_float = host->type.glsl_type.find_first_of("iu") != 0;  // vec4, float; not ivec4, uint
        if (is_float != host_float)
          throw BindingError(p.at(s) + "image '" + s.name + "' is a " + s.type.glsl_type +
                             " but the host's texels are " + gl::in_words(host->type, p.namer));
      }
      location.slot = b.slot;
      return location;
    }
    throw missing();
  }
  // Blocks and members: "Block.member", "instance.member", or "member" alone.
  const auto dot = name.find('.');
  const std::string_view block_name = dot == std::string_view::npos ? std::string_view() : name.substr(0, dot);
  const std::string_view member_name = dot == std::string_view::npos ? name : name.substr(dot + 1);
  const gl::Symbol* block = nullptr;
  const gl::Symbol* member = nullptr;
  std::size_t block_index = 0;
  for (std::size_t i = 0; i < p.stage.symbols.size() && !member; ++i) {
    const gl::Symbol& s = p.symbol(i);
    if (s.type.kind != gl::Kind::block || s.push_constant != (lookup == Lookup::push_constant)) continue;
    if (!block_name.empty() && !block_named(s, block_name)) continue;
    for (const gl::Symbol& m : s.members)
      if (m.name == member_name) {
        block = &s;
        member = &m;
        block_index = i;
        break;
      }
  }
  if (!member) throw missing();
  const std::string full = block->name + '.' + member->name;
  const std::string where = p.at(*member) + what + " '" + full + "'";
  const bool is_array = member->array_size.has_value() || member->unsized;
  const bool wants_array = lookup == Lookup::array_member || lookup == Lookup::storage_array;
  if (lookup == Lookup::storage_array) {
    if (block->storage != gl::Storage::buffer)
      throw BindingError(where + " is in uniform block '" + block->name +
                         "'; a storage_buffer binds to a buffer block");
    if (block->members.size() != 1)
      throw BindingError(where + " is one of " + std::to_string(block->members.size()) + " members of '" + block->name +
                         "'; a storage_buffer binds a block that is one array (use block() and array_member<T>)");
    const auto b =
        std::find_if(p.bindings.begin(), p.bindings.end(), [&](const auto& x) { return x.symbol == block_index; });
    if (b == p.bindings.end())
      throw BindingError(where + " is in block '" + block->name + "', which is in no descriptor set");
    location.slot = b->slot;
  }
  if (!member->offset)
    throw BindingError(where +
                       " has no offset in the symbol table (its block has no std140, std430 or scalar "
                       "packing, or a member before it is of a type the checker does not model)");
  location.block = static_cast<std::uint32_t>(block_index);
  location.offset = static_cast<std::uint32_t>(*member->offset);
  location.stride = static_cast<std::uint32_t>(member->array_stride.value_or(0));
  location.count = static_cast<std::uint32_t>(member->array_size.value_or(0));
  location.matrix_stride = static_cast<std::uint32_t>(member->matrix_stride.value_or(16));
  if (member->row_major) throw BindingError(where + " is a row_major matrix; runtime_vk writes matrices by columns");
  if (!host) return location;

  if (is_array != wants_array)
    throw BindingError(
        where + (is_array ? " is an array" +
                                (member->array_size ? " of " + std::to_string(*member->array_size) : std::string()) +
                                "; look it up with array_member<T>"
                          : " is not an array; look it up with member<T>"));
  const std::vector<std::string> parts = gl::differences(member->type, host->type);
  if (!parts.empty())
    throw BindingError(where + " is declared with type " + gl::in_words(member->type, p.namer) + " but the host uses " +
                       gl::in_words(host->type, p.namer) + " (" + detail::differ_words(parts) + ")");
  const bool is_struct = host->is_struct;
  if (!is_array && host->columns == 1 && member->size && *member->size != host->size)
    throw BindingError(where + " is " + std::to_string(*member->size) + " bytes in the shader but " +
                       std::to_string(host->size) + " bytes on the host");
  if (is_array && (lookup == Lookup::storage_array || is_struct) && location.stride != host->stride)
    throw BindingError(where + " has an array stride of " + std::to_string(location.stride) +
                       " bytes in the shader but " + std::to_string(host->stride) + " on the host" +
                       (is_struct ? " (sizeof(" + host->type.glsl_type + "))" : " (std430)"));
  return location;
}

void ComputePipeline::bind(block_binding_id id, const block_buffer& buffer) {
  PipelineImpl& p = *impl_;
  const detail::Binding* b = p.binding(id.slot);
  if (!b || b->symbol != id.block)
    throw BindingError(p.name + ": error: the handle of set " + std::to_string(id.slot.set) + ", binding " +
                       std::to_string(id.slot.binding) + " was not looked up in this pipeline");
  if (buffer.block() != id.block)
    throw BindingError(p.at(p.symbol(id.block)) + "block '" + p.symbol(id.block).name +
                       "' given the buffer of another block (symbol " + std::to_string(buffer.block()) + ")");
  bind_buffer(id.slot, buffer.raw());
}

void ComputePipeline::bind_buffer(descriptor_slot slot, const detail::Buffer& buffer) {
  PipelineImpl& p = *impl_;
  detail::Binding* b = p.binding(slot);
  if (!b)
    throw BindingError(p.name + ": error: " + p.stage.file + " has nothing at set " + std::to_string(slot.set) +
                       ", binding " + std::to_string(slot.binding));
  const gl::Symbol& s = p.symbol(b->symbol);
  const VkDescriptorType wanted =
      buffer.use() == BufferUse::uniform ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  if (b->type != wanted)
    throw BindingError(p.at(s) + "'" + s.name + "' is a " + (s.storage == gl::Storage::buffer ? "storage" : "uniform") +
                       " block but the host binds a " + (buffer.use() == BufferUse::uniform ? "uniform" : "storage") +
                       " buffer");
  if (s.size && buffer.size() < static_cast<std::size_t>(*s.size))
    throw ResourceError(p.at(s) + "block '" + s.name + "' is " + std::to_string(*s.size) +
                        " bytes but the buffer bound to it holds " + std::to_string(buffer.size()));
  const VkDescriptorBufferInfo info{buffer.handle(), 0, VK_WHOLE_SIZE};
  detail::write_descriptor(p, slot, *b, &info, nullptr);
}

void ComputePipeline::bind_image(descriptor_slot slot, const detail::Image& image) {
  PipelineImpl& p = *impl_;
  detail::Binding* b = p.binding(slot);
  if (!b || b->type != VK_DESCRIPTOR_TYPE_STORAGE_IMAGE)
    throw BindingError(p.name + ": error: no storage image at set " + std::to_string(slot.set) + ", binding " +
                       std::to_string(slot.binding));
  const VkDescriptorImageInfo info{VK_NULL_HANDLE, image.view(), VK_IMAGE_LAYOUT_GENERAL};
  detail::write_descriptor(p, slot, *b, nullptr, &info);
}

void ComputePipeline::dispatch(std::uint32_t x, std::uint32_t y, std::uint32_t z) const {
  if (impl_->push_block)
    throw BindingError(impl_->name + ": error: the shader has push constants ('" +
                       impl_->symbol(*impl_->push_block).name + "'); dispatch with push_constants()");
  dispatch(block_data("", 0, 0, BufferUse::storage), x, y, z);
}

void ComputePipeline::bind_texture(descriptor_slot slot, const detail::Image& image, Filter filter) {
  PipelineImpl& p = *impl_;
  detail::Binding* b = p.binding(slot);
  if (!b || b->type != VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER)
    throw BindingError(p.name + ": error: no sampler2D at set " + std::to_string(slot.set) + ", binding " +
                       std::to_string(slot.binding));
  if (filter == Filter::linear) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(p.context->physical, image.format(), &properties);
    if (!(properties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
      throw ResourceError(p.at(p.symbol(b->symbol)) + "device " + p.context->info.device_name +
                          " cannot filter this texture's format (VkFormat " + std::to_string(image.format()) +
                          ") linearly; bind it with Filter::nearest");
  }
  VkSampler& sampler = p.samplers[filter == Filter::linear ? 1 : 0];
  if (!sampler) {
    auto create = make<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    create.magFilter = create.minFilter = filter == Filter::linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
    create.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    create.addressModeU = create.addressModeV = create.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    create.maxLod = 0.0f;
    check(SAFEGI_VK(vkCreateSampler, p.context->device, &create, detail::kNoAllocator, &sampler), "vkCreateSampler");
  }
  const VkDescriptorImageInfo info{sampler, image.view(), VK_IMAGE_LAYOUT_GENERAL};
  detail::write_descriptor(p, slot, *b, nullptr, &info);
}

void ComputePipeline::check_dispatch(const block_data& push_constants) const {
  const PipelineImpl& p = *impl_;
  for (const detail::Binding& b : p.bindings)
    if (!b.bound)
      throw BindingError(p.name + ": error: dispatch with '" + p.symbol(b.symbol).name + "' (set " +
                         std::to_string(b.slot.set) + ", binding " + std::to_string(b.slot.binding) + ") unbound");
  if (p.push_block && push_constants.block() != *p.push_block)
    detail::throw_wrong_block(push_constants.name(), static_cast<std::uint32_t>(*p.push_block), push_constants.block());
}

void ComputePipeline::dispatch(const block_data& push_constants, std::uint32_t x, std::uint32_t y,
                               std::uint32_t z) const {
  check_dispatch(push_constants);
  impl_->context->submit([&](VkCommandBuffer commands) { record_dispatch(commands, push_constants, x, y, z); });
}

void ComputePipeline::record_dispatch(VkCommandBuffer commands, const block_data& push_constants, std::uint32_t x,
                                      std::uint32_t y, std::uint32_t z) const {
  const PipelineImpl& p = *impl_;
  auto before = make<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  before.srcAccessMask = VK_ACCESS_HOST_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  before.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_UNIFORM_READ_BIT;
  SAFEGI_VK(vkCmdPipelineBarrier, commands,
            VkPipelineStageFlags{VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT |
                                 VK_PIPELINE_STAGE_TRANSFER_BIT},
            VkPipelineStageFlags{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT}, VkDependencyFlags{0}, 1u, &before, 0u,
            static_cast<const VkBufferMemoryBarrier*>(nullptr), 0u, static_cast<const VkImageMemoryBarrier*>(nullptr));
  SAFEGI_VK(vkCmdBindPipeline, commands, VK_PIPELINE_BIND_POINT_COMPUTE, p.pipeline);
  if (!p.sets.empty())
    SAFEGI_VK(vkCmdBindDescriptorSets, commands, VK_PIPELINE_BIND_POINT_COMPUTE, p.layout, 0u,
              static_cast<std::uint32_t>(p.sets.size()), p.sets.data(), 0u, static_cast<const std::uint32_t*>(nullptr));
  if (p.push_block) {
    detail::trace_bytes("push constants", push_constants.bytes());
    SAFEGI_VK(vkCmdPushConstants, commands, p.layout, VkShaderStageFlags{VK_SHADER_STAGE_COMPUTE_BIT}, 0u, p.push_size,
              static_cast<const void*>(push_constants.bytes().data()));
  }
  SAFEGI_VK(vkCmdDispatch, commands, x, y, z);
  auto after = make<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  after.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  after.dstAccessMask = VK_ACCESS_HOST_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_SHADER_READ_BIT;
  SAFEGI_VK(vkCmdPipelineBarrier, commands, VkPipelineStageFlags{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT},
            VkPipelineStageFlags{VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT |
                                 VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT},
            VkDependencyFlags{0}, 1u, &after, 0u, static_cast<const VkBufferMemoryBarrier*>(nullptr), 0u,
            static_cast<const VkImageMemoryBarrier*>(nullptr));
}

Batch::Batch(Context& context) : context_(&context.impl()) {}

Batch& Batch::dispatch(const ComputePipeline& pipeline, const block_data& push_constants, std::uint32_t x,
                       std::uint32_t y, std::uint32_t z) {
  entries_.push_back({&pipeline, push_constants, x, y, z});
  return *this;
}

Batch& Batch::dispatch(const ComputePipeline& pipeline, std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  return dispatch(pipeline, block_data("", 0, 0, BufferUse::storage), x, y, z);
}

void Batch::run() const {
  for (const Entry& e : entries_) e.pipeline->check_dispatch(e.push);
  context_->submit([&](VkCommandBuffer commands) {
    for (const Entry& e : entries_) e.pipeline->record_dispatch(commands, e.push, e.x, e.y, e.z);
  });
}

std::vector<std::uint32_t> read_spirv_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ShaderError(path + ": error: cannot open the SPIR-V file");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() % 4 != 0) throw ShaderError(path + ": error: not a SPIR-V module (size is no multiple of 4)");
  std::vector<std::uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), bytes.size());
  return words;
}

SymbolTable read_symbol_table_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw gl::SymbolTableError(path + ": error: cannot open the symbol table");
  std::ostringstream text;
  text << in.rdbuf();
  return gl::parse_symbol_table(text.str(), path);
}

}  // namespace safegi::vk
