#include "gl/objects.h"

#include <algorithm>
#include <bit>

namespace ssr::gl {

Texture2D::Texture2D(std::string_view label, GLenum internal_format, int width, int height,
                     int levels)
    : tex_(label, GL_TEXTURE_2D), width_(width), height_(height), format_(internal_format) {
  if (levels <= 0)
    levels = 1 + static_cast<int>(std::bit_width(static_cast<unsigned>(std::max(width, height)))) - 1;
  levels_ = levels;
  glTextureStorage2D(tex_.id(), levels, internal_format, width, height);
  // Integer formats cannot be filtered; nearest everywhere is the safe default, passes that
  // want bilinear sampling use a sampler or set it explicitly.
  glTextureParameteri(tex_.id(), GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST);
  glTextureParameteri(tex_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(tex_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(tex_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

Buffer make_buffer(std::string_view label, GLsizeiptr size, const void* data, GLbitfield flags) {
  Buffer b(label);
  glNamedBufferStorage(b.id(), size > 0 ? size : 16, size > 0 ? data : nullptr, flags);
  return b;
}

}  // namespace ssr::gl
