#include "render/image_io.h"

#include <cstdio>
#include <string>
#include <vector>

#include <stb_image_write.h>
#include <tinyexr.h>

#include "core/errors.h"
#include "core/files.h"

namespace ssr {

namespace fs = std::filesystem;

ImageFormat image_format_for(const fs::path& path) {
  const std::string ext = files::lower_extension(path);
  if (ext == ".png") return ImageFormat::Png;
  if (ext == ".exr") return ImageFormat::Exr;
  throw InputError("output '" + path.string() + "' must end in .png or .exr.");
}

namespace {
void commit(const fs::path& tmp, const fs::path& path) {
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw RuntimeError("cannot write '" + path.string() + "'.");
  }
}
}  // namespace

void write_file_atomic(const fs::path& file, const void* bytes, std::size_t size) {
  const fs::path path = files::write_target(file);
  const fs::path tmp = files::temp_path_beside(path);
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw RuntimeError("cannot write '" + path.string() + "' (directory missing or not writable).");
  const bool ok = std::fwrite(bytes, 1, size, f) == size;
  if (std::fclose(f) != 0 || !ok) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw RuntimeError("cannot write '" + path.string() + "' (disk full?).");
  }
  commit(tmp, path);
}

void write_png(const fs::path& path, const RgbaImage8& image) {
  std::vector<std::uint8_t> encoded;
  auto sink = [](void* ctx, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(ctx);
    const auto* p = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), p, p + size);
  };
  if (!stbi_write_png_to_func(sink, &encoded, image.width, image.height, 4, image.pixels.data(),
                              image.width * 4))
    throw RuntimeError("PNG encoding failed for '" + path.string() + "'.");
  write_file_atomic(path, encoded.data(), encoded.size());
}

void write_exr(const fs::path& file, const RgbaImageF& image) {
  const fs::path path = files::write_target(file);
  const fs::path tmp = files::temp_path_beside(path);
  const char* err = nullptr;
  const int rc = SaveEXR(image.pixels.data(), image.width, image.height, 4, /*fp16=*/1,
                         tmp.c_str(), &err);
  if (rc != TINYEXR_SUCCESS) {
    const std::string msg = err ? err : "unknown error";
    if (err) FreeEXRErrorMessage(err);
    std::error_code ec;
    fs::remove(tmp, ec);
    throw RuntimeError("cannot write EXR '" + path.string() + "': " + msg + ".");
  }
  commit(tmp, path);
}

}  // namespace ssr
