#include "core/cli_common.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <regex>
#include <vector>

#include "core/errors.h"
#include "core/files.h"

namespace ssr {

namespace {
// Each size's names, the first the one help texts give.
struct SizeName {
  std::vector<const char*> names;
  int width, height;
};
const SizeName kSizeNames[] = {{{"720p"}, 1280, 720},          {{"1080p"}, 1920, 1080},
                               {{"1440p"}, 2560, 1440},        {{"4k", "2160p"}, 3840, 2160},
                               {{"8k", "4320p"}, 7680, 4320}};
}  // namespace

std::string size_names() {
  std::string out;
  for (const SizeName& s : kSizeNames) {
    out += (out.empty() ? "" : ", ") + std::string(s.names[0]);
    if (s.names.size() > 1) out += " (" + std::string(s.names[1]) + ")";
  }
  return out;
}

std::pair<int, int> parse_size(const std::string& text) {
  for (const SizeName& s : kSizeNames)
    for (const char* n : s.names)
      if (text == n) return {s.width, s.height};
  static const std::regex re(R"(^(\d{1,6})x(\d{1,6})$)");
  std::smatch m;
  if (!std::regex_match(text, m, re))
    throw InputError("size '" + text + "' is not of the form WIDTHxHEIGHT (e.g. 1280x720) nor a size name (" +
                     size_names() + ").");
  const int w = std::stoi(m[1]), h = std::stoi(m[2]);
  if (w < 1 || h < 1) throw InputError("size '" + text + "' must be at least 1x1.");
  if (static_cast<long long>(w) * h > kMaxFramePixels)
    throw InputError("size '" + text + "' has " + std::to_string(static_cast<long long>(w) * h) +
                     " pixels, more than the " + std::to_string(kMaxFramePixels) +
                     " (8192x8192) supported.");
  return {w, h};
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
    std::error_code ec;
    // The directory as the system resolves it ("nodir/../x.png" needs nodir), then the file a
    // write replaces (a symbolic link's target): what the checks below look at is what is written.
    const fs::path given_dir = fs::path(file).parent_path().empty() ? fs::path(".") : fs::path(file).parent_path();
    if (!fs::is_directory(given_dir, ec))
      throw InputError("output directory '" + given_dir.string() + "' of " + option + " does not exist.");
    const fs::path target = fs::absolute(files::write_target(file));
    const fs::path path = fs::weakly_canonical(target.parent_path(), ec) / target.filename();
    if (ec || !fs::is_directory(path.parent_path(), ec))
      throw InputError(option + " '" + file + "' is a link to a file in a directory that does not exist.");
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
