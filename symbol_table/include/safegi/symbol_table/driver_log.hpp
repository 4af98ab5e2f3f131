#pragma once
// Maps a GL driver's shader info log back to the annotated sources. The elider
// keeps lines aligned (or emits `#line N S`, S indexing the stage's
// source_files), so the driver's "string:line" is the user's "file:line".
// Understood formats: Mesa "0:12(5): error: ...", NVIDIA "0(12) : error C1008:
// ...", AMD/Intel "ERROR: 0:12: ...". Other lines are kept, prefixed by the file.
#include <string>
#include <string_view>

#include "safegi/symbol_table/symbol_table.hpp"

namespace safegi::gl {

// One line per message: "file:line[:col]: error|warning: text".
std::string map_driver_log(std::string_view log, const StageSymbols& stage);

}  // namespace safegi::gl
