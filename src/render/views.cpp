#include "render/views.h"

#include "core/errors.h"

namespace ssr {

const std::vector<ViewInfo>& view_table() {
  static const std::vector<ViewInfo> table = {
      {ViewMode::Final, "final", "composited colour, tone mapped", false},
      {ViewMode::Reflection, "reflection", "the technique's reflection rgb, tone mapped", false},
      {ViewMode::Confidence, "confidence", "the technique's reflection alpha, grey", false},
      {ViewMode::Lit, "lit", "lit colour without reflections, tone mapped", false},
      {ViewMode::Normal, "normal", "view-space normal * 0.5 + 0.5", false},
      {ViewMode::Depth, "depth", "linear view depth, near white -> far black (log scale)", false},
      {ViewMode::Albedo, "albedo", "linear albedo", false},
      {ViewMode::Roughness, "roughness", "perceptual roughness, grey", false},
      {ViewMode::Metallic, "metallic", "metallic, grey", false},
      {ViewMode::Mask, "mask", "reflective pixels white, planar reflectors tinted", false},
      {ViewMode::Steps, "steps", "tracer iterations per ray, heat map (0 .. 256+)", true},
      {ViewMode::Hits, "hits", "share of the pixel's rays that hit, grey", true},
      {ViewMode::Distance, "distance", "mean hit distance, heat map (0 .. 20 world units)", true},
      {ViewMode::Offsets, "offsets", "PPR: decoded offset to the source pixel as colour (0.5 = none)", true},
      {ViewMode::Holes, "holes", "PPR: red = hole before patching, yellow = still a hole after", true},
      {ViewMode::Reflected, "reflected", "the radiance the composite weights: mix(env, reflection, a)", false},
      {ViewMode::Motion, "motion", "motion vectors: hue = direction, brightness = length (16 px = full)", false},
      {ViewMode::Classes, "classify", "tile classification: black none, blue environment only, green traced, yellow reused", true},
      {ViewMode::Raw, "raw", "the trace's radiance before denoising (rgb * confidence), tone mapped", true},
      {ViewMode::RayLength, "ray-length", "mean hit length after spatial reuse, heat map (0 .. 20 world units)", true},
      {ViewMode::Spatial, "spatial", "after spatial reconstruction (rgb * confidence), tone mapped", true},
      {ViewMode::Temporal, "temporal", "after temporal accumulation (rgb * confidence), tone mapped", true},
      {ViewMode::Variance, "variance", "luminance variance estimate: sqrt as a heat map (0 .. 1)", true},
      {ViewMode::History, "history", "frames accumulated, heat map (0 .. 32)", true},
      {ViewMode::Iterations, "iterations", "telemetry: the pixel's trace iterations over all its rays, heat map (0 .. 128+)", true, true},
      {ViewMode::IdleLanes, "idle-lanes", "telemetry: the share of lane-iterations idle in the pixel's 32-lane warp, heat map (0 .. 1)", true, true},
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

ViewMode parse_view_mode(const std::string& name) {
  for (const ViewInfo& v : view_table())
    if (v.name == name) return v.mode;
  std::string known;
  for (const auto& n : view_mode_names()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("unknown view '" + name + "' (known: " + known + ").");
}

const ViewInfo& view_info(ViewMode mode) { return view_table().at(static_cast<std::size_t>(mode)); }

}  // namespace ssr
