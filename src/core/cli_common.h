// Pieces shared by the two programs' command lines.
#pragma once
#include <filesystem>
#include <string>
#include <utility>
#include <vector>


namespace ssr {

// At most this many pixels per frame (8192x8192): the renderer keeps about 100 bytes a pixel,
// so a size the GL accepts side by side (16384x16384) could still exhaust memory.
constexpr long long kMaxFramePixels = 1LL << 26;

// "WxH" or a size name (size_names()) -> {W, H}; throws InputError for anything else (0 sides and
// more than kMaxFramePixels included). The GL's own limit per side is checked once a context is
// open (open_gl).
std::pair<int, int> parse_size(const std::string& text);
// The size names parse_size takes, for help texts: "720p, 1080p, 1440p, 4k (2160p), 8k (4320p)".
std::string size_names();

// `text` made safe for a Markdown table cell: a '|' inside a cell would end it.
std::string markdown_cell(std::string text);

// Throws InputError unless a new file can be made in `dir` (one is made and removed: permissions
// alone do not say, as root ignores them and a read-only mount refuses root too). `option` and
// `path` name the output in the message.
void require_creatable(const std::string& option, const std::string& path, const std::filesystem::path& dir);

// Output files, checked before any work so that a bad path costs nothing and leaves nothing: the
// directory must exist and take a new file (require_creatable), the name must fit the file
// system, the path must not be a directory, no two outputs of one command may be the same file,
// and no output may be one of `inputs` (e.g. the --scene file). Pairs of {option, path}, e.g.
// {"--json", "r.json"}; empty paths are skipped, and inputs that are not files (built-in scene
// names).
void require_output_files(const std::vector<std::pair<std::string, std::string>>& option_and_path,
                          const std::vector<std::string>& inputs = {});

}  // namespace ssr
