#include "uri.hpp"

#include <gtest/gtest.h>

namespace safegi::lsp {
namespace {

TEST(Uri, FileUrisAndPaths) {
  EXPECT_EQ(path_from_uri("file:///home/u/light.sgl.frag"), "/home/u/light.sgl.frag");
  EXPECT_EQ(path_from_uri("file:///home/u/my%20shaders/l%C3%A9ger.frag"), "/home/u/my shaders/léger.frag");
  EXPECT_EQ(path_from_uri("file://localhost/a/b.frag"), "/a/b.frag");
  EXPECT_EQ(path_from_uri("FILE:///a.frag"), "/a.frag");
  EXPECT_EQ(path_from_uri("file:///a.frag?x#y"), "/a.frag");
  EXPECT_EQ(path_from_uri("untitled:Untitled-1"), std::nullopt);
  EXPECT_EQ(path_from_uri("file://host/a.frag"), std::nullopt);  // not a local file
  EXPECT_EQ(path_from_uri("file:///a%2"), std::nullopt);
  EXPECT_EQ(path_from_uri("file:///a%00b"), std::nullopt);
  EXPECT_EQ(path_from_uri("file:"), std::nullopt);
  EXPECT_EQ(uri_from_path("/home/u/my shaders/léger.frag"), "file:///home/u/my%20shaders/l%C3%A9ger.frag");
  EXPECT_EQ(path_from_uri(uri_from_path("/a/#b%c?.frag")), "/a/#b%c?.frag");
}

}  // namespace
}  // namespace safegi::lsp
