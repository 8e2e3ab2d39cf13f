// Reading input files with one-sentence errors (ARCHITECTURE §7): scene files, meshes, textures,
// viewer presets all come through here.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace ssr::files {

// Throws InputError with `msg` as one sentence: no control characters, one final full stop.
[[noreturn]] void fail(std::string msg);

// 'text' (built with append: GCC 12 warns wrongly about "'" + std::string at -O2, PR 105329).
std::string q(std::string_view s);
inline std::string q(const std::string& s) { return q(std::string_view(s)); }
inline std::string q(const std::filesystem::path& p) { return q(std::string_view(p.native())); }

// A fresh name beside `target` (its directory, so that a rename commits it) for a temporary file
// or directory: ".ssrlab-<pid>-<n>.tmp", short whatever the target's name, so a name near the
// file system's limit still gets a temporary.
std::filesystem::path temp_path_beside(const std::filesystem::path& target);

// The file that writing `file` replaces: `file`, or where a symbolic link there points (followed
// as a shell's `>` follows it), so that a temporary renamed over it replaces the target, not the
// link.
std::filesystem::path write_target(const std::filesystem::path& file);

// The path's extension in lower case (".PNG" and ".Png" -> ".png"), for checks of output formats.
std::string lower_extension(const std::filesystem::path& path);

// Reads a whole regular file of at most `cap` bytes. `what` names it ("OBJ file", ...);
// `context` prefixes the messages (e.g. "MTL file 'x' line 3: ").
std::string read_file(const std::filesystem::path& path, std::uintmax_t cap, const std::string& what,
                      const std::string& context = "");

// read_file for text (OBJ, MTL, JSON): without a leading UTF-8 byte-order mark, which editors on
// Windows write and which would otherwise become part of the first line's keyword.
std::string read_text_file(const std::filesystem::path& path, std::uintmax_t cap, const std::string& what,
                           const std::string& context = "");

}  // namespace ssr::files
