// Running the two sides on the same frame inputs, composing what the image area shows (A alone,
// A | B, or |A - B|), the A-vs-B figure (the shared metric code over compare's pixels), and the
// truth's state: an on-demand side whose image belongs to another frame is stale, and no figure
// computed from it is shown.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gl/gl.h"
#include <GLFW/glfw3.h>

#include "core/errors.h"
#include "eval/grid.h"
#include "eval/metrics.h"
#include "eval/runner.h"
#include "gl/readback.h"
#include "reference/reference.h"
#include "registry/registry.h"
#include "shared/bindings.h"
#include "viewer/viewer.h"

namespace ssr {

namespace {

// What a technique's image depends on besides the frame inputs: its name and parameter values,
// and for a technique whose image changes every frame (TechniqueDecl::varies_per_frame: new
// samples, accumulating history) the frame itself, so that the PSNR follows it as it settles.
std::string technique_key(Technique& t, int frame_index) {
  std::string k = t.name();
  ParamSet p = t.params();
  for (std::size_t i = 0; i < p.size(); ++i) k += "," + p.to_string(i);
  if (t.declare().varies_per_frame) k += "|frame " + std::to_string(frame_index);
  return k;
}


}  // namespace

FrameRequest Viewer::current_frame() const {
  return FrameRequest(camera_.camera(), FrameTime{frame_index_, time_, cut_});
}

std::string Viewer::inputs_key() const {
  const Camera& c = camera_.camera();
  char buf[320];
  // reflective_f0 decides which pixels reflect: the truth and the figures follow it.
  std::snprintf(buf, sizeof buf, "%llu|%d|%g %g %g|%g %g %g|%g|%g|%dx%d|%g",
                static_cast<unsigned long long>(renderer_->scene_id()), lighting_revision_, c.position.x,
                c.position.y, c.position.z, c.target.x, c.target.y, c.target.z, c.fov_y_deg,
                renderer_->settings.reflective_f0, render_w(), render_h(), time_);
  return buf;
}

std::string Viewer::frame_key() const {
  char buf[64];
  std::snprintf(buf, sizeof buf, "|%d|%g", view_, renderer_->settings.exposure);
  return inputs_key() + buf;
}

// Techniques too slow to run every frame (CPU ray tracing) run when asked: the registry's flag.
bool Viewer::on_demand(int i) const { return technique_info(sides_[i].technique->name()).on_demand; }

// The grid's truth: the registry's truth technique, made when the grid is first shown.
void Viewer::ensure_grid_truth() {
  if (compare_ == CompareGrid && !sides_[2].technique) set_technique(sides_[2], truth_name());
}

int Viewer::active_sides() const { return compare_ == CompareOff ? 1 : compare_ == CompareGrid ? 3 : 2; }

bool Viewer::side_current(int i) const {
  const Side& s = sides_[i];
  return s.valid && s.shown_key == frame_key() + "|" + technique_key(*s.technique, frame_index_);
}

std::string Viewer::side_state(int i) const {
  const Side& s = sides_[i];
  return s.request > 0 ? "computing" : side_current(i) ? "current" : s.computed ? "stale" : "not computed";
}

std::string Viewer::truth_state() const {
  const int n = active_sides();
  std::string state = "none";
  for (int i = 0; i < n; ++i) {
    if (!on_demand(i)) continue;
    if (sides_[i].request > 0) return "computing";
    state = side_state(i);
  }
  return state;
}

bool Viewer::figure_shown() const {
  return compare_ != CompareOff && view_ == VIEW_FINAL && psnr_valid_ && side_current(0) && side_current(1);
}

bool Viewer::truth_figure_shown() const {
  return figure_shown() && compare_ == CompareGrid && psnr_truth_valid_ && side_current(2);
}

PixelValues Viewer::inspect(int x, int y) const {
  if (x < 0 || y < 0 || x >= image_w_ || y >= image_h_ || !composed_)
    throw InputError("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                     std::to_string(image_w_) + "x" + std::to_string(image_h_) + " image.");
  if (compare_ == CompareGrid) {  // the cell's own pixel (each cell is a frame of its own)
    // An odd size's last column or row belongs to no cell (checked before wrapping: column 640
    // of a 641-wide grid read pixel 0).
    if (x >= 2 * render_w() || y >= 2 * render_h()) throw InputError("the grid has no cell at that pixel.");
    x %= std::max(render_w(), 1);
    y %= std::max(render_h(), 1);
  }
  const int n = active_sides();
  SideImages images[3];
  std::optional<int> truth;
  const std::vector<PixelClass>* classes = nullptr;
  for (int i = 0; i < n; ++i) {
    const Side& s = sides_[i];
    const std::vector<ViewMode> d = s.technique->declare().debug_views;
    images[i] = {s.technique->name(), &s.color, &s.copy, s.has_debug ? &s.debug : nullptr,
                 std::find(d.begin(), d.end(), ViewMode::Offsets) != d.end()};
    if (on_demand(i) && side_current(i)) {
      truth = i;
      classes = reference_outputs(*s.technique).classes;
    }
  }
  if (!classes && mask_ref_ && mask_key_ == inputs_key()) classes = reference_outputs(*mask_ref_).classes;
  PixelValues j = inspect_pixel(*renderer_, x, y, images, n, classes, truth);
  for (int i = 0; i < n; ++i) j[side_key(i)]["current"] = side_current(i);
  return j;
}

// Runs the reference of the mask on demand (or in scripted runs) and turns its classes into an image.
void Viewer::update_traceable_mask() {
  const std::string key = inputs_key();  // the classes do not depend on the exposure
  if (mask_key_ == key || !(mask_request_ || scripted_)) return;
  mask_request_ = false;
  if (!mask_ref_) {
    mask_ref_ = create_technique(truth_name());
    mask_ref_->load(renderer_->shaders());
    set_reference_progress(*mask_ref_, [this](double f) { draw_progress("traceable mask", f); });
  }
  renderer_->render(current_frame(), *mask_ref_, ViewMode::Final, nullptr);
  const ReferenceOutputs out = reference_outputs(*mask_ref_);
  const int w = render_w(), h = render_h();
  RgbaImage8 im = class_map(*out.classes, w, h);
  gl::flip_rows(im.pixels, w, h, 4);  // texture rows go bottom-up
  mask_tex_ = gl::Texture2D("viewer traceable mask", GL_RGBA8, w, h);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(mask_tex_.id(), 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, im.pixels.data());
  mask_key_ = key;
}

void Viewer::take_times(Side& s) {
  for (const gl::FrameTimes& t : s.timer->completed()) {
    s.history.push_back(static_cast<float>(technique_ms(t)));
    while (s.history.size() > 120) s.history.pop_front();
  }
  if (!s.timer->completed().empty()) s.last_times = s.timer->completed().back();
  s.timer->completed().clear();
}

void Viewer::render(bool advance) {
  const bool grid = compare_ == CompareGrid;
  const int W = image_w_, H = image_h_, w = render_w(), h = render_h();
  if (w <= 0 || h <= 0) return;
  renderer_->resize(w, h);
  if (advance) {
    ++frame_index_;  // every drawn frame is the next one of a sequence: history carries
    advance_time();
    cut_ = cut_next_;
    cut_next_ = false;
  }
  if (!view_offered(view_)) {  // the technique changed: its debug view is gone
    const std::string name = view_names_[static_cast<std::size_t>(view_)];
    set_status(compare_ == CompareGrid   ? "the grid shows final images (its truth has no view '" + name + "'): final image"
               : compare_ == CompareDiff ? "the difference needs view '" + name + "' from both sides: final image"
                                         : "view '" + name + "' is not filled by the technique now shown: final image",
               true);
    view_ = VIEW_FINAL;
  }
  if (!composed_ || composed_.width() != W || composed_.height() != H) {
    composed_ = gl::Texture2D("viewer composed", GL_RGBA8, W, H);
    glTextureParameteri(composed_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // the magnifier shows pixels
    glTextureParameteri(composed_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  for (Side& s : sides_) {
    if (s.copy && s.copy.width() == w && s.copy.height() == h) continue;
    s.copy = gl::Texture2D("viewer side copy", GL_RGBA8, w, h);
    s.color = gl::Texture2D("viewer side colour", GL_RGBA16F, w, h);
    s.debug = gl::Texture2D("viewer side debug", GL_RGBA16F, w, h);
    const std::uint8_t black[4] = {0, 0, 0, 255};
    glClearTexImage(s.copy.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, black);
    s.valid = false;
    s.shown_key.clear();
    psnr_valid_ = false;
    psnr_key_.clear();
  }
  const std::uint8_t black[4] = {0, 0, 0, 255};
  if (grid) glClearTexImage(composed_.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, black);  // an odd size's last row and column
  if (view_ == kViewTraceable) {
    update_traceable_mask();
    if (mask_tex_.width() == w && mask_tex_.height() == h)
      glCopyImageSubData(mask_tex_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, composed_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, w, h, 1);
    return;
  }
  const std::string fkey = frame_key(), ikey = inputs_key();
  const bool rested = glfwGetTime() - last_moved_ >= kRestSeconds && !playing_;
  const int n_sides = active_sides();
  renderer_->debug_outputs = section_open_[SectionInspector] || inspected_;
  // The display pass wrote with imageStore: the side keeps its image.
  const auto keep_display = [&](Side& s) {
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    glCopyImageSubData(renderer_->display().id(), GL_TEXTURE_2D, 0, 0, 0, 0, s.copy.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       w, h, 1);
  };
  for (int i = 0; i < n_sides; ++i) {
    Side& s = sides_[i];
    if (!side_fills_view(i, view_)) {
      // A view this side's technique does not produce: a plain grey half, which the overlay
      // labels (the display pass would show the debug image's leftovers), and nothing to run.
      const std::uint8_t grey[4] = {48, 48, 48, 255};
      glClearTexImage(s.copy.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, grey);
      continue;
    }
    const std::string tkey = technique_key(*s.technique, frame_index_);
    const std::string key = fkey + "|" + tkey;
    if (!advance && s.valid && s.shown_key == key) continue;  // drawn again: already current
    if (on_demand(i) && s.valid && s.request == 0 && view_ == VIEW_FINAL && s.ran_key == ikey + "|" + tkey) {
      // Only the exposure or the view moved: the reference's image is displayed again from its
      // colour, not traced again (1.5 s at 640x360 on llvmpipe, and a STALE banner meanwhile).
      renderer_->display_color(s.color);
      keep_display(s);
      s.shown_key = key;
      continue;
    }
    // On-demand techniques run when asked, once the camera rests (auto), on every changed frame
    // (live, and in scripted runs). One frame says "computing" first.
    if (on_demand(i) && s.request == 0 && s.shown_key != key && truth_policy_ == TruthPolicy::Rest && rested)
      s.request = 2;
    if (s.request == 2) {
      s.request = 1;
      continue;
    }
    const bool run_it = !on_demand(i) || s.request == 1 || (truth_policy_ == TruthPolicy::Live && s.shown_key != key);
    if (!run_it) continue;
    s.request = 0;
    // The telemetry views show an instrumented build's counts (its timings then include them).
    const bool telemetry = view_ < static_cast<int>(view_table().size()) &&
                           view_table()[static_cast<std::size_t>(view_)].telemetry;
    if (telemetry != s.instrumented) {
      s.technique->load(telemetry ? renderer_->shaders().with_defines({"SSR_TELEMETRY"}) : renderer_->shaders());
      s.instrumented = telemetry;
    }
    if (telemetry) renderer_->telemetry().begin(w, h);
    s.timer->begin_frame();
    // The inputs render once a frame: the second side's render() finds them current.
    renderer_->render(current_frame(), *s.technique, static_cast<ViewMode>(view_), s.timer.get());
    s.timer->end_frame();
    keep_display(s);
    glCopyImageSubData(renderer_->color().id(), GL_TEXTURE_2D, 0, 0, 0, 0, s.color.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       w, h, 1);
    s.has_debug = renderer_->debug_written();
    if (s.has_debug)
      glCopyImageSubData(renderer_->debug().id(), GL_TEXTURE_2D, 0, 0, 0, 0, s.debug.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                         w, h, 1);
    s.valid = s.computed = true;
    s.shown_key = key;
    s.ran_key = ikey + "|" + tkey;
    take_times(s);
  }
  // Compose A | B (split), the heat map (difference), the grid, or A alone.
  auto diff_into = [&](const gl::Texture2D& a, const gl::Texture2D& b, const gl::Texture2D& out) {
    glUseProgram(diff_prog_.id());
    glBindTextureUnit(TEX_DIFF_A, a.id());
    glBindTextureUnit(TEX_DIFF_B, b.id());
    glBindImageTexture(IMG_DIFF_OUT, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glUniform1f(0, diff_scale_);
    diff_prog_.dispatch_2d(out.width(), out.height());
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindTextureUnit(TEX_DIFF_A, 0);
    glBindTextureUnit(TEX_DIFF_B, 0);
  };
  auto copy_to = [&](const gl::Texture2D& from, int x, int y) {  // (x, y): GL texel of the cell's corner
    glCopyImageSubData(from.id(), GL_TEXTURE_2D, 0, 0, 0, 0, composed_.id(), GL_TEXTURE_2D, 0, x, y, 0, w, h, 1);
  };
  if (compare_ == CompareDiff) {
    diff_into(sides_[0].copy, sides_[1].copy, composed_);
  } else if (grid) {
    // A | B on top, truth | |A - truth| below (texture rows go up: the top cells start at H - h).
    if (!grid_diff_ || grid_diff_.width() != w || grid_diff_.height() != h)
      grid_diff_ = gl::Texture2D("viewer grid difference", GL_RGBA8, w, h);
    diff_into(sides_[0].copy, sides_[2].copy, grid_diff_);
    copy_to(sides_[0].copy, 0, H - h);
    copy_to(sides_[1].copy, w, H - h);
    copy_to(sides_[2].copy, 0, H - 2 * h);
    copy_to(grid_diff_, w, H - 2 * h);
  } else {
    copy_to(sides_[0].copy, 0, 0);
    const int x0 = std::clamp(static_cast<int>(std::lround(split_ * static_cast<float>(w))), 0, w);
    if (compare_ == CompareSplit && x0 < w)
      glCopyImageSubData(sides_[1].copy.id(), GL_TEXTURE_2D, 0, x0, 0, 0, composed_.id(), GL_TEXTURE_2D, 0, x0, 0, 0,
                         w - x0, h, 1);
  }
  // PSNR of A vs B, on the CPU, whenever either image changed, from the current frame only.
  if (compare_ != CompareOff && side_current(0) && side_current(1)) {
    const bool truth = grid && side_current(2);
    const std::string key = sides_[0].shown_key + "#" + sides_[1].shown_key + (truth ? "#" + sides_[2].shown_key : "");
    if (key != psnr_key_) {
      // The shared metric code over compare's pixels: the final image's display values on the
      // reflective and glass pixels of this frame's G-buffer (both sides ran on it: the key holds
      // the frame).
      std::optional<double> p;
      psnr_truth_valid_ = false;
      if (view_ == VIEW_FINAL) {
        const float exposure = renderer_->settings.exposure;
        const RgbaImageF a = display_values(renderer_->read_texture(sides_[0].color), exposure);
        const std::vector<bool> scored = scored_pixels(*renderer_);
        p = psnr_where(a, display_values(renderer_->read_texture(sides_[1].color), exposure), scored);
        if (truth) {
          const std::optional<double> t =
              psnr_where(a, display_values(renderer_->read_texture(sides_[2].color), exposure), scored);
          psnr_truth_valid_ = t.has_value();
          psnr_truth_ = t.value_or(0.0);
        }
      }
      psnr_valid_ = p.has_value();
      psnr_ = p.value_or(0.0);
      psnr_key_ = key;
      if (p && std::isfinite(*p)) {
        psnr_history_.push_back(static_cast<float>(std::min(*p, kPsnrCap)));
        while (psnr_history_.size() > 300) psnr_history_.pop_front();
      }
    }
  } else {
    psnr_valid_ = psnr_truth_valid_ = false;
    psnr_key_.clear();
  }
  update_truth_noise();
}

// The truth side shown and current (A, B or the grid's), or -1.
int Viewer::current_truth_side() const {
  for (int i = 0; i < active_sides(); ++i)
    if (on_demand(i) && side_current(i)) return i;
  return -1;
}

// The truth side whose noise floor is estimated (truth-noise on), or -1: only where the figures
// are (a compare mode, the final view), since nothing else shows the floor.
int Viewer::noise_truth_side() const {
  return truth_noise_ && compare_ != CompareOff && view_ == VIEW_FINAL ? current_truth_side() : -1;
}

void Viewer::update_truth_noise() {
  const int t = noise_truth_side();
  if (t < 0) return;
  const Side& s = sides_[t];
  if (noise_shown_key_ == s.shown_key && noise_ran_key_ == s.ran_key) return;
  if (noise_ran_key_ != s.ran_key) {
    // The truth's settings with compare's second seed. One reference serves every truth, so its
    // program is built once and its BVH once a scene, as the mask's are.
    if (!noise_truth_) {
      noise_truth_ = create_technique(truth_name());
      noise_truth_->load(renderer_->shaders());
      set_reference_progress(*noise_truth_, [this](double f) { draw_progress("truth noise", f); });
    }
    set_up_with_seed(*s.technique, *noise_truth_, kTruthNoiseSeedShift);
    renderer_->render(current_frame(), *noise_truth_, ViewMode::Final, nullptr);
    noise_color_ = renderer_->read_texture(renderer_->color());
    noise_ran_key_ = s.ran_key;
  }
  // Over the figures' pixels, with this exposure.
  const float exposure = renderer_->settings.exposure;
  noise_psnr_ = noise_floor_psnr(rmse_where(display_values(renderer_->read_texture(s.color), exposure),
                                            display_values(noise_color_, exposure), scored_pixels(*renderer_)));
  noise_shown_key_ = s.shown_key;
}

std::optional<double> Viewer::truth_noise_shown() const {
  const int t = noise_truth_side();
  if (t < 0 || sides_[t].shown_key != noise_shown_key_ || sides_[t].ran_key != noise_ran_key_) return std::nullopt;
  return noise_psnr_;
}

}  // namespace ssr
