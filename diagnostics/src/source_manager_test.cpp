#include <safegi/diagnostics/source_manager.hpp>

#include <gtest/gtest.h>

namespace safegi {
namespace {

TEST(SourceManager, LocationsAreOneBasedLinesAndByteColumns) {
  SourceManager sm;
  FileId f = sm.add_file("a.glsl", "ab\ncd\r\nef\rg");
  EXPECT_EQ(sm.line_count(f), 4u);
  EXPECT_EQ(sm.location_of(f, 0), (SourceLocation{f, 0, 1, 1}));
  EXPECT_EQ(sm.location_of(f, 2), (SourceLocation{f, 2, 1, 3}));
  EXPECT_EQ(sm.location_of(f, 3), (SourceLocation{f, 3, 2, 1}));
  EXPECT_EQ(sm.location_of(f, 7), (SourceLocation{f, 7, 3, 1}));
  EXPECT_EQ(sm.location_of(f, 10), (SourceLocation{f, 10, 4, 1}));
  EXPECT_EQ(sm.location_of(f, 99).offset, 11u);  // clamped
  EXPECT_EQ(sm.line_text(f, 1), "ab");
  EXPECT_EQ(sm.line_text(f, 2), "cd");
  EXPECT_EQ(sm.line_text(f, 3), "ef");
  EXPECT_EQ(sm.line_text(f, 4), "g");
  EXPECT_EQ(sm.line_text(f, 5), "");
}

TEST(SourceManager, LocationAfterAgreesWithLocationOf) {
  SourceManager sm;
  FileId f = sm.add_file("a.glsl", "ab\n\ncd\r\nef\rg\n");
  std::uint32_t hint = 0;
  for (std::uint32_t offset = 0; offset <= 13; ++offset) {
    EXPECT_EQ(sm.location_after(f, offset, hint), sm.location_of(f, offset)) << offset;
  }
  hint = 5;  // a hint past the offset falls back to the search
  EXPECT_EQ(sm.location_after(f, 1, hint), sm.location_of(f, 1));
  EXPECT_EQ(hint, 1u);
}

TEST(SourceManager, FileIdsStartAtOneAndPathsAreKept) {
  SourceManager sm;
  EXPECT_FALSE(sm.valid(kNoFile));
  FileId a = sm.add_file("a.glsl", "x");
  FileId b = sm.add_file("b.glsl", "");
  EXPECT_EQ(a, 1u);
  EXPECT_EQ(b, 2u);
  EXPECT_EQ(sm.path(b), "b.glsl");
  EXPECT_EQ(sm.text(a), "x");
  EXPECT_EQ(sm.line_count(b), 1u);
}

TEST(SourceManager, LoadFileReportsMissingFiles) {
  SourceManager sm;
  std::string error;
  EXPECT_FALSE(sm.load_file("/nonexistent/dir/shader.glsl", &error));
  EXPECT_EQ(error, "No such file or directory");
}

TEST(SourceManager, IncludeChainIsOutermostFirst) {
  SourceManager sm;
  FileId main = sm.add_file("main.glsl", "#include \"a.glsl\"\n");
  FileId a = sm.add_file("a.glsl", "\n#include \"b.glsl\"\n");
  FileId b = sm.add_file("b.glsl", "x");
  sm.set_included_from(a, sm.range_of(main, 0, 17));
  sm.set_included_from(b, sm.range_of(a, 1, 18));
  auto chain = sm.include_chain(b);
  ASSERT_EQ(chain.size(), 2u);
  EXPECT_EQ(chain[0].begin.file, main);
  EXPECT_EQ(chain[1].begin.file, a);
  EXPECT_EQ(chain[1].begin.line, 2u);
  EXPECT_TRUE(sm.include_chain(main).empty());
}

TEST(SourceManager, InclusionSharesTheBufferButNotThePosition) {
  SourceManager sm;
  FileId main = sm.add_file("main.glsl", "abc");
  FileId inc = sm.add_file("inc.glsl", "body");
  FileId second = sm.add_inclusion(inc, sm.range_of(main, 1, 2));
  EXPECT_NE(second, inc);
  EXPECT_EQ(sm.text(second).data(), sm.text(inc).data());
  EXPECT_EQ(sm.included_from(second).begin.offset, 1u);
  EXPECT_FALSE(sm.included_from(inc).valid());
}

TEST(SourceManager, LineDirectivesChangePresumedLines) {
  SourceManager sm;
  FileId f = sm.add_file("a.glsl", "a\n#line 10\nb\nc\n#line 20 3\nd\n");
  sm.add_line_directive(f, 11, 10, std::nullopt, std::nullopt);
  sm.add_line_directive(f, 26, 20, std::nullopt, 3u);
  EXPECT_EQ(sm.presumed(sm.location_of(f, 0)).line, 1u);
  EXPECT_EQ(sm.presumed(sm.location_of(f, 11)).line, 10u);
  EXPECT_EQ(sm.presumed(sm.location_of(f, 13)).line, 11u);
  PresumedLocation d = sm.presumed(sm.location_of(f, 26));
  EXPECT_EQ(d.line, 20u);
  EXPECT_EQ(d.file_name, "a.glsl");
  EXPECT_EQ(d.source_string, 3u);
}

TEST(SourceManager, SavedStringsStayValid) {
  SourceManager sm;
  std::string_view first = sm.save_string("ab");
  for (int i = 0; i < 1000; ++i) sm.save_string(std::string(i % 40, 'x'));
  EXPECT_EQ(first, "ab");
}

TEST(SourceManager, ExpansionTable) {
  SourceManager sm;
  FileId f = sm.add_file("a.glsl", "#define X 1\nX\n");
  ExpansionId e = sm.add_expansion({"X", sm.range_of(f, 8, 9), sm.range_of(f, 12, 13), kNoExpansion});
  EXPECT_EQ(e, 1u);
  EXPECT_EQ(sm.expansion(e).name, "X");
  EXPECT_EQ(sm.expansion(e).expansion_site.begin.line, 2u);
  EXPECT_THROW(sm.expansion(kNoExpansion), std::out_of_range);
}

}  // namespace
}  // namespace safegi
