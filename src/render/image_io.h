// Writing images. Every writer is atomic: it writes a temporary file beside the target and
// renames it, so a failure never leaves a partial file behind.
#pragma once
#include <filesystem>

#include "render/renderer.h"

namespace ssr {

// Which format a path asks for: ".png" or ".exr"; throws InputError for anything else.
enum class ImageFormat { Png, Exr };
ImageFormat image_format_for(const std::filesystem::path& path);

void write_png(const std::filesystem::path& path, const RgbaImage8& image);
void write_exr(const std::filesystem::path& path, const RgbaImageF& image);  // half float RGBA

// Writes `bytes` to `path` through a temporary file + rename. Throws RuntimeError on failure.
void write_file_atomic(const std::filesystem::path& path, const void* bytes, std::size_t size);

}  // namespace ssr
