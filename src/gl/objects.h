// Move-only RAII owners for GL objects. Each is created with DSA (glCreate*) and labelled
// (glObjectLabel) so debuggers and KHR_debug messages name it.
#pragma once
#include <string_view>
#include <utility>

#include "gl/gl.h"

namespace ssr::gl {

// One owner template for every object kind; `Traits` knows how to create and delete one.
template <class Traits>
class Object {
 public:
  Object() = default;
  explicit Object(std::string_view label, GLenum arg = 0) : id_(Traits::create(arg)) {
    if (!label.empty())
      glObjectLabel(Traits::kLabelKind, id_, static_cast<GLsizei>(label.size()), label.data());
  }
  ~Object() { reset(); }
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;
  Object(Object&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Object& operator=(Object&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  void reset() {
    if (id_) Traits::destroy(id_);
    id_ = 0;
  }
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }

 private:
  GLuint id_ = 0;
};

struct TextureTraits {
  static constexpr GLenum kLabelKind = GL_TEXTURE;
  static GLuint create(GLenum target) { GLuint id; glCreateTextures(target, 1, &id); return id; }
  static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct BufferTraits {
  static constexpr GLenum kLabelKind = GL_BUFFER;
  static GLuint create(GLenum) { GLuint id; glCreateBuffers(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct FramebufferTraits {
  static constexpr GLenum kLabelKind = GL_FRAMEBUFFER;
  static GLuint create(GLenum) { GLuint id; glCreateFramebuffers(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct VertexArrayTraits {
  static constexpr GLenum kLabelKind = GL_VERTEX_ARRAY;
  static GLuint create(GLenum) { GLuint id; glCreateVertexArrays(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct QueryTraits {
  static constexpr GLenum kLabelKind = GL_QUERY;
  static GLuint create(GLenum target) { GLuint id; glCreateQueries(target, 1, &id); return id; }
  static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};
struct SamplerTraits {
  static constexpr GLenum kLabelKind = GL_SAMPLER;
  static GLuint create(GLenum) { GLuint id; glCreateSamplers(1, &id); return id; }
  static void destroy(GLuint id) { glDeleteSamplers(1, &id); }
};
struct ProgramTraits {
  static constexpr GLenum kLabelKind = GL_PROGRAM;
  static GLuint create(GLenum) { return glCreateProgram(); }
  static void destroy(GLuint id) { glDeleteProgram(id); }
};
struct ShaderTraits {
  static constexpr GLenum kLabelKind = GL_SHADER;
  static GLuint create(GLenum stage) { return glCreateShader(stage); }
  static void destroy(GLuint id) { glDeleteShader(id); }
};

using Buffer = Object<BufferTraits>;
using Framebuffer = Object<FramebufferTraits>;
using VertexArray = Object<VertexArrayTraits>;
using Query = Object<QueryTraits>;
using Sampler = Object<SamplerTraits>;
using ProgramObject = Object<ProgramTraits>;
using ShaderObject = Object<ShaderTraits>;

// A 2D texture that remembers its size and format.
class Texture2D {
 public:
  Texture2D() = default;
  // `levels` = 0 means a full mip chain.
  Texture2D(std::string_view label, GLenum internal_format, int width, int height, int levels = 1);
  GLuint id() const { return tex_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }
  int levels() const { return levels_; }
  GLenum format() const { return format_; }
  explicit operator bool() const { return bool(tex_); }

 private:
  Object<TextureTraits> tex_;
  int width_ = 0, height_ = 0, levels_ = 0;
  GLenum format_ = 0;
};

// A buffer with immutable storage of a given size (glNamedBufferStorage).
Buffer make_buffer(std::string_view label, GLsizeiptr size, const void* data = nullptr,
                   GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);

}  // namespace ssr::gl
