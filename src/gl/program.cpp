#include "gl/program.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string_view>

#include "core/errors.h"

namespace ssr {
const std::map<std::string, std::string_view>& embedded_shaders();  // generated at build time
}

namespace ssr::gl {

ShaderSource::ShaderSource(std::optional<std::filesystem::path> dir) : dir_(std::move(dir)) {}

ShaderSource ShaderSource::from_option(const std::string& dir) {
  if (dir.empty()) return ShaderSource();
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(dir, ec)) throw InputError("shader directory '" + dir + "' does not exist.");
  if (!fs::is_directory(dir, ec)) throw InputError("'" + dir + "' given to --shaders is not a directory.");
  // Checked here, before any GL work: every program starts from the G-buffer pass.
  if (!fs::is_regular_file(fs::path(dir) / "render/gbuffer.vert", ec))
    throw InputError("shader directory '" + dir + "' holds no render/gbuffer.vert (name a checkout's shaders/ folder).");
  return ShaderSource(fs::path(dir));
}

ShaderSource ShaderSource::with_defines(std::vector<std::string> defines) const {
  ShaderSource out = *this;
  out.defines_.insert(out.defines_.end(), defines.begin(), defines.end());
  return out;
}

std::string ShaderSource::read(const std::string& path) const {
  if (dir_) {
    // Shader names are relative to the directory and stay inside it, as the embedded copy's do.
    const std::filesystem::path rel = std::filesystem::path(path).lexically_normal();
    if (rel.is_absolute() || rel.empty() || *rel.begin() == "..")
      throw InputError("shader file '" + path + "' is outside the --shaders directory.");
    std::error_code ec;
    if (std::filesystem::exists(*dir_ / rel, ec) && !std::filesystem::is_regular_file(*dir_ / rel, ec))
      throw InputError("shader file '" + (*dir_ / rel).string() + "' is not a regular file.");
    std::ifstream in(*dir_ / rel, std::ios::binary);
    if (!in) throw InputError("shader file '" + (*dir_ / rel).string() + "' does not exist (the --shaders directory lacks it).");
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  const auto& table = embedded_shaders();
  auto it = table.find(path);
  if (it == table.end()) throw RuntimeError("shader '" + path + "' is not embedded in the binary.");
  return std::string(it->second);
}

namespace {

void expand_into(const ShaderSource& src, const std::string& path, std::ostringstream& out,
                 std::vector<std::string>& files, std::set<std::string>& seen, int depth) {
  if (depth > 32) throw RuntimeError("shader include depth exceeded at '" + path + "'.");
  if (!seen.insert(path).second) return;  // every file once
  const int file_no = static_cast<int>(files.size());
  files.push_back(path);
  std::istringstream in(src.read(path));
  static const std::regex include_re(R"re(^\s*#\s*include\s+"([^"]+)"\s*$)re");
  static const std::regex skip_re(R"re(^\s*#\s*(pragma\s+once|version\b).*$)re");
  std::string line;
  int line_no = 0;
  out << "#line 1 " << file_no << "\n";
  while (std::getline(in, line)) {
    ++line_no;
    std::smatch m;
    if (std::regex_match(line, m, include_re)) {
      expand_into(src, m[1].str(), out, files, seen, depth + 1);
      out << "#line " << line_no + 1 << " " << file_no << "\n";
    } else if (std::regex_match(line, skip_re)) {
      out << "\n";  // keep line numbers
    } else {
      out << line << "\n";
    }
  }
}

}  // namespace

std::string ShaderSource::location(const std::string& path) const {
  return dir_ ? (*dir_ / path).string() : "shaders/" + path;
}

std::string ShaderSource::expand(const std::string& path, const std::vector<std::string>& defines,
                                 std::vector<std::string>& files) const {
  std::ostringstream out;
  out << "#version 450 core\n";
  for (const std::string& d : defines_) out << "#define " << d << "\n";
  for (const std::string& d : defines) out << "#define " << d << "\n";
  std::set<std::string> seen;
  files.clear();
  expand_into(*this, path, out, files, seen, 0);
  return out.str();
}

std::string map_info_log(const std::string& log, const std::vector<std::string>& files) {
  // Mesa: "0:12(5): error: ..."; NVIDIA: "0(12) : error C0000: ...".
  static const std::regex mesa(R"re(^(\d+):(\d+)\((\d+)\):\s*(.*)$)re");
  static const std::regex nvidia(R"re(^(\d+)\((\d+)\)\s*:\s*(.*)$)re");
  std::istringstream in(log);
  std::ostringstream out;
  std::string line;
  auto name = [&](const std::string& no) {
    const std::size_t i = std::stoul(no);
    return i < files.size() ? files[i] : "source " + no;
  };
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, mesa))
      out << name(m[1]) << ":" << m[2] << ":" << m[3] << ": " << m[4] << "\n";
    else if (std::regex_match(line, m, nvidia))
      out << name(m[1]) << ":" << m[2] << ": " << m[3] << "\n";
    else if (!line.empty())
      out << line << "\n";
  }
  return out.str();
}

namespace {

ShaderObject compile(const ShaderSource& src, GLenum stage, const std::string& path,
                     const std::vector<std::string>& defines) {
  std::vector<std::string> files;
  const std::string text = src.expand(path, defines, files);
  ShaderObject sh(path, stage);
  const char* ptr = text.c_str();
  glShaderSource(sh.id(), 1, &ptr, nullptr);
  glCompileShader(sh.id());
  GLint ok = 0;
  glGetShaderiv(sh.id(), GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetShaderiv(sh.id(), GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<std::size_t>(std::max(len, 1)), '\0');
    glGetShaderInfoLog(sh.id(), len, nullptr, log.data());
    for (std::string& f : files) f = src.location(f);
    throw RuntimeError("shader compile failed: " + src.location(path) + "\n" + map_info_log(log.c_str(), files));
  }
  return sh;
}

// With $SSRLAB_PROGRAM_BINARIES naming a directory, each linked program's driver binary is
// written there as <path>-<n>.bin (n counts links: defines make variants of one path). NVIDIA's
// holds its assembly as text (`strings`): the way to see why two shaders that do the same work
// differ in time (RESULTS.md, linear-binary's slowdown). Diagnostics only: failures are silent.
void dump_binary(GLuint prog, const std::string& what) {
  const char* dir = std::getenv("SSRLAB_PROGRAM_BINARIES");
  if (!dir || !*dir) return;
  static int count = 0;
  GLint len = 0;
  glGetProgramiv(prog, GL_PROGRAM_BINARY_LENGTH, &len);
  if (len <= 0) return;
  std::vector<char> data(static_cast<std::size_t>(len));
  GLenum format = 0;
  glGetProgramBinary(prog, len, nullptr, &format, data.data());
  std::string name = what;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-') c = '_';
  std::ofstream(std::string(dir) + "/" + name + "-" + std::to_string(count++) + ".bin", std::ios::binary)
      .write(data.data(), static_cast<std::streamsize>(data.size()));
}

void link(GLuint prog, const std::string& what) {
  glLinkProgram(prog);
  GLint ok = 0;
  glGetProgramiv(prog, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(prog, GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<std::size_t>(std::max(len, 1)), '\0');
    glGetProgramInfoLog(prog, len, nullptr, log.data());
    throw RuntimeError("program link failed: " + what + "\n" + log.c_str());
  }
  dump_binary(prog, what);
}

}  // namespace

Program Program::compute(const ShaderSource& src, const std::string& path,
                         const std::vector<std::string>& defines) {
  ShaderObject cs = compile(src, GL_COMPUTE_SHADER, path, defines);
  Program p;
  p.prog_ = ProgramObject(path);
  glAttachShader(p.prog_.id(), cs.id());
  link(p.prog_.id(), path);
  glDetachShader(p.prog_.id(), cs.id());
  GLint size[3] = {1, 1, 1};
  glGetProgramiv(p.prog_.id(), GL_COMPUTE_WORK_GROUP_SIZE, size);
  p.local_x_ = size[0];
  p.local_y_ = size[1];
  for (const std::string& d : defines)
    if (d.rfind("SSR_ROWS ", 0) == 0) p.rows_ = std::max(1, std::stoi(d.substr(9)));
  return p;
}

Program Program::graphics(const ShaderSource& src, const std::string& vert,
                          const std::string& frag, const std::vector<std::string>& defines) {
  ShaderObject vs = compile(src, GL_VERTEX_SHADER, vert, defines);
  ShaderObject fs = compile(src, GL_FRAGMENT_SHADER, frag, defines);
  Program p;
  p.prog_ = ProgramObject(vert + "+" + frag);
  glAttachShader(p.prog_.id(), vs.id());
  glAttachShader(p.prog_.id(), fs.id());
  link(p.prog_.id(), vert + " + " + frag);
  glDetachShader(p.prog_.id(), vs.id());
  glDetachShader(p.prog_.id(), fs.id());
  return p;
}

void Program::dispatch_2d(int w, int h) const {
  glUseProgram(prog_.id());
  glDispatchCompute(static_cast<GLuint>((w + local_x_ - 1) / local_x_),
                    static_cast<GLuint>((h + local_y_ * rows_ - 1) / (local_y_ * rows_)), 1);
}

}  // namespace ssr::gl
