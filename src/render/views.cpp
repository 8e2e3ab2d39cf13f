#include "render/views.h"

#include "core/errors.h"
#include "shared/colormap.h"

namespace ssr {

namespace {

Legend grey(float full, const char* unit) { return {Legend::Grey, full, unit, {}}; }
Legend heat(float full, const char* unit) { return {Legend::Heat, full, unit, {}}; }
Legend encoded() { return {Legend::Encoded, 1.0f, "", {}}; }
Legend swatches(std::vector<Legend::Swatch> s) { return {Legend::Swatches, 1.0f, "", std::move(s)}; }
Legend::Swatch swatch(const char* name, glm::vec3 c) { return {name, c.x, c.y, c.z}; }

}  // namespace

const std::vector<ViewInfo>& view_table() {
  static const std::vector<ViewInfo> table = {
      {ViewMode::Final, "final", "composited colour, tone mapped", false},
      {ViewMode::Reflection, "reflection", "the technique's reflection rgb, tone mapped", false},
      {ViewMode::Confidence, "confidence", "the technique's reflection alpha, grey", false, false, grey(1.0f, "confidence")},
      {ViewMode::Lit, "lit", "lit colour without reflections, tone mapped", false},
      {ViewMode::Normal, "normal", "view-space normal * 0.5 + 0.5", false, false, encoded()},
      {ViewMode::Depth, "depth", "linear view depth, near white -> far black (log scale)", false, false, encoded()},
      {ViewMode::Albedo, "albedo", "linear albedo", false, false, encoded()},
      {ViewMode::Roughness, "roughness", "perceptual roughness, grey", false, false, grey(1.0f, "roughness")},
      {ViewMode::Metallic, "metallic", "metallic, grey", false, false, grey(1.0f, "metallic")},
      {ViewMode::Mask, "mask", "reflective pixels white, planar reflectors tinted", false, false,
       swatches({swatch("not reflective", shared::mask_colour(false, false)), swatch("reflective", shared::mask_colour(true, false)),
                 swatch("planar reflector", shared::mask_colour(true, true))})},
      {ViewMode::Steps, "steps", "tracer iterations per ray, heat map (0 .. 256+)", true, false, heat(HEAT_STEPS_FULL, "iterations/ray")},
      {ViewMode::Hits, "hits", "share of the pixel's rays that hit, grey", true, false, grey(1.0f, "of rays hit")},
      {ViewMode::Distance, "distance", "mean hit distance, heat map (0 .. 20 world units; black: no hit)", true, false, heat(HEAT_DISTANCE_FULL, "world units")},
      {ViewMode::Offsets, "offsets", "PPR: decoded offset to the source pixel as colour (0.5 = none)", true, false, encoded()},
      {ViewMode::Holes, "holes", "PPR: red = a hole patched from a neighbour, green = projection refused (to the fallback), yellow = no source (fallback or environment)", true, false,
       swatches({swatch("projected", {0, 0, 0}), swatch("patched hole", {1, 0, 0}),
                 swatch("refused (fallback)", {0, 1, 0}), swatch("no source", {1, 1, 0})})},
      {ViewMode::Reflected, "reflected", "the radiance the composite weights: mix(env, reflection, a)", false},
      {ViewMode::Motion, "motion", "motion vectors: hue = direction, brightness = length (16 px = full)", false, false, encoded()},
      {ViewMode::Classes, "classify", "tile classification: black none, blue environment only, green traced, yellow reused", true, false,
       swatches({swatch("none", shared::tile_class_colour(0)), swatch("environment", shared::tile_class_colour(1)),
                 swatch("traced", shared::tile_class_colour(2)), swatch("reused", shared::tile_class_colour(3))})},
      {ViewMode::Raw, "raw", "the trace's radiance before denoising (rgb * confidence), tone mapped", true},
      {ViewMode::RayLength, "ray-length", "mean hit length after spatial reuse, heat map (0 .. 20 world units; black: no hit)", true, false, heat(HEAT_DISTANCE_FULL, "world units")},
      {ViewMode::Spatial, "spatial", "after spatial reconstruction (rgb * confidence), tone mapped", true},
      {ViewMode::Temporal, "temporal", "after temporal accumulation (rgb * confidence), tone mapped", true},
      {ViewMode::Variance, "variance", "luminance variance estimate: sqrt as a heat map (0 .. 1)", true, false, heat(1.0f, "std. dev. (luminance)")},
      {ViewMode::History, "history", "frames accumulated, heat map (0 .. 32)", true, false, heat(HEAT_HISTORY_FULL, "frames")},
      {ViewMode::Iterations, "iterations", "telemetry: the pixel's trace iterations over all its rays, heat map (0 .. 128+)", true, true,
       heat(HEAT_ITERATIONS_FULL, "iterations")},
      {ViewMode::IdleLanes, "idle-lanes", "telemetry: the share of lane-iterations idle in the pixel's 32-lane warp, heat map (0 .. 1)", true, true,
       heat(1.0f, "idle share")},
  };
  return table;
}

const std::vector<std::string>& view_mode_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const ViewInfo& v : view_table()) n.push_back(v.name);
    return n;
  }();
  return names;
}

ViewMode parse_view_mode(const std::string& name, const std::vector<std::string>& also_known) {
  for (const ViewInfo& v : view_table())
    if (v.name == name) return v.mode;
  std::string known;
  for (const auto* list : {&view_mode_names(), &also_known})
    for (const auto& n : *list) known += (known.empty() ? "" : ", ") + n;
  throw InputError("unknown view '" + name + "' (known: " + known + ").");
}

const ViewInfo& view_info(ViewMode mode) { return view_table().at(static_cast<std::size_t>(mode)); }

}  // namespace ssr
