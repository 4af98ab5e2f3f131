#pragma once
// One document through safegi::compile — the same pipeline, prelude and
// include rules as safeglslc — and the mapping of what comes out (diagnostics,
// symbols) onto LSP locations.
//
// Diagnostics in an #include'd file are reported at the #include line of the
// document ("In included file: …", as clangd does), with the real location
// as related information: the document's diagnostics are the result of
// compiling the document, and a header included by two shaders (with
// different macros) has no diagnostics of its own to publish.

#include <map>
#include <memory>
#include <optional>
#include <string>

#include <safegi/compiler/compile.hpp>

#include "positions.hpp"
#include "protocol.hpp"

namespace safegi::lsp {

struct Document;

struct Analysis {
  CompileResult result;  // with keep_analysis: result.stages[0].analysis when the document parsed
  const StageAnalysis* stage() const {
    return result.stages.empty() ? nullptr : result.stages.front().analysis.get();
  }
};

// `options.read_file` serves the includes (the server's open documents first).
std::shared_ptr<const Analysis> analyze(const Document& document, CompileOptions options);

// Source locations of one analysis as LSP locations, in the client's encoding.
class Locator {
 public:
  // `prelude_file`: a file on disk with the built-in prelude's text, where its
  // declarations are shown ("" when there is none).
  Locator(const Document& document, const SourceManager& sources, Encoding encoding, std::string prelude_file);

  bool in_document(FileId file) const;
  std::optional<std::string> uri(FileId file) const;  // nothing for the built-in prelude without a copy on disk
  json range(SourceRange range) const;                // in its own file
  std::optional<json> location(SourceRange range) const;
  // `range` if it is in the document, else the #include line that leads to it.
  SourceRange in_document_range(SourceRange range) const;

 private:
  const LineIndex& lines(FileId file) const;

  const Document& document_;
  const SourceManager& sources_;
  Encoding encoding_;
  std::string prelude_file_;
  mutable std::map<FileId, LineIndex> lines_;
};

struct DiagnosticStyle {
  bool related_information = false;  // the client shows relatedInformation; else notes and hints join the message
};

// The document's publishDiagnostics list.
json diagnostics_json(const Analysis& analysis, const Locator& locator, DiagnosticStyle style);

}  // namespace safegi::lsp
