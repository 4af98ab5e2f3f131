#pragma once
// Test helpers: the hand-written example shaders and symbol tables in testdata/.
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
