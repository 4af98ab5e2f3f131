#pragma once
// Test helpers: the example program in testdata/ (annotated sources and what
// safeglslc writes for them; the golden test golden.runtime_gl_fixture_is_compiler_output keeps them equal).
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace safegi::gl::testing {

inline std::string read_testdata(const std::string& name) {
  std::ifstream file(std::string(SAFEGI_RUNTIME_GL_TESTDATA) + '/' + name);
  if (!file) throw std::runtime_error("cannot open testdata/" + name);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace safegi::gl::testing
