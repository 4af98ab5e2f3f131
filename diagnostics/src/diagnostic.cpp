#include <safegi/diagnostics/diagnostic.hpp>

#include <utility>

namespace safegi {

std::string_view severity_name(Severity severity) {
  switch (severity) {
    case Severity::error: return "error";
    case Severity::warning: return "warning";
    case Severity::note: return "note";
  }
  return "error";
}

namespace {
Diagnostic make(Severity severity, SourceRange range, std::string message) {
  Diagnostic d;
  d.severity = severity;
  d.range = range;
  d.message = std::move(message);
  return d;
}
}  // namespace

Diagnostic Diagnostic::error(SourceRange range, std::string message) {
  return make(Severity::error, range, std::move(message));
}
Diagnostic Diagnostic::warning(SourceRange range, std::string message) {
  return make(Severity::warning, range, std::move(message));
}
Diagnostic Diagnostic::note(SourceRange range, std::string message) {
  return make(Severity::note, range, std::move(message));
}

Diagnostic& Diagnostic::with_note(Diagnostic n) & {
  notes.push_back(std::move(n));
  return *this;
}
Diagnostic&& Diagnostic::with_note(Diagnostic n) && { return std::move(with_note(std::move(n))); }
Diagnostic& Diagnostic::with_highlight(SourceRange r) & {
  highlights.push_back(r);
  return *this;
}
Diagnostic&& Diagnostic::with_highlight(SourceRange r) && { return std::move(with_highlight(r)); }
Diagnostic& Diagnostic::with_hint(std::string h) & {
  hint = std::move(h);
  return *this;
}
Diagnostic&& Diagnostic::with_hint(std::string h) && { return std::move(with_hint(std::move(h))); }
Diagnostic& Diagnostic::with_code(std::string c) & {
  code = std::move(c);
  return *this;
}
Diagnostic&& Diagnostic::with_code(std::string c) && { return std::move(with_code(std::move(c))); }
Diagnostic& Diagnostic::with_expansion(ExpansionId e) & {
  expansion = e;
  return *this;
}
Diagnostic&& Diagnostic::with_expansion(ExpansionId e) && { return std::move(with_expansion(e)); }

void DiagnosticEngine::report(Diagnostic diagnostic) {
  if (limit_reached_) return;
  if (diagnostic.severity == Severity::warning) {
    if (options_.suppress_warnings) return;
    if (options_.warnings_as_errors) diagnostic.severity = Severity::error;
  }
  if (diagnostic.severity == Severity::warning) ++warning_count_;
  if (diagnostic.severity == Severity::error) ++error_count_;
  diagnostics_.push_back(std::move(diagnostic));
  if (options_.error_limit != 0 && error_count_ >= options_.error_limit &&
      diagnostics_.back().severity == Severity::error) {
    limit_reached_ = true;
    diagnostics_.push_back(Diagnostic::note(
        SourceRange{}, "too many errors emitted, stopping now (error limit " +
                           std::to_string(options_.error_limit) + ")"));
  }
}

void DiagnosticEngine::error(SourceRange range, std::string message) {
  report(Diagnostic::error(range, std::move(message)));
}

void DiagnosticEngine::warning(SourceRange range, std::string message) {
  report(Diagnostic::warning(range, std::move(message)));
}

void DiagnosticEngine::clear() {
  diagnostics_.clear();
  error_count_ = warning_count_ = 0;
  limit_reached_ = false;
}

}  // namespace safegi
