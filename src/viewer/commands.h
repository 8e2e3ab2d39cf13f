// The viewer's commands: everything a script line, a key or a button can ask the viewer to do,
// declared once in SSRLAB_VIEWER_COMMANDS below. That one list gives
//   - the script language (--script FILE): one command per line, '#' starts a comment;
//   - the checks every line passes before the window opens (form and count of its arguments);
//   - the help (`ssrlab-view --help-script`) and the README's table;
//   - the handlers: the viewer declares `on_<Id>` for each entry and dispatches through a table
//     built from the same list, so a command without a handler fails to link.
//
// The whole script is checked before the window opens: an unknown command or a bad argument is
// an InputError naming the file and line. Errors while running (a scene that does not load) are
// InputErrors too, with the line.
#pragma once
#include <array>
#include <filesystem>
#include <string>
#include <vector>

// X(Id, "verb", ArgForm, "ARGS", "what it does")
#define SSRLAB_VIEWER_COMMANDS(X)                                                                        \
  X(Scene, "scene", Text, "NAME|PATH", "load a scene (built-in name with options, .json or .obj) at its first camera") \
  X(Camera, "camera", Text, "NAME", "a named camera of the scene (or a bookmark)")                       \
  X(Technique, "technique", Technique, "NAME", "technique A")                                           \
  X(TechniqueB, "technique-b", Technique, "NAME", "technique B")                                        \
  X(Set, "set", Assignment, "TECH.KEY=VALUE", "a parameter of A or B (the prefix says which; both when they are the same technique)") \
  X(SetB, "set-b", Assignment, "TECH.KEY=VALUE", "a parameter of B alone (A and B the same technique at two settings)") \
  X(Preset, "preset", PresetName, "NAME", "technique A set up by a named preset of the CLI (listed by ssrlab techniques, e.g. thesis-hq)") \
  X(PresetB, "preset-b", PresetName, "NAME", "technique B set up by a named preset") \
  X(Swap, "swap", None, "", "swap techniques A and B, with their parameters")                            \
  X(Compare, "compare", Compare, "MODE", "A alone, A | B, |A - B|, or the 2x2 grid, MODE one of") \
  X(Split, "split", Fraction, "X", "split view with the divider at X (0..1 of the image width)")        \
  X(View, "view", View, "NAME", "a display view (final, reflection, ..., traceable)")                  \
  X(Exposure, "exposure", Number, "STOPS", "display exposure")                                          \
  X(ReflectiveF0, "reflective-f0", Number, "F0", "pixels whose max F0 reaches this do reflection work (frame settings: [0.001, 1])") \
  X(Ambient, "ambient", NonNegative, "X", "the scene's ambient factor (the lighting panel's path)")     \
  X(Frames, "frames", Count, "N", "run N frames of the main loop")                                       \
  X(Screenshot, "screenshot", Png, "PATH.png", "the image of the last frame, without the UI")           \
  X(PresetSave, "preset-save", Text, "PATH", "save the session as a JSON preset (see preset.h)")         \
  X(PresetLoad, "preset-load", Text, "PATH", "load a JSON preset")                                      \
  X(Resize, "resize", Size, "WxH", "the image size (the window adds the side panel and the status bar)") \
  X(Minimise, "minimise", None, "", "iconify the window")                                               \
  X(Restore, "restore", None, "", "restore the window")                                                 \
  X(Panel, "panel", OnOff, "on|off", "show or hide the side panel (F2)")                                \
  X(Section, "section", Section, "NAME open|closed", "open or close a section of the side panel, NAME one of") \
  X(Reload, "reload", None, "", "reload the shaders (F5)")                                               \
  X(Path, "path", Text, "NAME|free", "follow the scene's camera path NAME (free: the orbit camera)")     \
  X(Time, "time", NonNegative, "SECONDS", "jump to a scene time (object motion and the path's camera)")  \
  X(Play, "play", None, "", "start playback (speed/30 s a drawn frame)")                                \
  X(Pause, "pause", None, "", "stop playback")                                                          \
  X(Truth, "truth", TruthPolicy, "now|rest|live|manual",                                                \
    "the on-demand side (the reference): compute now, once the camera rests, every changed frame, or only when asked") \
  X(TruthNoise, "truth-noise", OnOff, "on|off",                                                         \
    "with the truth shown, also estimate its own noise: a second truth with another seed (twice the truth's time); the figures show its noise floor") \
  X(WindowShot, "window-shot", Png, "PATH.png", "the whole window as the user sees it (panel, status bar, overlays), drawn again without advancing time") \
  X(Inspect, "inspect", Pixel, "X Y", "print the pixel inspector's values of image pixel (X, Y), row 0 at the top, as one JSON line, and pin the inspector there (the first one draws one more frame: the debug image is written from then on)") \
  X(Magnifier, "magnifier", Zoom, "off|2..16", "the magnifier at the cursor (nearest filtering) at this zoom, or off") \
  X(Status, "status", None, "", "print the status bar's message, device, frame time, truth state, the figures (A vs B, A vs truth, the truth's noise floor), frame index, whether the history carried over (and why not) and scene time as one JSON line")

namespace ssr {

// The compare modes, declared once: the compare command, presets, the panel's radio buttons.
enum CompareMode : int { CompareOff = 0, CompareSplit = 1, CompareDiff = 2, CompareGrid = 3 };
struct CompareInfo {
  CompareMode mode;
  const char* name;   // as scripts and presets write it
  const char* label;  // the panel's
  const char* help;
};
inline constexpr CompareInfo kCompareModes[] = {
    {CompareOff, "off", "A only", "technique A alone"},
    {CompareSplit, "split", "split", "A left and B right of a divider you drag"},
    {CompareDiff, "diff", "difference", "|A - B| of the display values as a heat map"},
    {CompareGrid, "grid", "grid", "2x2 at a quarter of the image each: A, B, the truth, |A - truth|"},
};
// The named mode; throws InputError listing the names.
CompareMode parse_compare_mode(const std::string& name);
std::vector<std::string> compare_mode_names();

// The side panel's sections, declared once: the panel's headers, the `section` command, status.
enum PanelSection : int {
  SectionInspector, SectionScene, SectionLights, SectionTime, SectionView,
  SectionTechniqueA, SectionTechniqueB, SectionPresets, SectionTiming
};
struct SectionInfo {
  PanelSection section;
  const char* name;   // as scripts write it
  const char* label;  // the panel's header
  bool open_at_start;
};
inline constexpr SectionInfo kPanelSections[] = {
    {SectionInspector, "inspector", "pixel inspector", false},
    {SectionScene, "scene", "scene and camera", true},
    {SectionLights, "lights", "lights and environment", false},
    {SectionTime, "time", "time and camera paths", false},
    {SectionView, "view", "view and compare", true},
    {SectionTechniqueA, "technique-a", "technique A", true},
    {SectionTechniqueB, "technique-b", "technique B", true},  // drawn while comparing
    {SectionPresets, "presets", "presets", false},
    {SectionTiming, "timing", "timing", true},
};
inline constexpr std::size_t kPanelSectionCount = std::size(kPanelSections);
// The named section; throws InputError listing the names.
PanelSection parse_panel_section(const std::string& name);

// The form of a command's arguments (each checked before a script runs).
enum class ArgForm { None, Text, Technique, Number, NonNegative, Fraction, Count, Size, Compare, View, Assignment, Png, OnOff, TruthPolicy, Pixel, Zoom, PresetName, Section };

enum class Verb {
#define SSRLAB_X(id, verb, form, args, help) id,
  SSRLAB_VIEWER_COMMANDS(SSRLAB_X)
#undef SSRLAB_X
};

struct CommandInfo {
  Verb verb;
  const char* name;   // as scripts write it
  ArgForm form;
  const char* args;   // for the help: "NAME", "WxH", ...
  const char* help;   // one line; the help adds the names of a form with a table (kCompareModes ...)
};

inline constexpr CommandInfo kCommands[] = {
#define SSRLAB_X(id, verb, form, args, help) {Verb::id, verb, ArgForm::form, args, help},
    SSRLAB_VIEWER_COMMANDS(SSRLAB_X)
#undef SSRLAB_X
};
inline constexpr std::size_t kCommandCount = std::size(kCommands);

const CommandInfo& command_info(Verb verb);

struct ScriptCommand {
  int line = 0;                   // 1-based, for messages; 0 = not from a script (keys, UI)
  Verb verb = Verb::Frames;
  std::vector<std::string> args;  // already checked for count and form (two-word forms are one: "X Y")
};

// Parses and checks a script; `where` names it in messages ("script.txt").
std::vector<ScriptCommand> parse_viewer_script(const std::string& text, const std::string& where);
std::vector<ScriptCommand> load_viewer_script(const std::filesystem::path& path);

// "file:line: " prefix for an error raised while running `c`.
std::string script_where(const std::string& file, const ScriptCommand& c);

// The command list as the README's Markdown table (ssrlab-view --help-script).
std::string commands_markdown();

}  // namespace ssr
