#include "core/cli_common.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <map>
#include <regex>

#include "core/errors.h"
#include "core/files.h"

namespace ssr {

std::pair<int, int> parse_size(const std::string& text) {
  static const std::regex re(R"(^(\d{1,6})x(\d{1,6})$)");
  std::smatch m;
  if (!std::regex_match(text, m, re))
    throw InputError("size '" + text + "' is not of the form WIDTHxHEIGHT (e.g. 1280x720).");
  const int w = std::stoi(m[1]), h = std::stoi(m[2]);
  if (w < 1 || h < 1) throw InputError("size '" + text + "' must be at least 1x1.");
  if (static_cast<long long>(w) * h > kMaxFramePixels)
    throw InputError("size '" + text + "' has " + std::to_string(static_cast<long long>(w) * h) +
                     " pixels, more than the " + std::to_string(kMaxFramePixels) +
                     " (8192x8192) supported.");
  return {w, h};
}

std::pair<int, int> parse_named_size(const std::string& text) {
  static const std::map<std::string, std::pair<int, int>> named = {
      {"720p", {1280, 720}}, {"1080p", {1920, 1080}}, {"1440p", {2560, 1440}},
      {"4k", {3840, 2160}}, {"2160p", {3840, 2160}}, {"8k", {7680, 4320}}, {"4320p", {7680, 4320}}};
  const auto it = named.find(text);
  return it != named.end() ? it->second : parse_size(text);
}

void require_creatable(const std::string& option, const std::string& path, const std::filesystem::path& dir) {
  const std::filesystem::path probe = files::temp_path_beside(dir / "x");
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0)
    throw InputError("cannot create " + option + " '" + path + "' in its directory (" + std::strerror(errno) + ").");
  ::close(fd);
  ::unlink(probe.c_str());
}

void require_output_files(const std::vector<std::pair<std::string, std::string>>& option_and_path,
                          const std::vector<std::string>& inputs) {
  namespace fs = std::filesystem;
  std::vector<std::pair<std::string, fs::path>> seen;
  for (const auto& [option, file] : option_and_path) {
    if (file.empty()) continue;
    const fs::path path = fs::absolute(file).lexically_normal();
    std::error_code ec;
    if (!fs::is_directory(path.parent_path(), ec))
      throw InputError("output directory '" + path.parent_path().string() + "' of " + option +
                       " does not exist.");
    if (fs::is_directory(path, ec))
      throw InputError(option + " '" + file + "' is a directory, not a file.");
    const long name_max = ::pathconf(path.parent_path().c_str(), _PC_NAME_MAX);
    if (name_max > 0 && path.filename().native().size() > static_cast<std::size_t>(name_max))
      throw InputError(option + " '" + file + "' has a name longer than the " + std::to_string(name_max) +
                       " bytes its file system allows.");
    require_creatable(option, file, path.parent_path());
    for (const std::string& input : inputs)
      if (fs::is_regular_file(input, ec) && fs::exists(path, ec) && fs::equivalent(path, input, ec))
        throw InputError(option + " '" + file + "' would overwrite the input '" + input + "'.");
    for (const auto& [other, p] : seen)
      if (p == path || fs::equivalent(p, path, ec))
        throw InputError(option + " and " + other + " name the same file '" + file + "'.");
    seen.emplace_back(option, path);
  }
}

std::string markdown_cell(std::string text) {
  for (std::size_t at = 0; (at = text.find('|', at)) != std::string::npos; at += 2) text.insert(at, "\\");
  return text;
}

}  // namespace ssr
