#include "eval/video.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include "core/errors.h"
#include "eval/grid.h"

namespace fs = std::filesystem;
using namespace ssr;

namespace {

RgbaImage8 solid(int w, int h, std::uint8_t v) {
  RgbaImage8 im{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 4, v)};
  for (std::size_t i = 3; i < im.pixels.size(); i += 4) im.pixels[i] = 255;
  return im;
}

const std::uint8_t* px(const RgbaImage8& im, int x, int y) {
  return &im.pixels[(std::size_t(y) * im.width + x) * 4];
}

// A directory of its own for each test, removed afterwards.
struct TempDir {
  fs::path path;
  TempDir() {
    static int n = 0;
    path = fs::temp_directory_path() / ("ssrlab-video-" + std::to_string(::getpid()) + "-" + std::to_string(n++));
    fs::create_directories(path);
  }
  ~TempDir() { std::error_code ec; fs::remove_all(path, ec); }
};

// "frames,width,height" as ffprobe counts them, decoding the whole stream.
std::string probe(const fs::path& file) {
  const std::string cmd = "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                          "stream=nb_read_frames,width,height -of csv=p=0 '" + file.string() + "'";
  std::string out;
  if (std::FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[256];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    ::pclose(p);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

// ffprobe's csv column order follows its own stream fields: width,height,...,nb_read_frames.
void encode_and_check(int w, int h, const std::string& expected) {
  if (!ffmpeg_available()) GTEST_SKIP() << "ffmpeg is not installed (scripts/install-deps.sh installs it)";
  TempDir dir;
  const fs::path file = dir.path / "clip.mp4";
  {
    VideoWriter video(file.string(), w, h, 24);
    EXPECT_EQ(video.video_width() % 2, 0);
    EXPECT_EQ(video.video_height() % 2, 0);
    for (int i = 0; i < 12; ++i) video.add_frame(solid(w, h, std::uint8_t(i * 20)));
    EXPECT_FALSE(fs::exists(file)) << "the file appears only at finish()";
    video.finish();
  }
  ASSERT_TRUE(fs::exists(file));
  EXPECT_EQ(probe(file), expected);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator{}), 1)
      << "no temporary file left beside the video";
}

}  // namespace

TEST(Video, HstackPutsPanelsSideBySideWithGreyGaps) {
  const RgbaImage8 out = hstack({solid(10, 6, 200), solid(7, 6, 100), solid(3, 6, 0)}, 4);
  EXPECT_EQ(out.width, 10 + 4 + 7 + 4 + 3);
  EXPECT_EQ(out.height, 6);
  ASSERT_EQ(out.pixels.size(), std::size_t(out.width) * out.height * 4);
  EXPECT_EQ(px(out, 9, 5)[0], 200);
  EXPECT_EQ(px(out, 10, 0)[0], px(out, 13, 5)[0]);  // the gap: one grey, neither panel
  EXPECT_NE(px(out, 12, 3)[0], 200);
  EXPECT_NE(px(out, 12, 3)[0], 100);
  EXPECT_EQ(px(out, 12, 3)[3], 255);
  EXPECT_EQ(px(out, 14, 0)[0], 100);
  EXPECT_EQ(px(out, 25, 2)[0], 0);
  EXPECT_EQ(hstack({solid(5, 4, 1), solid(5, 4, 2)}, 0).width, 10);
  EXPECT_EQ(hstack({}).width, 0);
  EXPECT_THROW(hstack({solid(5, 4, 1), solid(5, 3, 1)}), RuntimeError);
}

TEST(Video, VstackPutsRowsTopToBottomWithGreyGaps) {
  const RgbaImage8 out = vstack({solid(6, 10, 200), solid(6, 7, 100)}, 4);
  EXPECT_EQ(out.width, 6);
  EXPECT_EQ(out.height, 10 + 4 + 7);
  ASSERT_EQ(out.pixels.size(), std::size_t(out.width) * out.height * 4);
  EXPECT_EQ(px(out, 5, 9)[0], 200);
  EXPECT_NE(px(out, 3, 12)[0], 200);  // the gap
  EXPECT_NE(px(out, 3, 12)[0], 100);
  EXPECT_EQ(px(out, 3, 12)[3], 255);
  EXPECT_EQ(px(out, 0, 14)[0], 100);
  EXPECT_EQ(px(out, 5, 20)[0], 100);
  EXPECT_EQ(vstack({}).height, 0);
  EXPECT_THROW(vstack({solid(5, 4, 1), solid(4, 4, 1)}), RuntimeError);
}

// Labels wrap to their panel: at 160x90 the sequence's and compare's labels ran off the panel
// and lost their last words (a preset's name, the PSNR).
TEST(Video, WrappedLabelsFitTheirWidthAndKeepEveryCharacter) {
  const std::string text = "stochastic [stochastic-low]  4.63 ms cpu  an_unbroken_word_wider_than_the_panel";
  for (int scale : {1, 2})
    for (int width : {40, 80, 157, 300}) {
      const std::string wrapped = wrap_label(text, width, scale);
      std::size_t start = 0, lines = 0;
      while (start <= wrapped.size()) {
        const std::size_t end = std::min(wrapped.find('\n', start), wrapped.size());
        EXPECT_LE(label_size(wrapped.substr(start, end - start), scale).first, width)
            << "line " << lines << " of '" << wrapped << "' at scale " << scale;
        ++lines;
        start = end + 1;
      }
      std::string kept = wrapped, want = text;
      std::erase_if(kept, [](char c) { return c == '\n' || c == ' '; });
      std::erase_if(want, [](char c) { return c == ' '; });
      EXPECT_EQ(kept, want) << "width " << width << " scale " << scale;
      EXPECT_GT(lines, 1u);
    }
  EXPECT_EQ(wrap_label("hiz  frame 0", 400, 1), "hiz  frame 0") << "a label that fits is unchanged";
}

TEST(Video, GridStripGrowsForAWrappedLabel) {
  const RgbaImage8 tile = solid(160, 90, 128);
  const RgbaImage8 one_line = make_grid({{"hiz", tile}, {"ppr", tile}}, 2);
  const RgbaImage8 wrapped = make_grid({{"hiz", tile}, {"stochastic [stochastic-low]  4.63 ms cpu", tile}}, 2);
  EXPECT_EQ(one_line.width, wrapped.width);
  EXPECT_EQ(wrapped.height - one_line.height, label_size("x", 1).second) << "one more line of text";
}

TEST(Video, DrawLabelChangesPixelsInsideItsBoxOnly) {
  RgbaImage8 im = solid(120, 50, 128);
  const RgbaImage8 before = im;
  const int x = 10, y = 7;
  const auto [bw, bh] = label_size("SSR 42", 2);
  ASSERT_GT(bw, 0);
  ASSERT_GT(bh, 0);
  draw_label(im, x, y, "SSR 42", 2);
  ASSERT_EQ(im.width, 120);
  ASSERT_EQ(im.height, 50);
  ASSERT_EQ(im.pixels.size(), before.pixels.size());
  int white = 0, dark = 0;
  for (int py = 0; py < im.height; ++py)
    for (int px_ = 0; px_ < im.width; ++px_) {
      const bool inside = px_ >= x && px_ < x + bw && py >= y && py < y + bh;
      const bool changed = std::memcmp(px(im, px_, py), px(before, px_, py), 4) != 0;
      if (!inside) EXPECT_FALSE(changed) << "pixel " << px_ << "," << py << " outside the box";
      else if (px(im, px_, py)[0] == 255) ++white;
      else if (px(im, px_, py)[0] < 128) ++dark;
    }
  EXPECT_GT(white, 20) << "the text is drawn";
  EXPECT_GT(dark, white) << "on a darkened box";

  // Clipped at the border, odd characters tolerated, size kept.
  RgbaImage8 small = solid(8, 8, 50);
  draw_label(small, -3, 4, "\xff\x01 long label that runs off", 3);
  EXPECT_EQ(small.width, 8);
  EXPECT_EQ(small.pixels.size(), std::size_t(8 * 8 * 4));

  const RgbaImage8 pair = labelled_panels({{"A", solid(40, 30, 128)}, {"B", solid(40, 30, 128)}});
  EXPECT_EQ(pair.width, 84);
  EXPECT_EQ(pair.height, 30);
  EXPECT_NE(std::memcmp(px(pair, 4, 4), px(pair, 39, 29), 4), 0) << "label in the top-left corner";
}

TEST(Video, WritesTwelveFrames) { encode_and_check(64, 48, "64,48,12"); }

TEST(Video, PadsAnOddSizeToEven) { encode_and_check(65, 47, "66,48,12"); }

TEST(Video, DestroyedWithoutFinishLeavesNothing) {
  if (!ffmpeg_available()) GTEST_SKIP() << "ffmpeg is not installed (scripts/install-deps.sh installs it)";
  TempDir dir;
  const fs::path file = dir.path / "abandoned.mp4";
  {
    VideoWriter video(file.string(), 32, 32, 30);
    for (int i = 0; i < 3; ++i) video.add_frame(solid(32, 32, 90));
    VideoWriter moved = std::move(video);  // the moved-from writer must not remove anything twice
  }
  EXPECT_TRUE(fs::is_empty(dir.path));
}

// An ffmpeg that dies mid-stream: an error with its message, not a SIGPIPE crash, and nothing left.
TEST(Video, DyingFfmpegIsAnErrorNotACrash) {
  if (!ffmpeg_available()) GTEST_SKIP() << "ffmpeg is not installed (scripts/install-deps.sh installs it)";
  TempDir dir, bin;
  const fs::path fake = bin.path / "ffmpeg";
  {
    std::FILE* f = std::fopen(fake.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("#!/bin/sh\nfor a; do out=$a; done\necho partial > \"$out\"\n"
               "head -c 100 >/dev/null\necho 'boom: encoder exploded' >&2\nexit 1\n", f);
    std::fclose(f);
  }
  fs::permissions(fake, fs::perms::owner_all);
  const std::string old_path = std::getenv("PATH");
  ::setenv("PATH", (bin.path.string() + ":" + old_path).c_str(), 1);
  try {
    VideoWriter video((dir.path / "v.mp4").string(), 64, 64, 30);
    for (int i = 0; i < 200; ++i) video.add_frame(solid(64, 64, 7));  // 3 MB: more than a pipe holds
    video.finish();
    ADD_FAILURE() << "no error from a failing ffmpeg";
  } catch (const RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find("boom: encoder exploded"), std::string::npos) << e.what();
  }
  ::setenv("PATH", old_path.c_str(), 1);
  EXPECT_TRUE(fs::is_empty(dir.path));
}

TEST(Video, RejectsWrongFrameSize) {
  if (!ffmpeg_available()) GTEST_SKIP() << "ffmpeg is not installed (scripts/install-deps.sh installs it)";
  TempDir dir;
  VideoWriter video((dir.path / "v.mp4").string(), 32, 32, 30);
  EXPECT_THROW(video.add_frame(solid(31, 32, 0)), RuntimeError);
}

TEST(Video, BadDestinationsAreInputErrors) {
  TempDir dir;
  EXPECT_THROW(VideoWriter((dir.path / "missing" / "v.mp4").string(), 64, 48, 24), InputError);
  EXPECT_THROW(VideoWriter((dir.path / "v.gif").string(), 64, 48, 24), InputError);
  EXPECT_THROW(VideoWriter((dir.path / "v").string(), 64, 48, 24), InputError);
  EXPECT_THROW(VideoWriter((dir.path / "v.mp4").string(), 0, 48, 24), InputError);
  EXPECT_THROW(VideoWriter((dir.path / "v.mp4").string(), 64, 48, 0), InputError);
  if (!ffmpeg_available()) EXPECT_THROW(VideoWriter((dir.path / "v.mp4").string(), 64, 48, 24), InputError);
  EXPECT_TRUE(fs::is_empty(dir.path));
}
