// Shared by the libFuzzer targets. The loaders read from disk (paths, "stays inside the
// directory" checks and caches are part of what is fuzzed), so one input is split into files
// written to a scratch directory on tmpfs, one per process (workers of -fork/-jobs each get
// their own).
#pragma once
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "scene/scene.h"

namespace fuzz {

namespace fs = std::filesystem;

// Separates the files inside one input (in the dictionaries too).
constexpr std::string_view kSeparator = "\n@@@@\n";

// Splits `data` at kSeparator into exactly `n` parts: missing ones are empty, the last one keeps
// any further separators.
inline std::vector<std::string_view> split(std::string_view data, std::size_t n) {
  std::vector<std::string_view> parts;
  while (parts.size() + 1 < n) {
    const std::size_t at = data.find(kSeparator);
    if (at == std::string_view::npos) break;
    parts.push_back(data.substr(0, at));
    data.remove_prefix(at + kSeparator.size());
  }
  parts.push_back(data);
  parts.resize(n);
  return parts;
}

inline void write_file(const fs::path& p, std::string_view bytes) {
  std::FILE* f = std::fopen(p.c_str(), "wb");
  if (!f || std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size() || std::fclose(f)) {
    std::perror(p.c_str());
    std::abort();  // the harness itself failed: not a finding in the loaders
  }
}

// /dev/shm/ssrlab-fuzz-<pid>/ with fixed extra files the inputs may name: tex.png (valid),
// textures/tex.png, corrupt.png (not an image), dir/ (a directory), up -> .. (a symlink
// leading out). Removed at exit.
inline const fs::path& scratch_dir() {
  static const fs::path dir = [] {
    const fs::path base = fs::is_directory("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
    fs::path d = base / ("ssrlab-fuzz-" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d / "textures");
    fs::create_directories(d / "dir");
    const fs::path data = SSRLAB_FUZZ_DATA;  // tests/data
    fs::copy_file(data / "obj/textures/tex.png", d / "tex.png");
    fs::copy_file(data / "obj/textures/tex.png", d / "textures/tex.png");
    fs::copy_file(data / "obj/textures/corrupt.png", d / "corrupt.png");
    fs::create_directory_symlink("..", d / "up");
    static const fs::path to_remove = d;
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(to_remove, ec);
    });
    return d;
  }();
  return dir;
}

// A scene a loader accepted must pass validate(): a failure here is a finding, not a rejection.
inline void require_valid(const ssr::Scene& s) {
  try {
    ssr::validate(s);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "loaded scene fails validate(): %s\n", e.what());
    std::abort();
  }
}

}  // namespace fuzz
