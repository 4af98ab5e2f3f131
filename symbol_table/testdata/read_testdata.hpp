#pragma once
// The symbol-table contract's example program, for the tests of symbol_table/ and runtime_gl/
// (annotated sources and what safeglslc writes for them; the golden test
// golden.symbol_table_fixture_is_compiler_output keeps them equal).
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace safegi::gl::testing {

inline std::string read_testdata(const std::string& name) {
  std::ifstream file(std::string(SAFEGI_SYMBOL_TABLE_TESTDATA) + '/' + name);
  if (!file) throw std::runtime_error("cannot open symbol_table/testdata/" + name);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace safegi::gl::testing
