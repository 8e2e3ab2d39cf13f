#include "core/files.h"

#include <unistd.h>

#include <atomic>
#include <fstream>
#include <system_error>

#include "core/errors.h"

namespace ssr::files {

namespace fs = std::filesystem;

void fail(std::string msg) {
  for (char& c : msg)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  while (!msg.empty() && (msg.back() == ' ' || msg.back() == '.')) msg.pop_back();
  throw InputError(msg + ".");
}

std::string q(std::string_view s) {
  std::string r;
  r.reserve(s.size() + 2);
  r.append(1, '\'').append(s).append(1, '\'');
  return r;
}

fs::path temp_path_beside(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  return target.parent_path() / (".ssrlab-" + std::to_string(static_cast<long long>(::getpid())) + "-" +
                                 std::to_string(counter++) + ".tmp");
}

fs::path write_target(const fs::path& file) {
  fs::path p = file;
  for (int hops = 0; hops < 40; ++hops) {  // 40: Linux's own limit on links in a path
    std::error_code ec;
    if (!fs::is_symlink(p, ec)) return p;
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) return p;
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  return p;
}

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return ext;
}

std::string read_file(const fs::path& path, std::uintmax_t cap, const std::string& what,
                      const std::string& context) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) fail(context + what + " " + q(path) + " does not exist");
  if (!fs::is_regular_file(st)) fail(context + what + " " + q(path) + " is not a regular file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) fail(context + what + " " + q(path) + " could not be read (" + ec.message() + ")");
  if (size > cap)
    fail(context + what + " " + q(path) + " is " + std::to_string(size) + " bytes, more than the " +
         std::to_string(cap) + " supported");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(context + what + " " + q(path) + " could not be opened");
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (in.gcount() != static_cast<std::streamsize>(size))
    fail(context + what + " " + q(path) + " could not be read completely");
  return text;
}

std::string read_text_file(const fs::path& path, std::uintmax_t cap, const std::string& what,
                           const std::string& context) {
  std::string text = read_file(path, cap, what, context);
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  return text;
}

}  // namespace ssr::files
