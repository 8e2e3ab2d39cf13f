// Scripted input for the viewer (--script FILE): what a user would do with the mouse and keys,
// written down so that tests (and bug reports) can replay it in a real window.
//
// One command per line; '#' starts a comment; arguments are separated by spaces.
//
//   scene NAME|PATH        load a scene (built-in name, .json or .obj); its first camera
//   camera NAME            a named camera of the scene
//   technique NAME         technique A            technique-b NAME   technique B
//   set TECH.KEY=VALUE     a parameter of A or B (the prefix says which)
//   compare off|split|diff split X (0..1: the divider, and turns split on)
//   view NAME              a display view (final, reflection, ..., traceable)
//   exposure STOPS         ambient X (>= 0: the scene's ambient, through the lighting panel's path)
//   frames N               run N frames of the main loop (N >= 1)
//   screenshot PATH.png    the composed image of the last frame, without UI
//   preset-save PATH       preset-load PATH       (JSON presets, see viewer_preset.h)
//   resize WxH             minimise               restore
//   reload                 F5: reload the shaders
//   path NAME|free         follow the scene's camera path NAME (free: the orbit camera)
//   time SECONDS           jump to a scene time (object motion and the path's camera)
//   play                   pause              (playback: speed/30 s a drawn frame)
//
// The whole file is checked before the window opens: an unknown command or a bad argument is
// an InputError naming the file and line. Errors while running (a scene that does not load)
// are InputErrors too, with the line.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace ssr {

struct ScriptCommand {
  int line = 0;                   // 1-based, for messages
  std::string verb;
  std::vector<std::string> args;  // already checked for count and form
};

// Parses and checks a script; `where` names it in messages ("script.txt").
std::vector<ScriptCommand> parse_viewer_script(const std::string& text, const std::string& where);
std::vector<ScriptCommand> load_viewer_script(const std::filesystem::path& path);

// "file:line: " prefix for an error raised while running `c`.
std::string script_where(const std::string& file, const ScriptCommand& c);

}  // namespace ssr
