#include "safegi/lsp/server.hpp"

#include <filesystem>
#include <map>

#include <safegi/compiler/compile.hpp>

#include "analysis.hpp"
#include "completion.hpp"
#include "documents.hpp"
#include "navigation.hpp"
#include "protocol.hpp"
#include "uri.hpp"

namespace safegi::lsp {
namespace {

// A string array member of an optional object; nothing when absent.
std::vector<std::string> strings_of(const json& object, const char* name) {
  std::vector<std::string> out;
  if (!object.is_object() || !object.contains(name)) return out;
  const json& list = object[name];
  if (!list.is_array()) throw RequestError{error_code::invalid_params, "'" + std::string(name) + "' must be an array of strings"};
  for (const json& s : list) {
    if (!s.is_string()) throw RequestError{error_code::invalid_params, "'" + std::string(name) + "' must be an array of strings"};
    out.push_back(s.get<std::string>());
  }
  return out;
}

// `capabilities.textDocument.hover.contentFormat` and the like: the value at a
// path of members, or null. A reference: the client's JSON is never copied
// (copying is recursive, and a message may nest a million levels deep).
const json& at_path(const json& root, std::initializer_list<const char*> path) {
  static const json null;
  const json* here = &root;
  for (const char* name : path) {
    if (!here->is_object()) return null;
    auto it = here->find(name);
    if (it == here->end()) return null;
    here = &*it;
  }
  return *here;
}

enum class Phase { uninitialized, running, shutting_down, exited };

}  // namespace

struct Server::Impl {
  ServerOptions options;
  Phase phase = Phase::uninitialized;
  bool shutdown_received = false;
  Encoding encoding = Encoding::utf16;
  DiagnosticStyle diagnostic_style;
  HoverStyle hover_style;
  std::map<std::string, Document> documents;  // by URI
  std::vector<std::string> outgoing;

  explicit Impl(ServerOptions o) : options(std::move(o)) {}

  void send(const json& message) { outgoing.push_back(serialize(message)); }
  // window/logMessage; not before initialize, when the protocol lets a server send nothing.
  void log(int type, const std::string& message) {
    if (phase == Phase::uninitialized) return;
    send(notification("window/logMessage", {{"type", type}, {"message", std::string(kServerName) + ": " + message}}));
  }

  // ------------------------------------------------------------- dispatch

  using Request = json (Impl::*)(const json& params);
  using Notification = void (Impl::*)(const json& params);

  static const std::map<std::string, Request, std::less<>>& requests() {
    static const std::map<std::string, Request, std::less<>> table = {
        {"initialize", &Impl::initialize},
        {"shutdown", &Impl::shutdown},
        {"textDocument/hover", &Impl::hover_request},
        {"textDocument/definition", &Impl::definition_request},
        {"textDocument/completion", &Impl::completion_request},
    };
    return table;
  }
  static const std::map<std::string, Notification, std::less<>>& notifications() {
    static const std::map<std::string, Notification, std::less<>> table = {
        {"initialized", &Impl::ignore},
        {"exit", &Impl::exit},
        {"textDocument/didOpen", &Impl::did_open},
        {"textDocument/didChange", &Impl::did_change},
        {"textDocument/didClose", &Impl::did_close},
        {"textDocument/didSave", &Impl::ignore},
        {"workspace/didChangeConfiguration", &Impl::ignore},
        {"$/cancelRequest", &Impl::ignore},  // every request is answered before the next is read
        {"$/setTrace", &Impl::ignore},
    };
    return table;
  }

  void handle(std::string_view body) {
    if (phase == Phase::exited) return;
    json message = json::parse(body, nullptr, /*allow_exceptions=*/false);
    if (message.is_discarded()) return send(error_response(nullptr, error_code::parse_error, "invalid JSON"));
    if (!message.is_object())
      return send(error_response(nullptr, error_code::invalid_request, "a message must be a JSON object (batches are not part of LSP)"));
    const bool has_id = message.contains("id");
    const json& raw_id = at_path(message, {"id"});
    const bool valid_id = raw_id.is_string() || raw_id.is_number_integer();
    const json id = valid_id ? raw_id : json();  // a copy only of a string or a number
    if (at_path(message, {"jsonrpc"}) != "2.0")
      return send(error_response(id, error_code::invalid_request, "\"jsonrpc\" must be \"2.0\""));
    if (!message.contains("method")) {
      if (has_id && (message.contains("result") || message.contains("error"))) return;  // a reply; this server asks nothing
      return send(error_response(id, error_code::invalid_request, "a request needs a \"method\""));
    }
    if (!message["method"].is_string())
      return send(error_response(id, error_code::invalid_request, "\"method\" must be a string"));
    const std::string method = message["method"].get<std::string>();
    // `"params": null` is not JSON-RPC, but clients send it with exit and shutdown: as if absent.
    static const json no_params = json::object();
    const json& given = at_path(message, {"params"});
    const json& params = given.is_null() ? no_params : given;
    if (!params.is_object() && !params.is_array())
      return has_id ? send(error_response(id, error_code::invalid_request, "\"params\" must be an object or an array"))
                    : log(1, method + ": \"params\" must be an object or an array");
    if (!has_id) return dispatch_notification(method, params);
    if (!valid_id) return send(error_response(nullptr, error_code::invalid_request, "\"id\" must be an integer or a string"));
    dispatch_request(id, method, params);
  }

  void dispatch_request(const json& id, const std::string& method, const json& params) {
    if (phase == Phase::uninitialized && method != "initialize")
      return send(error_response(id, error_code::server_not_initialized, "the server is not initialized yet"));
    if (phase == Phase::shutting_down)
      return send(error_response(id, error_code::invalid_request, "the server is shutting down"));
    auto it = requests().find(method);
    if (it == requests().end()) return send(error_response(id, error_code::method_not_found, "unknown method '" + method + "'"));
    try {
      json result = (this->*(it->second))(params);
      send(response(id, std::move(result)));
    } catch (const RequestError& e) {
      send(error_response(id, e.code, method + ": " + e.message));
    } catch (const std::exception& e) {
      send(error_response(id, error_code::internal_error, method + ": " + e.what()));
    }
  }

  void dispatch_notification(const std::string& method, const json& params) {
    // Before initialize only exit counts; after shutdown, too.
    if (method != "exit" && phase != Phase::running) return;
    auto it = notifications().find(method);
    if (it == notifications().end()) return;  // unknown notifications ($/…, others) are ignored, as the spec says
    try {
      (this->*(it->second))(params);
    } catch (const RequestError& e) {
      log(1, method + ": " + e.message);
    } catch (const std::exception& e) {
      log(1, method + ": " + e.what());
    }
  }

  void ignore(const json&) {}

  // ------------------------------------------------------------ lifecycle

  json initialize(const json& params) {
    if (phase != Phase::uninitialized) throw RequestError{error_code::invalid_request, "initialize may be sent only once"};
    if (!params.is_object()) throw RequestError{error_code::invalid_params, "expected an object"};
    const json& capabilities = at_path(params, {"capabilities"});
    // utf-8 when the client offers it: positions are then the compiler's own byte columns.
    const std::vector<std::string> encodings = strings_of(at_path(capabilities, {"general"}), "positionEncodings");
    for (const std::string& e : encodings)
      if (e == "utf-8") encoding = Encoding::utf8;
    diagnostic_style.related_information =
        at_path(capabilities, {"textDocument", "publishDiagnostics", "relatedInformation"}) == true;
    const std::vector<std::string> formats = strings_of(at_path(capabilities, {"textDocument", "hover"}), "contentFormat");
    hover_style.markdown = formats.empty() || std::find(formats.begin(), formats.end(), "markdown") != formats.end();
    read_initialization_options(params);
    phase = Phase::running;
    return {{"capabilities",
             {{"positionEncoding", encoding_name(encoding)},
              {"textDocumentSync", {{"openClose", true}, {"change", sync_kind::incremental}}},
              {"hoverProvider", true},
              {"definitionProvider", true},
              {"completionProvider", {{"triggerCharacters", {"<", ","}}}}}},
            {"serverInfo", {{"name", kServerName}, {"version", kCompilerVersion}}}};
  }

  // initializationOptions: {"includePaths": [...], "defines": ["NAME=value", ...], "strict": bool,
  // "notesInMessage": bool};
  // relative include paths are taken from the workspace root.
  void read_initialization_options(const json& params) {
    const json& init = at_path(params, {"initializationOptions"});
    if (init.is_null()) return;
    if (!init.is_object()) throw RequestError{error_code::invalid_params, "initializationOptions must be an object"};
    std::filesystem::path root;
    if (params.contains("rootUri") && params["rootUri"].is_string())
      if (std::optional<std::string> p = path_from_uri(params["rootUri"].get<std::string>())) root = *p;
    for (const std::string& dir : strings_of(init, "includePaths")) {
      const std::filesystem::path p(dir);
      options.include_paths.push_back(p.is_relative() && !root.empty() ? (root / p).lexically_normal().string() : dir);
    }
    for (const std::string& d : strings_of(init, "defines")) {
      const std::size_t eq = d.find('=');
      options.defines.emplace_back(d.substr(0, eq), eq == std::string::npos ? "1" : d.substr(eq + 1));
    }
    auto flag = [&](const char* name, bool& into) {
      if (!init.contains(name)) return;
      if (!init[name].is_boolean()) throw RequestError{error_code::invalid_params, "'" + std::string(name) + "' must be a boolean"};
      into = init[name].get<bool>();
    };
    flag("strict", options.strict);
    // For clients that take related information but show only the message.
    bool notes_in_message = false;
    flag("notesInMessage", notes_in_message);
    if (notes_in_message) diagnostic_style.related_information = false;
  }

  json shutdown(const json&) {
    phase = Phase::shutting_down;
    shutdown_received = true;
    return nullptr;
  }

  void exit(const json&) { phase = Phase::exited; }

  // ------------------------------------------------------------ documents

  CompileOptions compile_options() const {
    CompileOptions c;
    c.include_paths = options.include_paths;
    c.defines = options.defines;
    c.strict = options.strict;
    // An #include'd file open in the editor is read as the editor has it.
    c.read_file = [this](const std::string& path) -> std::optional<std::string> {
      for (const auto& [uri, doc] : documents)
        if (doc.path == path) return doc.text;
      return options.read_file ? options.read_file(path) : read_file_from_disk(path);
    };
    return c;
  }

  Document& open_document(const json& params) {
    const std::string uri = string_member(member(params, "textDocument"), "uri");
    auto it = documents.find(uri);
    if (it == documents.end()) throw RequestError{error_code::invalid_params, "'" + uri + "' is not open"};
    return it->second;
  }

  void analyze_and_publish(Document& doc) {
    doc.analysis = analyze(doc, compile_options());
    if (doc.analysis->stage()) doc.last_checked = doc.analysis;
    json diagnostics = json::array();
    if (doc.analysis->result.sources) {
      const Locator locator(doc, *doc.analysis->result.sources, encoding, options.prelude_file);
      diagnostics = diagnostics_json(*doc.analysis, locator, diagnostic_style);
    }
    send(notification("textDocument/publishDiagnostics",
                      {{"uri", doc.uri}, {"version", doc.version}, {"diagnostics", std::move(diagnostics)}}));
  }

  // Documents that include `path` see its new text.
  void reanalyze_dependents(const Document& changed) {
    for (auto& [uri, doc] : documents) {
      if (uri == changed.uri || !doc.analysis) continue;
      const std::vector<std::string>& deps = doc.analysis->result.dependencies;
      if (std::find(deps.begin(), deps.end(), changed.path) != deps.end()) analyze_and_publish(doc);
    }
  }

  void did_open(const json& params) {
    const json& item = member(params, "textDocument");
    Document doc;
    doc.uri = string_member(item, "uri");
    doc.path = path_from_uri(doc.uri).value_or(doc.uri);
    doc.language_id = item.contains("languageId") && item["languageId"].is_string() ? item["languageId"].get<std::string>() : "";
    doc.text = string_member(item, "text");
    if (item.contains("version") && item["version"].is_number_integer()) doc.version = item["version"].get<std::int64_t>();
    Document& stored = documents[doc.uri] = std::move(doc);
    analyze_and_publish(stored);
    reanalyze_dependents(stored);
  }

  void did_change(const json& params) {
    Document& doc = open_document(params);
    const json& changes = member(params, "contentChanges");
    if (!changes.is_array()) throw RequestError{error_code::invalid_params, "'contentChanges' must be an array"};
    Document edited = doc;  // all or nothing: a malformed change leaves the document as it was
    for (const json& change : changes) apply_change(edited, change, encoding);
    const json& version = member(member(params, "textDocument"), "version");
    if (version.is_number_integer()) edited.version = version.get<std::int64_t>();
    doc = std::move(edited);
    analyze_and_publish(doc);
    reanalyze_dependents(doc);
  }

  void did_close(const json& params) {
    const std::string uri = string_member(member(params, "textDocument"), "uri");
    if (documents.erase(uri) == 0) return;
    // Diagnostics of a closed file are the client's to forget; an empty list clears them.
    send(notification("textDocument/publishDiagnostics", {{"uri", uri}, {"diagnostics", json::array()}}));
  }

  // -------------------------------------------------------------- queries

  struct Query {
    const Document* doc = nullptr;
    std::optional<Locator> locator;
    std::size_t offset = 0;
  };

  Query query(const json& params) {
    Query q;
    const Document& doc = open_document(params);
    q.doc = &doc;
    const Position at = position_from_json(member(params, "position"));
    q.offset = LineIndex(doc.text).offset_of(at, encoding);
    if (doc.analysis && doc.analysis->result.sources) q.locator.emplace(doc, *doc.analysis->result.sources, encoding, options.prelude_file);
    return q;
  }

  json hover_request(const json& params) {
    Query q = query(params);
    return q.locator ? hover(*q.doc->analysis, *q.locator, q.offset, hover_style) : json();
  }

  json definition_request(const json& params) {
    Query q = query(params);
    return q.locator ? definition(*q.doc->analysis, *q.locator, q.offset) : json();
  }

  json completion_request(const json& params) {
    Query q = query(params);
    const StageAnalysis* stage = q.doc->last_checked ? q.doc->last_checked->stage() : nullptr;
    return completion(q.doc->path, q.doc->text, q.offset, compile_options(), stage ? &stage->checked.registry : nullptr);
  }
};

Server::Server(ServerOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}
Server::~Server() = default;

std::vector<std::string> Server::handle(std::string_view body) {
  impl_->outgoing.clear();
  try {
    impl_->handle(body);
  } catch (const std::exception& e) {
    // A bug, never an expected path: report it and keep serving.
    impl_->log(1, std::string("internal error: ") + e.what());
  }
  return std::move(impl_->outgoing);
}

std::string Server::framing_error(std::string_view reason) {
  return serialize(error_response(nullptr, error_code::parse_error, "unreadable message: " + std::string(reason)));
}

bool Server::exited() const { return impl_->phase == Phase::exited; }
int Server::exit_code() const { return impl_->shutdown_received ? 0 : 1; }

std::string find_prelude_file(const std::string& executable) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path exe = fs::weakly_canonical(fs::path(executable), error);
  std::vector<fs::path> candidates = {exe.parent_path().parent_path() / "share/safegi/include/safegi/prelude.sgl"};
#ifdef SAFEGI_SOURCE_PRELUDE
  candidates.emplace_back(SAFEGI_SOURCE_PRELUDE);  // the build tree's: the file the build made from vocabulary.def
#endif
  for (const fs::path& candidate : candidates) {
    std::optional<std::string> text = read_file_from_disk(candidate.string());
    if (text && *text == prelude_text()) return candidate.string();
  }
  return {};
}

}  // namespace safegi::lsp
