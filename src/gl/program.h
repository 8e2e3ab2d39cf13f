// Shader programs built from the files under shaders/.
//
// Sources come from the copy embedded in the binary at build time, or from a directory (the
// viewer's live reload). `#include "path"` lines are expanded recursively (paths relative to
// shaders/), each file once (`#pragma once` semantics), with `#line` directives so that compile
// errors are reported as file:line. Headers in shaders/shared/ are also compiled as C++.
#pragma once
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "gl/objects.h"

namespace ssr::gl {

class ShaderSource {
 public:
  // Embedded copy (default) or, with a directory, files read from disk on every load.
  explicit ShaderSource(std::optional<std::filesystem::path> dir = std::nullopt);
  // A `--shaders DIR` option's source: the embedded copy for "", else that directory; throws
  // InputError when it is not one (before any GL work: nothing half-done).
  static ShaderSource from_option(const std::string& dir);
  // A copy whose every program also gets `defines` (e.g. SSR_TELEMETRY: an instrumented build).
  ShaderSource with_defines(std::vector<std::string> defines) const;
  // The text of one file; throws RuntimeError when it does not exist.
  std::string read(const std::string& path) const;
  // Where a user finds the file `path` names: in the --shaders directory, or the checkout's
  // shaders/ folder that the embedded copy was made from (compile errors name it).
  std::string location(const std::string& path) const;
  // The expanded text of `path`, with `defines` ("NAME VALUE" or "NAME") inserted after #version.
  // `files` receives the file name of each GLSL source-string number used in #line.
  std::string expand(const std::string& path, const std::vector<std::string>& defines,
                     std::vector<std::string>& files) const;

 private:
  std::optional<std::filesystem::path> dir_;
  std::vector<std::string> defines_;  // added to every expand()
};

// Rewrites "0:12(5): error ..." / "0(12) : error ..." info-log lines to "file.glsl:12: error ...",
// the file named by files[source-string number].
std::string map_info_log(const std::string& log, const std::vector<std::string>& files);

// A linked program. Compile/link failures throw RuntimeError with the mapped info log.
class Program {
 public:
  Program() = default;
  static Program compute(const ShaderSource& src, const std::string& path,
                         const std::vector<std::string>& defines = {});
  static Program graphics(const ShaderSource& src, const std::string& vert,
                          const std::string& frag, const std::vector<std::string>& defines = {});
  GLuint id() const { return prog_.id(); }
  explicit operator bool() const { return bool(prog_); }
  // Dispatches enough work groups of this compute program's local size to cover w x h. A program
  // compiled with the define "SSR_ROWS N" (common/screen_rows.glsl) covers N pixel rows per
  // invocation, so it gets N times fewer groups.
  void dispatch_2d(int w, int h) const;

 private:
  ProgramObject prog_;
  int local_x_ = 1, local_y_ = 1;
  int rows_ = 1;
};

}  // namespace ssr::gl
