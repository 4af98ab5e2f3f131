// The Vulkan flavour of the generated handles header: typed handles for a
// runtime_vk ComputePipeline, and the layout of every block as constants.
#include <functional>
#include <sstream>

#include "safegi/symbol_table/error.hpp"
#include "speller.hpp"

namespace safegi::gl::detail {
namespace {

struct Handle {
  std::string kind;    // member_id, array_member_id, storage_array_id, block_binding_id
  std::string type;    // the C++ value type ("" for block_binding_id)
  std::string lookup;  // push_constant, member, ...
  std::string name;    // the name looked up ("Push.factor")
  std::string field;   // the C++ field ("Push_factor")
};

// "Params.tint" -> "Params_tint": a C++ identifier.
std::string field_of(const std::string& block, const std::string& member) {
  return member.empty() ? block : block + '_' + member;
}

}  // namespace

std::string generate_vk_handles_header(const SymbolTable& table, const HandlesHeaderOptions& options) {
  const StageSymbols* stage = table.stage(Stage::compute);
  if (!stage || stage->client != Client::vulkan)
    throw SymbolTableError(
        (options.origin.empty() ? std::string("<symbol table>") : options.origin) +
        ": error: Vulkan handles need a Vulkan compute stage (safeglslc -V or --target-env vulkan1.x)");
  const DimensionNamer namer = table.namer();
  const Speller speller(options, namer);
  std::vector<Handle> handles;
  std::vector<std::string> skipped;
  std::ostringstream layout;
  // The C++ type of a member, or empty (and a note) when it has none.
  const auto spell = [&](const Symbol& s) -> std::string {
    try {
      return speller.type(s, s.type);
    } catch (const SymbolTableError& error) {
      skipped.push_back(std::string(error.what()).substr(0, std::string(error.what()).find(": error: ")) + ": " +
                        s.block + '.' + s.name + " (" + s.type.glsl_type +
                        ": declare a safegi::vk::std430_struct, check its fields against layout::…::fields "
                        "with SAFEGI_VK_EXPECT_MEMBER, and look it up yourself)");
      return {};
    }
  };
  // A member's struct in layout::, named as the member unless that is one of the names the struct
  // holds (a member called `offset`: `struct offset_`, since a class cannot hold its own name).
  const auto layout_name = [](const Symbol& s, bool typed) {
    const bool taken = (s.name == "type" && typed) || s.name == "offset" || (s.name == "size" && s.size) ||
                       (s.name == "stride" && s.array_stride) || (s.name == "count" && s.array_size) ||
                       (s.name == "fields" && !s.fields.empty());
    return taken ? s.name + '_' : s.name;
  };
  // A struct member's fields (an array of structs': its element's), each placed from the struct's
  // start, for SAFEGI_VK_EXPECT_MEMBER on the host struct: layout::Block::member::fields::field.
  const std::function<void(const Symbol&, const std::string&)> write_fields = [&](const Symbol& s, const std::string& indent) {
    if (s.fields.empty()) return;
    layout << indent << "struct fields {\n";
    for (const Symbol& f : s.fields) {
      if (!f.offset) continue;
      const std::string type = f.fields.empty() ? spell(f) : std::string();
      layout << indent << "  struct " << layout_name(f, !type.empty()) << " {\n";
      if (!type.empty()) layout << indent << "    using type = " << type << ";\n";
      layout << indent << "    static constexpr std::uint32_t offset = " << *f.offset;
      if (f.size) layout << ", size = " << *f.size;
      if (f.array_stride) layout << ", stride = " << *f.array_stride;
      if (f.array_size) layout << ", count = " << *f.array_size;
      layout << ";\n";
      write_fields(f, indent + "    ");
      layout << indent << "  };\n";
    }
    layout << indent << "};\n";
  };
  for (const Symbol& block : stage->symbols) {
    if (block.type.kind != Kind::block) {
      if (block.set)
        skipped.push_back(to_string(block.declared_at) + ": " + block.type.glsl_type + ' ' + block.name +
                          " (the host chooses the texel type: pipeline.image<T>)");
      continue;
    }
    if (block.storage != Storage::uniform && block.storage != Storage::buffer) continue;
    layout << "struct " << block.name << " {\n";
    if (block.size) layout << "  static constexpr std::uint32_t block_size = " << *block.size << ";\n";
    if (block.set)
      layout << "  static constexpr safegi::vk::descriptor_slot block_slot{" << *block.set << ", "
             << block.binding.value_or(0) << "};\n";
    const bool one_array = block.storage == Storage::buffer && block.members.size() == 1 &&
                           (block.members[0].array_size || block.members[0].unsized);
    if (block.set && !one_array) handles.push_back({"block_binding_id", "", "block_binding", block.name, block.name});
    for (const Symbol& m : block.members) {
      if (!m.offset) {
        skipped.push_back(to_string(m.declared_at) + ": " + block.name + '.' + m.name + " (no offset in the table)");
        continue;
      }
      const std::string type = spell(m);
      const bool array = m.array_size || m.unsized;
      layout << "  struct " << layout_name(m, !type.empty()) << " {\n";
      if (!type.empty()) layout << "    using type = " << type << ";\n";
      layout << "    static constexpr std::uint32_t offset = " << *m.offset;
      if (m.size) layout << ", size = " << *m.size;
      if (m.array_stride) layout << ", stride = " << *m.array_stride;
      if (m.array_size) layout << ", count = " << *m.array_size;
      layout << ";\n";
      write_fields(m, "    ");
      layout << "  };\n";
      if (type.empty()) continue;
      const std::string name = block.name + '.' + m.name;
      const std::string lookup = block.push_constant ? "push_constant"
                                 : one_array         ? "storage_array"
                                 : array             ? "array_member"
                                                     : "member";
      const std::string kind = one_array ? "storage_array_id" : array ? "array_member_id" : "member_id";
      handles.push_back({kind, type, lookup, name, field_of(block.name, m.name)});
    }
    layout << "};\n";
  }

  std::ostringstream out;
  out << "// Generated by safegi-gl-handles --api vulkan" << (options.origin.empty() ? "" : " from " + options.origin)
      << ". Do not edit.\n"
         "// Typed handles for one compute pipeline's interface (a value or buffer of another\n"
         "// dimension or space than the shader declares fails to compile), and where each\n"
         "// block member lies (layout::, for SAFEGI_VK_EXPECT_MEMBER on host structs).\n"
         "#pragma once\n\n"
         "#include <cstdint>\n"
         "#include <safegi/runtime_vk/runtime_vk.hpp>\n"
         "#include <safegi/typed.hpp>\n\n"
         "namespace "
      << options.namespace_name << " {\n\n";
  write_skipped_and_aliases(out, skipped, speller);
  out << "// The table's layout: bytes from the block's start, sizes, array strides and counts,\n"
         "// descriptor set and binding.\nnamespace layout {\n"
      << layout.str() << "}  // namespace layout\n\n";
  if (!stage->specialization_constants.empty()) {
    out << "// Specialization constants: their ids.\nnamespace constants {\n";
    for (const auto& c : stage->specialization_constants) {
      std::string id_name = c.name;
      for (char& ch : id_name)
        if (ch == '.') ch = '_';
      out << "inline constexpr std::uint32_t " << id_name << " = " << c.id << ";\n";
    }
    out << "}  // namespace constants\n\n";
  }
  out << "struct " << options.struct_name << " {\n";
  for (const auto& h : handles)
    out << "  safegi::vk::" << h.kind << (h.type.empty() ? "" : '<' + h.type + '>') << ' ' << h.field << ";\n";
  out << "\n  // Looks every handle up (checked against the pipeline's symbol table) and\n"
         "  // refuses a pipeline whose shader is not the one this header was made from.\n"
         "  explicit "
      << options.struct_name << "(const safegi::vk::ComputePipeline& pipeline)";
  for (std::size_t i = 0; i < handles.size(); ++i) {
    const Handle& h = handles[i];
    out << (i == 0 ? "\n      : " : ",\n        ") << h.field << "(pipeline." << h.lookup
        << (h.type.empty() ? "" : '<' + h.type + '>') << "(\"" << h.name << "\"))";
  }
  out << " {\n";
  if (!stage->source_hash.empty()) out << "    pipeline.expect_source_hash(\"" << stage->source_hash << "\");\n";
  out << "  }\n};\n\n}  // namespace " << options.namespace_name << '\n';
  return out.str();
}

}  // namespace safegi::gl::detail
