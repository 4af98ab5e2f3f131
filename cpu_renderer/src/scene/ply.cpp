#include "scene/ply.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <optional>

namespace safegi::render {

namespace {

enum class Format { ascii, binary_little_endian, binary_big_endian };
enum class Scalar { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

// Faces with more vertices than this are surely damage, not geometry.
constexpr uint64_t kMaxPolygonVertices = 1024;

std::optional<Scalar> scalar_named(std::string_view name) {
  struct Named {
    std::string_view name;
    Scalar type;
  };
  static constexpr Named kNames[] = {
      {"char", Scalar::int8},     {"int8", Scalar::int8},       {"uchar", Scalar::uint8},   {"uint8", Scalar::uint8},
      {"short", Scalar::int16},   {"int16", Scalar::int16},     {"ushort", Scalar::uint16}, {"uint16", Scalar::uint16},
      {"int", Scalar::int32},     {"int32", Scalar::int32},     {"uint", Scalar::uint32},   {"uint32", Scalar::uint32},
      {"float", Scalar::float32}, {"float32", Scalar::float32}, {"double", Scalar::float64}, {"float64", Scalar::float64}};
  for (const Named& named : kNames)
    if (named.name == name) return named.type;
  return std::nullopt;
}

size_t size_of(Scalar type) {
  switch (type) {
    case Scalar::int8: case Scalar::uint8: return 1;
    case Scalar::int16: case Scalar::uint16: return 2;
    case Scalar::int32: case Scalar::uint32: case Scalar::float32: return 4;
    case Scalar::float64: return 8;
  }
  return 1;
}

bool is_integer(Scalar type) { return type != Scalar::float32 && type != Scalar::float64; }

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

struct Property {
  std::string name;
  Scalar type = Scalar::float32;  // of the value, or of a list's items
  bool is_list = false;
  Scalar count_type = Scalar::uint8;
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
};

struct Header {
  Format format = Format::ascii;
  std::vector<Element> elements;
  size_t body_offset = 0;
  int body_line = 0;  // line number of the first body line (ASCII)
};

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> words;
  size_t at = 0;
  while (at < line.size()) {
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
    size_t end = at;
    while (end < line.size() && line[end] != ' ' && line[end] != '\t') ++end;
    if (end > at) words.push_back(line.substr(at, end - at));
    at = end;
  }
  return words;
}

std::string quoted(std::string_view text) {
  constexpr size_t kShown = 40;
  std::string shown;
  for (char c : text.substr(0, kShown)) shown += (c >= 32 && c < 127) ? c : '?';
  return "'" + shown + (text.size() > kShown ? "...'" : "'");
}

[[noreturn]] void fail_line(int line, const std::string& message) {
  throw PlyError("line " + std::to_string(line) + ": " + message);
}

Header parse_header(std::string_view bytes) {
  Header header;
  size_t at = 0;
  int line_number = 0;
  bool has_format = false;
  auto next_line = [&]() -> std::optional<std::string_view> {
    if (at >= bytes.size()) return std::nullopt;
    size_t end = bytes.find('\n', at);
    if (end == std::string_view::npos) end = bytes.size();
    std::string_view line = bytes.substr(at, end - at);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    at = end + 1;
    ++line_number;
    return line;
  };
  std::optional<std::string_view> first = next_line();
  if (!first || *first != "ply") throw PlyError("not a PLY file: expected 'ply' on line 1");
  while (std::optional<std::string_view> line = next_line()) {
    std::vector<std::string_view> words = split(*line);
    if (words.empty()) continue;
    std::string_view keyword = words[0];
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") {
      if (!has_format) fail_line(line_number, "end_header before a format line");
      header.body_offset = std::min(at, bytes.size());
      header.body_line = line_number + 1;
      return header;
    }
    if (keyword == "format") {
      if (words.size() != 3 || words[2] != "1.0")
        fail_line(line_number, "expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0', got " + quoted(*line));
      if (words[1] == "ascii") header.format = Format::ascii;
      else if (words[1] == "binary_little_endian") header.format = Format::binary_little_endian;
      else if (words[1] == "binary_big_endian") header.format = Format::binary_big_endian;
      else fail_line(line_number, "unknown format " + quoted(words[1]));
      has_format = true;
    } else if (keyword == "element") {
      uint64_t count = 0;
      if (words.size() != 3 ||
          std::from_chars(words[2].data(), words[2].data() + words[2].size(), count).ptr != words[2].data() + words[2].size())
        fail_line(line_number, "expected 'element <name> <count>', got " + quoted(*line));
      header.elements.push_back({std::string(words[1]), count, {}});
    } else if (keyword == "property") {
      if (header.elements.empty()) fail_line(line_number, "property before any element");
      Property property;
      if (words.size() == 5 && words[1] == "list") {
        std::optional<Scalar> count_type = scalar_named(words[2]), item_type = scalar_named(words[3]);
        if (!count_type || !is_integer(*count_type))
          fail_line(line_number, "a list's count must have an integer type, got " + quoted(words[2]));
        if (!item_type) fail_line(line_number, "unknown property type " + quoted(words[3]));
        property = {std::string(words[4]), *item_type, true, *count_type};
      } else if (words.size() == 3) {
        std::optional<Scalar> type = scalar_named(words[1]);
        if (!type) fail_line(line_number, "unknown property type " + quoted(words[1]));
        property = {std::string(words[2]), *type, false, Scalar::uint8};
      } else {
        fail_line(line_number, "expected 'property <type> <name>' or 'property list <count type> <item type> <name>', got " +
                                   quoted(*line));
      }
      header.elements.back().properties.push_back(property);
    } else {
      fail_line(line_number, "unknown header keyword " + quoted(keyword));
    }
  }
  throw PlyError("the header has no end_header");
}

// Reads the body's values one by one, in either encoding.
class BodyReader {
 public:
  BodyReader(std::string_view body, Format format, int first_line)
      : body_(body), format_(format), line_(first_line) {}

  size_t remaining() const { return body_.size() - at_; }

  // The next value; nullopt at the end of the file. `error` names a malformed value.
  std::optional<double> next(Scalar type, std::string& error) {
    return format_ == Format::ascii ? next_text(type, error) : next_binary(type);
  }
  int line() const { return line_; }

 private:
  std::optional<double> next_text(Scalar type, std::string& error) {
    while (at_ < body_.size() && is_space(body_[at_])) {
      if (body_[at_] == '\n') ++line_;
      ++at_;
    }
    if (at_ >= body_.size()) return std::nullopt;
    size_t end = at_;
    while (end < body_.size() && !is_space(body_[end])) ++end;
    std::string_view word = body_.substr(at_, end - at_);
    at_ = end;
    const char* last = word.data() + word.size();
    if (is_integer(type)) {
      long long value = 0;
      auto [ptr, code] = std::from_chars(word.data(), last, value);
      if (code == std::errc() && ptr == last) return static_cast<double>(value);
    } else {
      double value = 0;
      auto [ptr, code] = std::from_chars(word.data(), last, value);
      if (code == std::errc() && ptr == last) return value;
    }
    error = "expected " + std::string(is_integer(type) ? "an integer" : "a number") + ", got " + quoted(word);
    return 0.0;
  }

  std::optional<double> next_binary(Scalar type) {
    size_t size = size_of(type);
    if (remaining() < size) return std::nullopt;
    unsigned char raw[8];
    std::memcpy(raw, body_.data() + at_, size);
    at_ += size;
    bool swap = (format_ == Format::binary_big_endian) != (std::endian::native == std::endian::big);
    if (swap)
      for (size_t i = 0; i < size / 2; ++i) std::swap(raw[i], raw[size - 1 - i]);
    switch (type) {
      case Scalar::int8: return static_cast<double>(std::bit_cast<int8_t>(raw[0]));
      case Scalar::uint8: return static_cast<double>(raw[0]);
      case Scalar::int16: return static_cast<double>(load<int16_t>(raw));
      case Scalar::uint16: return static_cast<double>(load<uint16_t>(raw));
      case Scalar::int32: return static_cast<double>(load<int32_t>(raw));
      case Scalar::uint32: return static_cast<double>(load<uint32_t>(raw));
      case Scalar::float32: return static_cast<double>(load<float>(raw));
      case Scalar::float64: return load<double>(raw);
    }
    return std::nullopt;
  }

  template <class T>
  static T load(const unsigned char* raw) {
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

  std::string_view body_;
  Format format_;
  size_t at_ = 0;
  int line_;
};

int find_property(const Element& element, std::string_view name) {
  for (size_t i = 0; i < element.properties.size(); ++i)
    if (element.properties[i].name == name) return static_cast<int>(i);
  return -1;
}

// What the mesh needs from the vertex and face elements.
struct Layout {
  int position[3] = {-1, -1, -1};
  int normal[3] = {-1, -1, -1};
  int uv[2] = {-1, -1};
  int face_indices = -1;
};

Layout layout_of(const Element& element) {
  Layout layout;
  if (element.name == "vertex") {
    const char* position_names[3] = {"x", "y", "z"};
    const char* normal_names[3] = {"nx", "ny", "nz"};
    int normals = 0;
    for (int axis = 0; axis < 3; ++axis) {
      layout.position[axis] = find_property(element, position_names[axis]);
      if (layout.position[axis] < 0 || element.properties[layout.position[axis]].is_list)
        throw PlyError(std::string("the vertex element needs a scalar property '") + position_names[axis] + "'");
      layout.normal[axis] = find_property(element, normal_names[axis]);
      if (layout.normal[axis] >= 0 && !element.properties[layout.normal[axis]].is_list) ++normals;
    }
    if (normals != 0 && normals != 3) throw PlyError("the vertex element has some of nx, ny, nz but not all three");
    if (normals == 0) layout.normal[0] = layout.normal[1] = layout.normal[2] = -1;
    // Texture coordinates go by several names (pbrt-v3 reads u/v, s/t, texture_u/v, texture_s/t).
    const char* uv_names[][2] = {{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};
    for (const auto& names : uv_names) {
      int u = find_property(element, names[0]), v = find_property(element, names[1]);
      if (u >= 0 && v >= 0 && !element.properties[u].is_list && !element.properties[v].is_list) {
        layout.uv[0] = u;
        layout.uv[1] = v;
        break;
      }
    }
  } else if (element.name == "face") {
    layout.face_indices = find_property(element, "vertex_indices");
    if (layout.face_indices < 0) layout.face_indices = find_property(element, "vertex_index");
    if (layout.face_indices < 0 || !element.properties[layout.face_indices].is_list)
      throw PlyError("the face element needs a list property 'vertex_indices'");
    if (!is_integer(element.properties[layout.face_indices].type))
      throw PlyError("the face element's vertex_indices must be integers");
  }
  return layout;
}

// Fewest bytes one entry of `element` can take, to reject counts the file
// cannot hold before allocating for them.
size_t smallest_entry(const Element& element, Format format) {
  size_t bytes = 0;
  for (const Property& property : element.properties)
    bytes += format == Format::ascii ? 2 : size_of(property.is_list ? property.count_type : property.type);
  return std::max<size_t>(bytes, 1);
}

}  // namespace

PlyMesh parse_ply(std::string_view bytes) {
  Header header = parse_header(bytes);
  BodyReader reader(bytes.substr(header.body_offset), header.format, header.body_line);
  PlyMesh mesh;
  std::vector<uint64_t> face_of_triangle;
  bool has_vertices = false, has_faces = false;
  std::vector<Layout> layouts;  // all checked before any body byte is read
  for (const Element& element : header.elements) layouts.push_back(layout_of(element));
  for (size_t e = 0; e < header.elements.size(); ++e) {
    const Element& element = header.elements[e];
    const Layout& layout = layouts[e];
    bool is_vertex = element.name == "vertex", is_face = element.name == "face";
    if ((is_vertex && has_vertices) || (is_face && has_faces))
      throw PlyError("more than one '" + element.name + "' element");
    has_vertices |= is_vertex;
    has_faces |= is_face;
    // An ASCII entry takes at least 2 bytes per value, a binary one its size.
    if (element.count > (reader.remaining() + 1) / smallest_entry(element, header.format))
      throw PlyError("element '" + element.name + "' declares " + std::to_string(element.count) +
                     " entries, more than the rest of the file can hold (truncated?)");
    bool has_normals = is_vertex && layout.normal[0] >= 0;
    bool has_uvs = is_vertex && layout.uv[0] >= 0;
    if (is_vertex) {
      mesh.positions.reserve(element.count);
      if (has_normals) mesh.normals.reserve(element.count);
      if (has_uvs) mesh.uvs.reserve(element.count);
    }
    std::vector<double> scalars(element.properties.size());
    std::vector<uint32_t> polygon;
    for (uint64_t entry = 0; entry < element.count; ++entry) {
      auto where = [&] {
        return (header.format == Format::ascii ? "line " + std::to_string(reader.line()) + ": " : std::string()) +
               element.name + " " + std::to_string(entry) + ": ";
      };
      auto value = [&](Scalar type, const std::string& what) {
        std::string error;
        std::optional<double> v = reader.next(type, error);
        if (!v) throw PlyError(where() + "the file ends inside the element (truncated?)");
        if (!error.empty()) throw PlyError(where() + what + ": " + error);
        return *v;
      };
      for (size_t p = 0; p < element.properties.size(); ++p) {
        const Property& property = element.properties[p];
        if (!property.is_list) {
          scalars[p] = value(property.type, "property '" + property.name + "'");
          continue;
        }
        double count = value(property.count_type, "the count of list '" + property.name + "'");
        if (count < 0 || count > kMaxPolygonVertices)
          throw PlyError(where() + "list '" + property.name + "' has " + std::to_string(static_cast<long long>(count)) +
                         " items (expected 0 to " + std::to_string(kMaxPolygonVertices) + ")");
        bool is_polygon = is_face && static_cast<int>(p) == layout.face_indices;
        if (is_polygon) polygon.clear();
        for (int i = 0; i < static_cast<int>(count); ++i) {
          double item = value(property.type, "list '" + property.name + "'");
          if (!is_polygon) continue;
          if (item < 0 || item > 4294967295.0)
            throw PlyError(where() + "vertex index " + std::to_string(static_cast<long long>(item)) + " is out of range");
          polygon.push_back(static_cast<uint32_t>(item));
        }
        if (is_polygon) {
          if (polygon.size() < 3)
            throw PlyError(where() + "a face needs at least 3 vertices, this one has " + std::to_string(polygon.size()));
          for (size_t i = 1; i + 1 < polygon.size(); ++i) {  // fan: triangles, quads, convex polygons
            mesh.indices.insert(mesh.indices.end(), {polygon[0], polygon[i], polygon[i + 1]});
            face_of_triangle.push_back(entry);
          }
        }
      }
      if (is_vertex) {
        std::array<float, 3> position{}, normal{};
        for (int axis = 0; axis < 3; ++axis) {
          position[axis] = static_cast<float>(scalars[layout.position[axis]]);
          if (!std::isfinite(position[axis])) throw PlyError(where() + "the position is not finite");
          if (has_normals) normal[axis] = static_cast<float>(scalars[layout.normal[axis]]);
        }
        mesh.positions.push_back(position);
        if (has_normals) mesh.normals.push_back(normal);
        if (has_uvs)
          mesh.uvs.push_back({static_cast<float>(scalars[layout.uv[0]]), static_cast<float>(scalars[layout.uv[1]])});
      }
    }
  }
  if (!has_vertices) throw PlyError("no 'vertex' element");
  if (!has_faces) throw PlyError("no 'face' element");
  for (size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= mesh.positions.size())
      throw PlyError("face " + std::to_string(face_of_triangle[i / 3]) + ": vertex index " +
                     std::to_string(mesh.indices[i]) + " is out of range (" + std::to_string(mesh.positions.size()) +
                     " vertices)");
  return mesh;
}

}  // namespace safegi::render
