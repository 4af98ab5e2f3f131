#pragma once
// Typed GPU resources: a buffer of T bound to an attribute of T, a 2D texture
// of T (the paper's safeglCreateTexture2D<T>), and a framebuffer whose colour
// attachments are typed by the fragment outputs they receive. Each owns its GL
// object (RAII, move-only); the context must outlive them.
#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "safegi/symbol_table/error.hpp"
#include "safegi/runtime_gl/handles.hpp"
#include "safegi/symbol_table/value_traits.hpp"

namespace safegi::gl {

namespace detail {

enum class ObjectKind { buffer, vertex_array, texture, framebuffer, renderbuffer, program };
void delete_object(ObjectKind kind, unsigned name);

unsigned create_buffer(const void* data, std::size_t bytes);
unsigned create_vertex_array();
void bind_attribute(unsigned vertex_array, unsigned buffer, int location, ScalarType scalar, int components,
                    std::size_t stride);
void draw_triangles(unsigned vertex_array, int first, int count);
unsigned create_texture2d(int width, int height, ScalarType scalar, int components);
void upload_texture2d(unsigned texture, int width, int height, ScalarType scalar, int components, const void* data);
void read_texture2d(unsigned texture, int width, int height, ScalarType scalar, int components, void* data);
unsigned create_framebuffer();
void attach_color(unsigned framebuffer, int location, unsigned texture);
unsigned attach_depth(unsigned framebuffer, int width, int height);
void bind_framebuffer(unsigned framebuffer, const std::vector<int>& locations, int width, int height);
void bind_sampler(unsigned program, int location, unsigned texture, int unit);
void set_uniform(unsigned program, int location, ScalarType scalar, int components, int columns, int count,
                 const void* data);

// Owns one GL object name.
class Object {
 public:
  Object(ObjectKind kind, unsigned name) : kind_(kind), name_(name) {}
  ~Object() {
    if (name_) delete_object(kind_, name_);
  }
  Object(Object&& other) noexcept : kind_(other.kind_), name_(std::exchange(other.name_, 0)) {}
  Object& operator=(Object&& other) noexcept {
    if (this != &other) {
      if (name_) delete_object(kind_, name_);
      kind_ = other.kind_;
      name_ = std::exchange(other.name_, 0);
    }
    return *this;
  }
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;
  unsigned name() const { return name_; }

 private:
  ObjectKind kind_;
  unsigned name_;
};

}  // namespace detail

template <gl_storable T>
class vertex_buffer {
 public:
  explicit vertex_buffer(std::span<const T> values)
      : object_(detail::ObjectKind::buffer, detail::create_buffer(values.data(), values.size_bytes())),
        size_(values.size()) {}
  unsigned id() const { return object_.name(); }
  std::size_t size() const { return size_; }

 private:
  detail::Object object_;
  std::size_t size_;
};

class vertex_array {
 public:
  vertex_array() : object_(detail::ObjectKind::vertex_array, detail::create_vertex_array()) {}

  // Feeds attribute `attribute` from `buffer`, one T per vertex.
  template <gl_storable T>
  void bind(attribute_id<T> attribute, const vertex_buffer<T>& buffer) {
    static_assert(gl_layout_of<T>::columns == 1, "matrix attributes are not supported");
    detail::bind_attribute(object_.name(), buffer.id(), attribute.location, gl_layout_of<T>::scalar,
                           gl_layout_of<T>::components, sizeof(T));
  }
  void draw_triangles(int first, int count) const { detail::draw_triangles(object_.name(), first, count); }
  unsigned id() const { return object_.name(); }

 private:
  detail::Object object_;
};

template <gl_storable T>
class texture2d {
  static_assert(gl_layout_of<T>::columns == 1, "a texel is a scalar or a vector");

 public:
  texture2d(int width, int height)
      : object_(detail::ObjectKind::texture,
                detail::create_texture2d(width, height, gl_layout_of<T>::scalar, gl_layout_of<T>::components)),
        width_(width),
        height_(height) {}
  texture2d(int width, int height, std::span<const T> texels) : texture2d(width, height) { upload(texels); }

  // Replaces every texel, row by row from the bottom (GL order).
  void upload(std::span<const T> texels) {
    if (texels.size() != texel_count())
      throw ResourceError("safegi::gl: texture2d upload of " + std::to_string(texels.size()) + " texels into a " +
                          std::to_string(width_) + 'x' + std::to_string(height_) + " texture");
    detail::upload_texture2d(object_.name(), width_, height_, gl_layout_of<T>::scalar, gl_layout_of<T>::components,
                             texels.data());
  }
  std::vector<T> read_back() const {
    std::vector<T> texels(texel_count());
    detail::read_texture2d(object_.name(), width_, height_, gl_layout_of<T>::scalar, gl_layout_of<T>::components, texels.data());
    return texels;
  }

  unsigned id() const { return object_.name(); }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  std::size_t texel_count() const { return static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_); }

  detail::Object object_;
  int width_, height_;
};

// Colour attachments are typed by the fragment output they receive: attaching
// a texture2d<U> to an output_id<T> with U != T does not compile.
class framebuffer {
 public:
  framebuffer(int width, int height)
      : object_(detail::ObjectKind::framebuffer, detail::create_framebuffer()), width_(width), height_(height) {}

  template <gl_storable T>
  void attach(output_id<T> output, const texture2d<T>& texture) {
    if (texture.width() != width_ || texture.height() != height_)
      throw ResourceError("safegi::gl: a " + std::to_string(texture.width()) + 'x' +
                          std::to_string(texture.height()) + " texture attached to a " + std::to_string(width_) +
                          'x' + std::to_string(height_) + " framebuffer");
    if (output.location < 0) return;  // output optimized away: nothing to receive
    detail::attach_color(object_.name(), output.location, texture.id());
    locations_.push_back(output.location);
  }
  // Adds a depth buffer the size of the framebuffer.
  void add_depth() { depth_ = detail::Object(detail::ObjectKind::renderbuffer,
                                              detail::attach_depth(object_.name(), width_, height_)); }

  // Binds for drawing: draw buffers routed to the attached outputs, viewport
  // set to the whole framebuffer. Throws ResourceError when incomplete.
  void bind() const { detail::bind_framebuffer(object_.name(), locations_, width_, height_); }

  unsigned id() const { return object_.name(); }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  detail::Object object_;
  detail::Object depth_{detail::ObjectKind::renderbuffer, 0};
  std::vector<int> locations_;
  int width_, height_;
};

}  // namespace safegi::gl
