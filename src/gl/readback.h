// Reading textures back to the CPU: the one place that knows GL's row order (row 0 at the
// bottom) and the pack alignment. Images in the rest of the code (core/image.h, PNG, metrics)
// keep row 0 at the top.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "gl/objects.h"

namespace ssr::gl {

enum class Rows { TopFirst, GlOrder };

// Swaps rows end for end: GL's bottom-first order <-> top-first (the same operation both ways).
template <class T>
void flip_rows(std::vector<T>& px, int width, int height, int channels) {
  const std::size_t row = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(px.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y)),
                     px.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y + 1)),
                     px.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(height - 1 - y)));
}

// Level 0 of `tex`, `channels` values of T a pixel in `format`/`type` as glGetTextureImage takes
// them (GL_RGBA + GL_FLOAT, GL_RGBA_INTEGER + GL_UNSIGNED_SHORT, GL_DEPTH_COMPONENT + GL_FLOAT...).
template <class T>
std::vector<T> read_texture(const Texture2D& tex, GLenum format, GLenum type, int channels,
                            Rows rows = Rows::TopFirst) {
  std::vector<T> px(static_cast<std::size_t>(tex.width()) * static_cast<std::size_t>(tex.height()) *
                    static_cast<std::size_t>(channels));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);  // rows packed tightly, whatever the width
  glGetTextureImage(tex.id(), 0, format, type, static_cast<GLsizei>(px.size() * sizeof(T)), px.data());
  if (rows == Rows::TopFirst) flip_rows(px, tex.width(), tex.height(), channels);
  return px;
}

// One pixel of level 0: (x, y) with row 0 at the top, as read-back images have it; N values.
template <class T, int N>
std::array<T, N> read_texel(const Texture2D& tex, int x, int y, GLenum format, GLenum type) {
  std::array<T, N> v{};
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureSubImage(tex.id(), 0, x, tex.height() - 1 - y, 0, 1, 1, 1, format, type, static_cast<GLsizei>(sizeof v),
                       v.data());
  return v;
}

}  // namespace ssr::gl
