// The GL side of the typed resources: each function is the handful of raw
// calls one typed operation stands for. Creating or editing a resource must not
// disturb what is bound for drawing (a texture on a sampler's unit, the draw
// framebuffer), so GL 4.5's direct state access is used where present; on a
// 3.3 context the edit binds and then restores the previous binding.
#include <glad/gl.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

#include "safegi/runtime_gl/resources.hpp"

namespace safegi::gl::detail {
namespace {

GLenum gl_scalar(ScalarType scalar) {
  switch (scalar) {
    case ScalarType::float32: return GL_FLOAT;
    case ScalarType::int32: return GL_INT;
    case ScalarType::uint32: return GL_UNSIGNED_INT;
  }
  return GL_FLOAT;
}

// Transfer format of `components` channels. Integer textures need the
// *_INTEGER formats.
GLenum pixel_format(ScalarType scalar, int components) {
  const bool integer = scalar != ScalarType::float32;
  switch (components) {
    case 1: return integer ? GL_RED_INTEGER : GL_RED;
    case 2: return integer ? GL_RG_INTEGER : GL_RG;
    case 3: return integer ? GL_RGB_INTEGER : GL_RGB;
    default: return integer ? GL_RGBA_INTEGER : GL_RGBA;
  }
}

// Three-channel texels are stored as four: RGB32F is not required to be
// colour-renderable, and a texture2d must be a valid framebuffer attachment.
GLenum internal_format(ScalarType scalar, int components) {
  static constexpr GLenum formats[3][4] = {
      {GL_R32F, GL_RG32F, GL_RGBA32F, GL_RGBA32F},
      {GL_R32I, GL_RG32I, GL_RGBA32I, GL_RGBA32I},
      {GL_R32UI, GL_RG32UI, GL_RGBA32UI, GL_RGBA32UI},
  };
  return formats[static_cast<int>(scalar)][components - 1];
}

// Binds a texture (GL_TEXTURE_2D of the active unit) or a draw framebuffer for
// one edit on a context without direct state access, restoring the previous
// binding after.
class ScopedEdit {
 public:
  enum Target { texture2d, draw_framebuffer };
  ScopedEdit(Target target, GLuint name) : target_(target) {
    glGetIntegerv(target == texture2d ? GL_TEXTURE_BINDING_2D : GL_DRAW_FRAMEBUFFER_BINDING, &previous_);
    bind(name);
  }
  ~ScopedEdit() { bind(static_cast<GLuint>(previous_)); }
  ScopedEdit(const ScopedEdit&) = delete;
  ScopedEdit& operator=(const ScopedEdit&) = delete;

 private:
  void bind(GLuint name) const {
    if (target_ == texture2d) glBindTexture(GL_TEXTURE_2D, name);
    else glBindFramebuffer(GL_DRAW_FRAMEBUFFER, name);
  }
  Target target_;
  GLint previous_ = 0;
};

bool direct_state_access() { return GLAD_GL_VERSION_4_5 != 0; }

std::string framebuffer_status_name(GLenum status) {
  switch (status) {
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT (nothing attached)";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    default: {
      char hex[16];
      std::snprintf(hex, sizeof hex, "status 0x%04X", status);
      return hex;
    }
  }
}

}  // namespace

void delete_object(ObjectKind kind, unsigned name) {
  switch (kind) {
    case ObjectKind::buffer: glDeleteBuffers(1, &name); break;
    case ObjectKind::vertex_array: glDeleteVertexArrays(1, &name); break;
    case ObjectKind::texture: glDeleteTextures(1, &name); break;
    case ObjectKind::framebuffer: glDeleteFramebuffers(1, &name); break;
    case ObjectKind::renderbuffer: glDeleteRenderbuffers(1, &name); break;
    case ObjectKind::program: glDeleteProgram(name); break;
  }
}

unsigned create_buffer(const void* data, std::size_t bytes) {
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
  return buffer;
}

unsigned create_vertex_array() {
  GLuint vertex_array = 0;
  glGenVertexArrays(1, &vertex_array);
  return vertex_array;
}

void bind_attribute(unsigned vertex_array, unsigned buffer, int location, ScalarType scalar, int components,
                    std::size_t stride) {
  if (location < 0) return;
  glBindVertexArray(vertex_array);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  const auto index = static_cast<GLuint>(location);
  glEnableVertexAttribArray(index);
  if (scalar == ScalarType::float32)
    glVertexAttribPointer(index, components, GL_FLOAT, GL_FALSE, static_cast<GLsizei>(stride), nullptr);
  else
    glVertexAttribIPointer(index, components, gl_scalar(scalar), static_cast<GLsizei>(stride), nullptr);
}

void draw_triangles(unsigned vertex_array, int first, int count) {
  glBindVertexArray(vertex_array);
  glDrawArrays(GL_TRIANGLES, first, count);
}

unsigned create_texture2d(int width, int height, ScalarType scalar, int components) {
  const GLenum format = internal_format(scalar, components);
  GLuint texture = 0;
  // Exact texel values: no filtering between texels, no mipmaps.
  const std::pair<GLenum, GLint> parameters[] = {{GL_TEXTURE_MIN_FILTER, GL_NEAREST},
                                                 {GL_TEXTURE_MAG_FILTER, GL_NEAREST},
                                                 {GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE},
                                                 {GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE}};
  if (direct_state_access()) {
    glCreateTextures(GL_TEXTURE_2D, 1, &texture);
    glTextureStorage2D(texture, 1, format, width, height);
    for (const auto& [name, value] : parameters) glTextureParameteri(texture, name, value);
    return texture;
  }
  glGenTextures(1, &texture);
  ScopedEdit edit(ScopedEdit::texture2d, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(format), width, height, 0, pixel_format(scalar, components),
               gl_scalar(scalar), nullptr);
  for (const auto& [name, value] : parameters) glTexParameteri(GL_TEXTURE_2D, name, value);
  return texture;
}

void upload_texture2d(unsigned texture, int width, int height, ScalarType scalar, int components, const void* data) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  if (direct_state_access()) {
    glTextureSubImage2D(texture, 0, 0, 0, width, height, pixel_format(scalar, components), gl_scalar(scalar), data);
    return;
  }
  ScopedEdit edit(ScopedEdit::texture2d, texture);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, pixel_format(scalar, components), gl_scalar(scalar), data);
}

void read_texture2d(unsigned texture, int width, int height, ScalarType scalar, int components, void* data) {
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  if (direct_state_access()) {
    const auto bytes = static_cast<GLsizei>(width * height * components * 4);
    glGetTextureImage(texture, 0, pixel_format(scalar, components), gl_scalar(scalar), bytes, data);
    return;
  }
  ScopedEdit edit(ScopedEdit::texture2d, texture);
  glGetTexImage(GL_TEXTURE_2D, 0, pixel_format(scalar, components), gl_scalar(scalar), data);
}

unsigned create_framebuffer() {
  GLuint framebuffer = 0;
  if (direct_state_access()) glCreateFramebuffers(1, &framebuffer);
  else glGenFramebuffers(1, &framebuffer);
  return framebuffer;
}

void attach_color(unsigned framebuffer, int location, unsigned texture) {
  const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(location);
  if (direct_state_access()) {
    glNamedFramebufferTexture(framebuffer, attachment, texture, 0);
    return;
  }
  ScopedEdit edit(ScopedEdit::draw_framebuffer, framebuffer);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture, 0);
}

unsigned attach_depth(unsigned framebuffer, int width, int height) {
  GLuint depth = 0;
  if (direct_state_access()) {
    glCreateRenderbuffers(1, &depth);
    glNamedRenderbufferStorage(depth, GL_DEPTH_COMPONENT24, width, height);
    glNamedFramebufferRenderbuffer(framebuffer, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    return depth;
  }
  glGenRenderbuffers(1, &depth);
  glBindRenderbuffer(GL_RENDERBUFFER, depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  ScopedEdit edit(ScopedEdit::draw_framebuffer, framebuffer);
  glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  return depth;
}

void bind_framebuffer(unsigned framebuffer, const std::vector<int>& locations, int width, int height) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  GLenum buffers[8];
  GLsizei count = 0;
  for (int location : locations) {
    if (location >= 8) continue;
    while (count < location) buffers[count++] = GL_NONE;
    buffers[location] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(location);
    count = std::max<GLsizei>(count, location + 1);
  }
  glDrawBuffers(count, buffers);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw ResourceError("safegi::gl: framebuffer incomplete: " + framebuffer_status_name(status));
  glViewport(0, 0, width, height);
}

void bind_sampler(unsigned program, int location, unsigned texture, int unit) {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(GL_TEXTURE_2D, texture);
  if (location < 0) return;
  if (GLAD_GL_VERSION_4_1) {
    glProgramUniform1i(program, location, unit);
  } else {
    glUseProgram(program);
    glUniform1i(location, unit);
  }
}

void set_uniform(unsigned program, int location, ScalarType scalar, int components, int columns, int count,
                 const void* data) {
  if (location < 0) return;
  // GL 4.1's direct-state uniforms when present, otherwise bind and set.
  const bool direct = GLAD_GL_VERSION_4_1 != 0;
  if (!direct) glUseProgram(program);
  const auto* f = static_cast<const GLfloat*>(data);
  const auto* i = static_cast<const GLint*>(data);
  const auto* u = static_cast<const GLuint*>(data);
  if (columns > 1) {
    using MatrixSetter = void (*)(GLuint, GLint, GLsizei, GLboolean, const GLfloat*);
    using MatrixUniform = void (*)(GLint, GLsizei, GLboolean, const GLfloat*);
    static const MatrixSetter* direct_setters[3][3] = {
        {&glProgramUniformMatrix2fv, &glProgramUniformMatrix2x3fv, &glProgramUniformMatrix2x4fv},
        {&glProgramUniformMatrix3x2fv, &glProgramUniformMatrix3fv, &glProgramUniformMatrix3x4fv},
        {&glProgramUniformMatrix4x2fv, &glProgramUniformMatrix4x3fv, &glProgramUniformMatrix4fv}};
    static const MatrixUniform* bound_setters[3][3] = {
        {&glUniformMatrix2fv, &glUniformMatrix2x3fv, &glUniformMatrix2x4fv},
        {&glUniformMatrix3x2fv, &glUniformMatrix3fv, &glUniformMatrix3x4fv},
        {&glUniformMatrix4x2fv, &glUniformMatrix4x3fv, &glUniformMatrix4fv}};
    if (direct) (*direct_setters[columns - 2][components - 2])(program, location, count, GL_FALSE, f);
    else (*bound_setters[columns - 2][components - 2])(location, count, GL_FALSE, f);
    return;
  }
  switch (scalar) {
    case ScalarType::float32: {
      static const PFNGLPROGRAMUNIFORM1FVPROC* direct_setters[4] = {
          &glProgramUniform1fv, &glProgramUniform2fv, &glProgramUniform3fv, &glProgramUniform4fv};
      static const PFNGLUNIFORM1FVPROC* bound_setters[4] = {&glUniform1fv, &glUniform2fv,
                                                            &glUniform3fv, &glUniform4fv};
      if (direct) (*direct_setters[components - 1])(program, location, count, f);
      else (*bound_setters[components - 1])(location, count, f);
      break;
    }
    case ScalarType::int32: {
      static const PFNGLPROGRAMUNIFORM1IVPROC* direct_setters[4] = {
          &glProgramUniform1iv, &glProgramUniform2iv, &glProgramUniform3iv, &glProgramUniform4iv};
      static const PFNGLUNIFORM1IVPROC* bound_setters[4] = {&glUniform1iv, &glUniform2iv,
                                                            &glUniform3iv, &glUniform4iv};
      if (direct) (*direct_setters[components - 1])(program, location, count, i);
      else (*bound_setters[components - 1])(location, count, i);
      break;
    }
    case ScalarType::uint32: {
      static const PFNGLPROGRAMUNIFORM1UIVPROC* direct_setters[4] = {
          &glProgramUniform1uiv, &glProgramUniform2uiv, &glProgramUniform3uiv,
          &glProgramUniform4uiv};
      static const PFNGLUNIFORM1UIVPROC* bound_setters[4] = {&glUniform1uiv, &glUniform2uiv,
                                                             &glUniform3uiv, &glUniform4uiv};
      if (direct) (*direct_setters[components - 1])(program, location, count, u);
      else (*bound_setters[components - 1])(location, count, u);
      break;
    }
  }
}

}  // namespace safegi::gl::detail
