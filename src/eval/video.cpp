#include "eval/video.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"  // the header's unused stb_easy_font_spacing
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

#include "core/errors.h"
#include "core/files.h"

extern char** environ;

namespace ssr {

namespace fs = std::filesystem;

namespace {

// Runs a shell command: true if it exited 0; its stdout goes to *out.
bool probe(const char* cmd, std::string* out = nullptr) {
  std::FILE* p = ::popen(cmd, "r");
  if (!p) return false;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;)
    if (out) out->append(buf, n);
  const int status = ::pclose(p);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// Writes everything with SIGPIPE blocked in this thread: a dead ffmpeg then gives EPIPE, which we
// report, instead of a signal that kills the process. A SIGPIPE our write raised is consumed before
// unblocking; the process-wide disposition is left alone.
bool write_all(int fd, const std::uint8_t* p, std::size_t n) {
  sigset_t pipe_set, old;
  sigemptyset(&pipe_set);
  sigaddset(&pipe_set, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_set, &old);
  bool ok = true;
  while (n > 0) {
    const ssize_t k = ::write(fd, p, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) { ok = false; break; }
    p += k;
    n -= static_cast<std::size_t>(k);
  }
  if (!ok && errno == EPIPE) {
    const timespec zero{};
    sigtimedwait(&pipe_set, nullptr, &zero);
  }
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  return ok;
}

std::string read_message(int fd) {
  std::string msg;
  char buf[4096];
  ::lseek(fd, 0, SEEK_SET);
  for (ssize_t n; (n = ::read(fd, buf, sizeof buf)) > 0;) msg.append(buf, static_cast<std::size_t>(n));
  while (!msg.empty() && std::isspace(static_cast<unsigned char>(msg.back()))) msg.pop_back();
  if (msg.size() > 600) msg = "..." + msg.substr(msg.size() - 600);
  return msg.empty() ? "no message" : msg;
}

}  // namespace

bool ffmpeg_available() {
  static const bool ok = probe("ffmpeg -hide_banner -version >/dev/null 2>&1");
  return ok;
}

VideoWriter::VideoWriter(const std::string& path, int width, int height, int fps)
    : path_(path), width_(width), height_(height) {
  const fs::path p(path);
  const std::string ext = files::lower_extension(p);
  if (ext != ".mp4" && ext != ".mkv")
    throw InputError("video '" + path + "' must end in .mp4 or .mkv.");
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw InputError("video size " + std::to_string(width) + "x" + std::to_string(height) +
                     " is out of range (1 to 16384 pixels a side).");
  if (fps < 1 || fps > 240)
    throw InputError("video frame rate " + std::to_string(fps) + " is out of range (1 to 240).");
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError("cannot write video '" + path + "': directory '" + dir.string() + "' does not exist.");
  if (::access(dir.c_str(), W_OK) != 0)
    throw InputError("cannot write video '" + path + "': directory '" + dir.string() + "' is not writable.");
  if (!ffmpeg_available())
    throw InputError("--video needs ffmpeg, which is not installed (scripts/install-deps.sh installs it).");

  static const bool has_x264 = [] {
    std::string list;
    return probe("ffmpeg -hide_banner -encoders 2>/dev/null", &list) && list.find(" libx264 ") != std::string::npos;
  }();
  static std::atomic<int> counter{0};
  tmp_ = path + ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  const std::string size = std::to_string(video_width()) + "x" + std::to_string(video_height());
  const std::string rate = std::to_string(fps);
  std::vector<std::string> args = {"ffmpeg", "-y", "-hide_banner", "-loglevel", "error",
      "-f", "rawvideo", "-pix_fmt", "rgba", "-s", size, "-r", rate, "-i", "-"};
  if (has_x264) args.insert(args.end(), {"-c:v", "libx264", "-crf", "18"});
  else args.insert(args.end(), {"-c:v", "mpeg4", "-q:v", "2"});  // mpeg4 has no crf: q 2 is near-lossless
  // The muxer is named because the temporary file's name has no usable extension; "file:" keeps a
  // name with a colon or a leading '-' from being read as a protocol or an option.
  args.insert(args.end(), {"-pix_fmt", "yuv420p", "-f", ext == ".mp4" ? "mp4" : "matroska", "file:" + tmp_});
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  // Both of our ends are close-on-exec, so no other child (ours or another writer's) keeps the
  // pipe open and ffmpeg sees EOF when we close it. ffmpeg's stderr goes to an anonymous file read
  // on failure: a pipe could fill up and block it.
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw RuntimeError("cannot create a pipe for ffmpeg.");
  stdin_fd_ = fds[1];
  stderr_fd_ = ::memfd_create("ffmpeg-stderr", MFD_CLOEXEC);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, fds[0], 0);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  if (stderr_fd_ >= 0) posix_spawn_file_actions_adddup2(&fa, stderr_fd_, 2);
  const int rc = ::posix_spawnp(&pid_, "ffmpeg", &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  ::close(fds[0]);
  if (rc != 0) {
    pid_ = -1;
    abort();
    throw RuntimeError("cannot start ffmpeg: " + std::string(std::strerror(rc)) + ".");
  }
}

void VideoWriter::take(VideoWriter& o) noexcept {
  path_ = std::move(o.path_);
  tmp_ = std::exchange(o.tmp_, {});
  width_ = o.width_;
  height_ = o.height_;
  frames_ = o.frames_;
  pid_ = std::exchange(o.pid_, -1);
  stdin_fd_ = std::exchange(o.stdin_fd_, -1);
  stderr_fd_ = std::exchange(o.stderr_fd_, -1);
}

VideoWriter::VideoWriter(VideoWriter&& o) noexcept { take(o); }
VideoWriter& VideoWriter::operator=(VideoWriter&& o) noexcept {
  if (this != &o) { abort(); take(o); }
  return *this;
}
VideoWriter::~VideoWriter() { abort(); }

void VideoWriter::abort() noexcept {
  if (stdin_fd_ >= 0) ::close(stdin_fd_);
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    while (::waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {}
  }
  if (stderr_fd_ >= 0) ::close(stderr_fd_);
  if (!tmp_.empty()) { std::error_code ec; fs::remove(tmp_, ec); }
  stdin_fd_ = stderr_fd_ = pid_ = -1;
  tmp_.clear();
}

void VideoWriter::fail(const std::string& why) {
  // Closing stdin ends ffmpeg if it still runs; then its message is complete.
  if (stdin_fd_ >= 0) ::close(stdin_fd_);
  stdin_fd_ = -1;
  if (pid_ > 0) while (::waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {}
  pid_ = -1;
  const std::string msg = stderr_fd_ >= 0 ? read_message(stderr_fd_) : "no message";
  abort();
  throw RuntimeError(why + " (ffmpeg: " + msg + ").");
}

void VideoWriter::add_frame(const RgbaImage8& f) {
  if (pid_ < 0) throw RuntimeError("video '" + path_ + "' is already finished.");
  if (f.width != width_ || f.height != height_ || f.pixels.size() != std::size_t(width_) * height_ * 4)
    throw RuntimeError("video frame is " + std::to_string(f.width) + "x" + std::to_string(f.height) +
                       ", expected " + std::to_string(width_) + "x" + std::to_string(height_) + ".");
  const std::uint8_t* data = f.pixels.data();
  std::vector<std::uint8_t> padded;
  const int W = video_width(), H = video_height();
  if (W != width_ || H != height_) {  // repeat the last column/row: black would bleed into chroma
    padded.resize(std::size_t(W) * H * 4);
    for (int y = 0; y < H; ++y) {
      const std::uint8_t* src = data + std::size_t(std::min(y, height_ - 1)) * width_ * 4;
      std::uint8_t* dst = padded.data() + std::size_t(y) * W * 4;
      std::memcpy(dst, src, std::size_t(width_) * 4);
      if (W != width_) std::memcpy(dst + std::size_t(width_) * 4, src + std::size_t(width_ - 1) * 4, 4);
    }
    data = padded.data();
  }
  if (!write_all(stdin_fd_, data, std::size_t(W) * H * 4)) fail("ffmpeg stopped while writing '" + path_ + "'");
  ++frames_;
}

void VideoWriter::finish() {
  if (pid_ < 0) throw RuntimeError("video '" + path_ + "' is already finished.");
  if (frames_ == 0) { abort(); throw RuntimeError("video '" + path_ + "' has no frames."); }
  ::close(stdin_fd_);  // EOF: ffmpeg flushes the encoder and writes the container's index
  stdin_fd_ = -1;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {}
  pid_ = -1;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) fail("ffmpeg failed to write '" + path_ + "'");
  std::error_code ec;
  fs::rename(tmp_, path_, ec);
  if (ec) {
    abort();
    throw RuntimeError("cannot move the video into place at '" + path_ + "': " + ec.message() + ".");
  }
  tmp_.clear();
  abort();  // only closes the stderr file now
}

RgbaImage8 hstack(const std::vector<RgbaImage8>& panels, int gap) {
  RgbaImage8 out;
  if (panels.empty()) return out;
  gap = std::max(gap, 0);
  out.height = panels[0].height;
  for (const auto& p : panels) {
    if (p.height != out.height) throw RuntimeError("hstack: the panels differ in height.");
    out.width += p.width;
  }
  out.width += gap * int(panels.size() - 1);
  out.pixels.assign(std::size_t(out.width) * out.height * 4, 48);  // dark grey gaps
  for (std::size_t i = 3; i < out.pixels.size(); i += 4) out.pixels[i] = 255;
  int x0 = 0;
  for (const auto& p : panels) {
    for (int y = 0; y < p.height; ++y)
      std::memcpy(&out.pixels[(std::size_t(y) * out.width + x0) * 4], &p.pixels[std::size_t(y) * p.width * 4],
                  std::size_t(p.width) * 4);
    x0 += p.width + gap;
  }
  return out;
}

RgbaImage8 vstack(const std::vector<RgbaImage8>& rows, int gap) {
  RgbaImage8 out;
  if (rows.empty()) return out;
  gap = std::max(gap, 0);
  out.width = rows[0].width;
  for (const auto& r : rows) {
    if (r.width != out.width) throw RuntimeError("vstack: the rows differ in width.");
    out.height += r.height;
  }
  out.height += gap * int(rows.size() - 1);
  out.pixels.assign(std::size_t(out.width) * out.height * 4, 48);  // dark grey gaps
  for (std::size_t i = 3; i < out.pixels.size(); i += 4) out.pixels[i] = 255;
  std::size_t at = 0;
  for (const auto& r : rows) {  // rows are contiguous: one copy each
    std::memcpy(&out.pixels[at], r.pixels.data(), r.pixels.size());
    at += r.pixels.size() + std::size_t(out.width) * gap * 4;
  }
  return out;
}

namespace {
// stb_easy_font indexes its tables with (c - 32): anything else would read out of bounds.
std::string printable(const std::string& text) {
  std::string s = text;
  for (char& c : s)
    if (c != '\n' && (c < 32 || c > 126)) c = '?';
  return s;
}
}  // namespace

std::pair<int, int> label_size(const std::string& text, int scale) {
  std::string s = printable(text);
  scale = std::max(scale, 1);
  // One font unit of margin left and right; a line is 12 units, which leaves room for descenders.
  return {stb_easy_font_width(s.data()) * scale + 2 * scale, stb_easy_font_height(s.data()) * scale};
}

void draw_label(RgbaImage8& im, int x, int y, const std::string& text, int scale) {
  std::string s = printable(text);
  scale = std::max(scale, 1);
  const auto [bw, bh] = label_size(s, scale);
  auto fill = [&](int x0, int y0, int x1, int y1, bool text_px) {
    for (int py = std::max(y0, 0); py < std::min(y1, im.height); ++py)
      for (int px = std::max(x0, 0); px < std::min(x1, im.width); ++px) {
        std::uint8_t* c = &im.pixels[(std::size_t(py) * im.width + px) * 4];
        for (int k = 0; k < 3; ++k) c[k] = text_px ? 255 : std::uint8_t(c[k] * 2 / 5);  // 60% black
        c[3] = 255;  // opaque, so the label shows in PNGs with transparent pixels too
      }
  };
  fill(x, y, x + bw, y + bh, false);
  std::vector<char> quads(s.size() * 400 + 64);  // the header expects ~270 bytes a character
  const int n = stb_easy_font_print(0, 0, s.data(), nullptr, quads.data(), int(quads.size()));
  for (int q = 0; q < n; ++q) {
    // Each quad is an axis-aligned rectangle: vertex 0 its top-left, vertex 2 its bottom-right.
    float v0[2], v2[2];
    std::memcpy(v0, &quads[std::size_t(q) * 64], sizeof v0);
    std::memcpy(v2, &quads[std::size_t(q) * 64 + 32], sizeof v2);
    fill(x + scale + int(v0[0]) * scale, y + scale + int(v0[1]) * scale,
         x + scale + int(v2[0]) * scale, y + scale + int(v2[1]) * scale, true);
  }
}

std::string wrap_label(const std::string& text, int max_width, int scale) {
  const auto fits = [&](const std::string& line) { return label_size(line, scale).first <= max_width; };
  std::string out, line;
  const auto flush = [&] {
    if (!out.empty()) out += '\n';
    out += line;
    line.clear();
  };
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t end = std::min(text.find(' ', i), text.size());
    std::string word = text.substr(i, end - i);
    i = end + 1;
    if (word.empty() && line.empty()) continue;  // runs of spaces at a line's start
    if (fits(line.empty() ? word : line + " " + word)) {
      line = line.empty() ? word : line + " " + word;
      continue;
    }
    if (!line.empty()) flush();
    for (char c : word) {  // a word wider than a line: cut it where it reaches the edge
      if (!line.empty() && !fits(line + c)) flush();
      line += c;
    }
  }
  if (!line.empty() || out.empty()) flush();
  return out;
}

RgbaImage8 labelled_panels(const std::vector<std::pair<std::string, RgbaImage8>>& panels) {
  std::vector<RgbaImage8> images;
  for (const auto& [label, image] : panels) {
    images.push_back(image);
    const int scale = label_scale(image.width);
    draw_label(images.back(), 4, 4, wrap_label(label, image.width - 8, scale), scale);
  }
  return hstack(images);
}

}  // namespace ssr
