#include "render/technique_api.h"

#include <algorithm>
#include <atomic>

#include "core/errors.h"

namespace ssr {

namespace {
const FrameSettings kDefaultSettings{};
}  // namespace

std::span<const ParamDesc> frame_settings_table() {
  static const std::vector<ParamDesc> table = {
      SSR_PARAM_FLOAT(FrameSettings, exposure, -20, 20, 0.1, "stops", "Exposure before tone mapping (0: as lit)."),
      SSR_PARAM_FLOAT(FrameSettings, reflective_f0, 0.001, 1, 0.01, "F0",
                      "Pixels whose largest F0 reaches this do reflection work (the reflective mask)."),
  };
  return table;
}

ParamSet frame_settings_params(FrameSettings& settings) {
  return ParamSet("frame", frame_settings_table(), &settings, &kDefaultSettings);
}

std::string frame_setting_option(const ParamDesc& d) {
  std::string name = std::string("--") + d.name;
  std::replace(name.begin(), name.end(), '_', '-');
  return name;
}

void set_frame_setting(FrameSettings& settings, const std::string& key, double value, const std::string& option) {
  ParamSet p = frame_settings_params(settings);
  const int i = p.find(key);
  if (i < 0) throw InputError("unknown frame setting '" + key + "'.");
  try {
    p.set(static_cast<std::size_t>(i), value);
  } catch (const InputError& e) {
    // The table's sentence, naming what the user typed: "--exposure must be in [-20, 20], got inf."
    const std::string named = "parameter '" + p.key(static_cast<std::size_t>(i)) + "'", what = e.what();
    if (option.empty() || what.rfind(named, 0) != 0) throw;
    throw InputError(option + what.substr(named.size()));
  }
}

Technique::Technique() {
  static std::atomic<std::uint64_t> next{1};
  instance_id_ = next++;
}

}  // namespace ssr
