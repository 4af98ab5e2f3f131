#include <safegi/diagnostics/diagnostic.hpp>

#include <gtest/gtest.h>

namespace safegi {
namespace {

TEST(DiagnosticEngine, CountsBySeverity) {
  DiagnosticEngine engine;
  engine.error({}, "e1");
  engine.warning({}, "w1");
  engine.report(Diagnostic::note({}, "n"));
  EXPECT_EQ(engine.error_count(), 1u);
  EXPECT_EQ(engine.warning_count(), 1u);
  EXPECT_TRUE(engine.has_errors());
  ASSERT_EQ(engine.diagnostics().size(), 3u);
  EXPECT_EQ(engine.diagnostics()[1].message, "w1");
}

TEST(DiagnosticEngine, WerrorPromotesWarnings) {
  DiagnosticEngine engine({.warnings_as_errors = true});
  engine.warning({}, "w");
  EXPECT_EQ(engine.error_count(), 1u);
  EXPECT_EQ(engine.warning_count(), 0u);
  EXPECT_EQ(engine.diagnostics()[0].severity, Severity::error);
}

TEST(DiagnosticEngine, SuppressedWarningsAreDropped) {
  DiagnosticEngine engine({.suppress_warnings = true});
  engine.warning({}, "w");
  EXPECT_TRUE(engine.diagnostics().empty());
}

TEST(DiagnosticEngine, ErrorLimitStopsWithAFinalError) {
  DiagnosticEngine engine({.error_limit = 2});
  engine.error({}, "a");
  engine.warning({}, "w");
  EXPECT_FALSE(engine.limit_reached());
  engine.error({}, "b");
  EXPECT_TRUE(engine.limit_reached());
  engine.error({}, "c");
  ASSERT_EQ(engine.diagnostics().size(), 4u);
  EXPECT_EQ(engine.diagnostics()[3].severity, Severity::note);
  EXPECT_EQ(engine.diagnostics()[3].message, "too many errors emitted, stopping now (error limit 2)");
  EXPECT_EQ(engine.error_count(), 2u);
}

TEST(Diagnostic, BuildersChain) {
  Diagnostic d = Diagnostic::error({}, "m").with_hint("h").with_code("E-X").with_note(Diagnostic::note({}, "n"));
  EXPECT_EQ(d.hint, "h");
  EXPECT_EQ(d.code, "E-X");
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].severity, Severity::note);
}

}  // namespace
}  // namespace safegi
