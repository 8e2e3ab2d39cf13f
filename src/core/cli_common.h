// Pieces shared by the two programs' command lines.
#pragma once
#include <string>
#include <utility>
#include <vector>


namespace ssr {

// At most this many pixels per frame (8192x8192): the renderer keeps about 100 bytes a pixel,
// so a size the GL accepts side by side (16384x16384) could still exhaust memory.
constexpr long long kMaxFramePixels = 1LL << 26;

// "WxH" -> {W, H}; throws InputError for anything else (0 sides and more than kMaxFramePixels
// included). The GL's own limit per side is checked once a context is open (open_gl).
std::pair<int, int> parse_size(const std::string& text);
// parse_size, or a name: "720p", "1080p", "1440p", "4k" (= "2160p"), "8k" (= "4320p").
std::pair<int, int> parse_named_size(const std::string& text);

// `text` made safe for a Markdown table cell: a '|' inside a cell would end it.
std::string markdown_cell(std::string text);

// Output files: the directory must exist, the path must not be a directory, and no two outputs
// of one command may be the same file. Pairs of {option, path}, e.g. {"--json", "r.json"};
// empty paths are skipped.
void require_output_files(const std::vector<std::pair<std::string, std::string>>& option_and_path);

}  // namespace ssr
