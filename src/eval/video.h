// Side-by-side videos for `ssrlab sequence --video`: a writer that streams frames into ffmpeg, and
// the helpers that compose labelled panels (used for the video and for PNG frames alike).
#pragma once
#include <sys/types.h>

#include <string>
#include <utility>
#include <vector>

#include "core/image.h"

namespace ssr {

// ffmpeg is on PATH and runs (probed once per process).
bool ffmpeg_available();

// Streams RGBA8 frames into an ffmpeg child: H.264 (libx264, yuv420p, crf 18), or MPEG-4 part 2
// where this ffmpeg has no libx264. ffmpeg writes a temporary file beside the destination; finish()
// renames it into place, anything else (ffmpeg failed, destroyed without finish()) removes it, so a
// half-written video never appears under the destination's name.
// yuv420p needs even sizes: an odd width or height is padded by one column/row repeating the edge,
// so the video is video_width() x video_height(); frames are still given at width x height.
class VideoWriter {
 public:
  // path: .mp4 or .mkv, in an existing, writable directory; width/height 1..16384; fps 1..240.
  // Throws InputError (one sentence) for any of these or when ffmpeg is missing, RuntimeError when
  // ffmpeg cannot be started.
  VideoWriter(const std::string& path, int width, int height, int fps);
  VideoWriter(VideoWriter&& other) noexcept;
  VideoWriter& operator=(VideoWriter&& other) noexcept;
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;
  ~VideoWriter();  // without finish(): kills ffmpeg, removes the temporary file

  // The frame must be width x height. RuntimeError (with ffmpeg's message) if ffmpeg has died.
  void add_frame(const RgbaImage8& frame);
  // Ends the stream, waits for ffmpeg and moves the file into place. RuntimeError with ffmpeg's
  // message if it failed or no frame was added (the temporary file is removed).
  void finish();

  int video_width() const { return (width_ + 1) & ~1; }
  int video_height() const { return (height_ + 1) & ~1; }

 private:
  void take(VideoWriter& other) noexcept;
  void abort() noexcept;                          // kill + reap ffmpeg, remove the temporary file
  [[noreturn]] void fail(const std::string& why);  // reap ffmpeg, remove the file, throw
  std::string path_, tmp_;
  int width_ = 0, height_ = 0, frames_ = 0;
  pid_t pid_ = -1;
  int stdin_fd_ = -1, stderr_fd_ = -1;
};

// Panels left to right with `gap` dark grey columns between them. Heights must match
// (RuntimeError otherwise); no panels give an empty image.
RgbaImage8 hstack(const std::vector<RgbaImage8>& panels, int gap = 4);
// Rows of equal width stacked top to bottom, with the same gaps (RuntimeError on other widths).
RgbaImage8 vstack(const std::vector<RgbaImage8>& rows, int gap = 4);

// Size (w, h) of the box draw_label fills for `text` (stb_easy_font, `scale` pixels per font unit).
std::pair<int, int> label_size(const std::string& text, int scale = 2);
// White text on a semi-transparent black box whose top-left corner is (x, y), clipped to the
// image; readable on any content. Characters outside printable ASCII are drawn as '?'.
void draw_label(RgbaImage8& im, int x, int y, const std::string& text, int scale = 2);

// `text` broken at spaces into lines (joined by '\n') whose label_size() at `scale` is at most
// `max_width` pixels wide; a word wider than that is cut across lines. A label never runs off its
// panel, so no figure in it is lost at small sizes.
std::string wrap_label(const std::string& text, int max_width, int scale);
// The font scale for labels on panels `width` pixels wide: 2 from 480 up, else 1.
inline int label_scale(int width) { return width >= 480 ? 2 : 1; }

// Each panel with its label, wrapped to the panel's width, in the top-left corner, stacked with
// hstack().
RgbaImage8 labelled_panels(const std::vector<std::pair<std::string, RgbaImage8>>& panels);

}  // namespace ssr
