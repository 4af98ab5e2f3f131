#include "scene/ply.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <random>
#include <utility>

namespace safegi::render {
namespace {

// A unit square as one quad and a triangle on top, with normals and an extra
// per-vertex property and element that the reader must skip.
const char* const kAscii =
    "ply\n"
    "format ascii 1.0\n"
    "comment made by hand\n"
    "element vertex 5\n"
    "property float x\nproperty float y\nproperty float z\n"
    "property float nx\nproperty float ny\nproperty float nz\n"
    "property uchar red\n"
    "element face 2\n"
    "property list uchar int vertex_indices\n"
    "element edge 1\n"
    "property int vertex1\nproperty int vertex2\n"
    "end_header\n"
    "0 0 0 0 0 1 255\n"
    "1 0 0 0 0 1 255\n"
    "1 1 0 0 0 1 255\n"
    "0 1 0 0 0 1 255\n"
    "0.5 1.5 0 0 0 1 7\n"
    "4 0 1 2 3\n"
    "3 3 2 4\n"
    "0 1\n";

template <class T>
void put(std::string& out, T value, bool big_endian) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big))
    for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
  out.append(raw, sizeof(T));
}

// The same mesh in binary (vertices as float, faces with uchar counts and int indices).
std::string binary(bool big_endian) {
  std::string out = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\n"
                    "element vertex 5\n"
                    "property float x\nproperty float y\nproperty float z\n"
                    "property double nx\nproperty double ny\nproperty double nz\n"
                    "element face 2\n"
                    "property list uchar int vertex_indices\n"
                    "end_header\n";
  const float positions[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 1.5f, 0}};
  for (const auto& p : positions) {
    for (float c : p) put(out, c, big_endian);
    for (double n : {0.0, 0.0, 1.0}) put(out, n, big_endian);
  }
  put<uint8_t>(out, 4, big_endian);
  for (int32_t i : {0, 1, 2, 3}) put(out, i, big_endian);
  put<uint8_t>(out, 3, big_endian);
  for (int32_t i : {3, 2, 4}) put(out, i, big_endian);
  return out;
}

void expect_square_and_roof(const PlyMesh& mesh) {
  ASSERT_EQ(mesh.positions.size(), 5u);
  EXPECT_EQ(mesh.positions[4], (std::array<float, 3>{0.5f, 1.5f, 0}));
  ASSERT_EQ(mesh.normals.size(), 5u);
  EXPECT_EQ(mesh.normals[2], (std::array<float, 3>{0, 0, 1}));
  // The quad is fanned into two triangles.
  EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 3, 2, 4}));
}

std::string error_of(std::string_view bytes) {
  try {
    parse_ply(bytes);
  } catch (const PlyError& error) {
    return error.what();
  }
  return "no error";
}

TEST(Ply, ReadsAsciiTrianglesAndQuads) { expect_square_and_roof(parse_ply(kAscii)); }

TEST(Ply, ReadsBinaryInEitherByteOrder) {
  expect_square_and_roof(parse_ply(binary(false)));
  expect_square_and_roof(parse_ply(binary(true)));
}

TEST(Ply, CrlfLineEndsAndNoNormals) {
  PlyMesh mesh = parse_ply(
      "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty double x\r\nproperty double y\r\nproperty double z\r\n"
      "element face 1\r\nproperty list uchar uint vertex_index\r\nend_header\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n");
  EXPECT_EQ(mesh.positions.size(), 3u);
  EXPECT_TRUE(mesh.normals.empty());
  EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 1, 2}));
}

TEST(Ply, MalformedFilesNameTheProblem) {
  const std::string vertex3 = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string face1 = "element face 1\nproperty list uchar int vertex_indices\n";
  const std::string ascii = "ply\nformat ascii 1.0\n";
  EXPECT_EQ(error_of("solid cube\n"), "not a PLY file: expected 'ply' on line 1");
  EXPECT_EQ(error_of("ply\nformat ascii 2.0\nend_header\n"),
            "line 2: expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0', got 'format ascii 2.0'");
  EXPECT_EQ(error_of("ply\nformat binary_middle_endian 1.0\n"), "line 2: unknown format 'binary_middle_endian'");
  EXPECT_EQ(error_of(ascii + "element vertex 3\nproperty flaot x\n"), "line 4: unknown property type 'flaot'");
  EXPECT_EQ(error_of(ascii + "element vertex many\n"), "line 3: expected 'element <name> <count>', got 'element vertex many'");
  EXPECT_EQ(error_of(ascii + "property float x\n"), "line 3: property before any element");
  EXPECT_EQ(error_of(ascii + "element face 1\nproperty list float int vertex_indices\n"),
            "line 4: a list's count must have an integer type, got 'float'");
  EXPECT_EQ(error_of(ascii + vertex3), "the header has no end_header");
  EXPECT_EQ(error_of(ascii + "vertices 3\nend_header\n"), "line 3: unknown header keyword 'vertices'");
  EXPECT_EQ(error_of(ascii + "element vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n"),
            "the vertex element needs a scalar property 'z'");
  EXPECT_EQ(error_of(ascii + vertex3 + "property float nx\n" + face1 + "end_header\n"),
            "the vertex element has some of nx, ny, nz but not all three");
  EXPECT_EQ(error_of(ascii + vertex3 + "element face 1\nproperty int vertex_indices\nend_header\n"),
            "the face element needs a list property 'vertex_indices'");
  EXPECT_EQ(error_of(ascii + vertex3 + "end_header\n0 0 0\n1 0 0\n0 1 0\n"), "no 'face' element");
  // Bodies of a one-triangle file, damaged.
  const std::pair<const char*, const char*> bodies[] = {
      {"0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "face 0: vertex index 7 is out of range (3 vertices)"},
      {"0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n", "line 13: face 0: vertex index -1 is out of range"},
      {"0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "line 13: face 0: a face needs at least 3 vertices, this one has 2"},
      {"0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n", "line 11: vertex 1: property 'y': expected a number, got 'zero'"},
      {"0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "line 11: vertex 1: the position is not finite"},
      {"0 0 0\n1 0 0\n0 1 0\n3 0 1\n", "line 14: face 0: the file ends inside the element (truncated?)"},
  };
  for (const auto& [body, expected] : bodies)
    EXPECT_EQ(error_of(ascii + vertex3 + face1 + "end_header\n" + body), expected);
  EXPECT_EQ(error_of(ascii + "element vertex 4000000000\nproperty float x\nproperty float y\nproperty float z\n" + face1 +
                     "end_header\n0 0 0\n"),
            "element 'vertex' declares 4000000000 entries, more than the rest of the file can hold (truncated?)");
  std::string truncated = binary(false);
  truncated.resize(truncated.size() - 3);
  EXPECT_EQ(error_of(truncated), "face 1: the file ends inside the element (truncated?)");
}

// Every prefix of a valid file, and files with random bytes overwritten, give
// a mesh or a PlyError: never a crash, a hang or another exception.
TEST(Ply, TruncatedAndGarbledInputNeverCrashes) {
  std::mt19937 random(20261123);
  int errors = 0;
  for (const std::string& valid : {std::string(kAscii), binary(false), binary(true)}) {
    for (size_t length = 0; length < valid.size(); ++length) {
      try {
        parse_ply(std::string_view(valid).substr(0, length));
      } catch (const PlyError&) {
        ++errors;
      }
    }
    for (int round = 0; round < 3000; ++round) {
      std::string garbled = valid;
      int changes = 1 + static_cast<int>(random() % 4);
      for (int c = 0; c < changes; ++c) garbled[random() % garbled.size()] = static_cast<char>(random() % 256);
      try {
        PlyMesh mesh = parse_ply(garbled);
        for (uint32_t index : mesh.indices) ASSERT_LT(index, mesh.positions.size());
      } catch (const PlyError&) {
        ++errors;
      }
    }
  }
  EXPECT_GT(errors, 1000);  // the damage was seen, not silently accepted
}

}  // namespace
}  // namespace safegi::render
