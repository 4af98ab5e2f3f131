#pragma once
// Every runtime_gl failure is an exception derived from safegi::gl::Error whose
// what() is the complete, user-facing message (file:line:col where known).
#include <stdexcept>
#include <string>

namespace safegi::gl {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// No OpenGL context could be created on the requested platform(s).
class ContextError : public Error {
 public:
  using Error::Error;
};

// A symbol table that is not valid JSON or does not follow docs/symbol-table.md.
class SymbolTableError : public Error {
 public:
  using Error::Error;
};

// The driver rejected a shader or the program link; lines are mapped back to
// the user's annotated sources.
class ShaderError : public Error {
 public:
  using Error::Error;
};

// A typed lookup failed: the name is missing, or the host type does not match
// the shader's declaration.
class BindingError : public Error {
 public:
  using Error::Error;
};

// A GL resource could not be created or used (incomplete framebuffer, size
// mismatch on upload, ...).
class ResourceError : public Error {
 public:
  using Error::Error;
};

}  // namespace safegi::gl
