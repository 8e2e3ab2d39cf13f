#include "reference/reference.h"

#include "gl/readback.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <string>
#include <thread>

#include <glm/gtc/matrix_access.hpp>

#include "core/errors.h"
#include "reference/embree_scene.h"
#include "render/gpu_scene.h"
#include "shared/bindings.h"
#include "shared/reference.h"
#include "shared/reference_params.h"
#include "shared/sampling.h"

namespace ssr {

namespace {

using P = shared::ReferenceParams;
const ParamDesc kTable[] = {
    SSR_PARAM_INT(P, samples, 1, 4096, "rays", "GGX VNDF samples per rough pixel; mirror pixels trace one ray."),
    SSR_PARAM_INT(P, seed, 0, 1000000, "", "Random seed of the samples: the same seed gives the same image."),
    SSR_PARAM_FLOAT(P, mirror_roughness, 0.0, 1.0, 0.001, "",
                    "Pixels with a perceptual roughness below this trace a single mirror ray."),
    SSR_PARAM_FLOAT(P, depth_tolerance, 0.0001, 0.5, 0.001, "relative",
                    "A true hit counts as visible on screen when the depth buffer there is within this relative distance."),
    SSR_PARAM_INT(P, bounces, 1, 8, "segments",
                  "Reflection bounces: 1 shades hits with direct and ambient light only (a mirror seen in a mirror is "
                  "black); N follows reflective hits (reflector or F0 above the frame's threshold) N-1 more times."),
};

// Samples per GPU batch: bounds the upload to ~256 MiB whatever the size and sample count.
constexpr std::size_t kMaxBatchSamples = std::size_t(4) << 20;

}  // namespace

class ReferenceTechnique final : public TechniqueWithParams<P> {
 public:
  ReferenceTechnique() : TechniqueWithParams("reference", kTable) {}

  void load(const gl::ShaderSource& src) override {
    program_ = gl::Program::compute(src, "reference/shade.comp");
  }

  // Its truth goes to the reflection and (glass pixels) refraction targets; the ideal and the
  // classes are outputs of its own (reference_outputs).
  TechniqueDecl declare() const override {
    TechniqueDecl d;
    d.reads = kReadGBuffer | kReadLit | kReadGlass;
    d.writes_refraction = true;
    return d;
  }
  void run(const FrameContext& in) override;

  ReferenceOutputs outputs() const { return {&ideal_, &ideal_refraction_, &classes_, rays_}; }
  std::function<void(double)> progress;

 private:
  gl::Program program_;
  std::uint64_t bvh_geometry_ = 0;  // FrameContext::geometry_id the BVH was built for
  std::unique_ptr<EmbreeScene> bvh_;
  gl::Texture2D ideal_, ideal_refraction_;
  std::vector<PixelClass> classes_;
  std::size_t rays_ = 0;
};

std::unique_ptr<Technique> make_reference_technique() { return std::make_unique<ReferenceTechnique>(); }

void set_reference_progress(Technique& t, std::function<void(double)> progress) {
  if (auto* r = dynamic_cast<ReferenceTechnique*>(&t)) r->progress = std::move(progress);
}

ReferenceOutputs reference_outputs(const Technique& t) {
  if (auto* r = dynamic_cast<const ReferenceTechnique*>(&t)) return r->outputs();
  return {};
}

void ReferenceTechnique::run(const FrameContext& in) {
  const gl::Texture2D& reflection = *in.reflection;
  gl::ScopedPass pass(in.timer, "reference");
  const Scene& scene = in.scene;
  if (!bvh_ || bvh_geometry_ != in.geometry_id) {
    bvh_.reset();
    bvh_ = std::make_unique<EmbreeScene>(scene);
    bvh_geometry_ = in.geometry_id;
  }
  const int w = in.width, h = in.height;
  const std::size_t npx = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);

  // --- read the G-buffer back (GL convention: row 0 at the bottom) --------------------------
  using gl::Rows;
  const std::vector<float> depth = gl::read_texture<float>(in.gbuffer.depth, GL_DEPTH_COMPONENT, GL_FLOAT, 1, Rows::GlOrder);
  const std::vector<float> normal_rough = gl::read_texture<float>(in.gbuffer.normal_roughness, GL_RGBA, GL_FLOAT, 4, Rows::GlOrder);
  // reflector id, reflectance, flags, object id
  const std::vector<std::uint16_t> material =
      gl::read_texture<std::uint16_t>(in.gbuffer.material, GL_RGBA_INTEGER, GL_UNSIGNED_SHORT, 4, Rows::GlOrder);

  const CameraMatrices& m = in.matrices;
  const glm::dmat4 inv_proj = glm::inverse(glm::dmat4(m.proj));
  const glm::dmat4 inv_view = glm::inverse(glm::dmat4(m.view));
  const glm::dmat4 view = glm::dmat4(m.view);
  const glm::dmat4 view_proj = glm::dmat4(m.proj) * view;
  const glm::dvec3 eye = glm::dvec3(inv_view[3]);
  const double proj_a = m.proj[2][2], proj_b = m.proj[3][2];
  // Ray cone: the angle one pixel subtends, for texture filtering at the hits.
  const double pixel_angle = 2.0 / (static_cast<double>(m.proj[1][1]) * h);

  auto view_z_at = [&](int x, int y) {  // view-space z of the depth buffer; +inf for background
    const double d = depth[static_cast<std::size_t>(y) * w + x];
    return d <= 0.0 ? std::numeric_limits<double>::infinity() : -proj_b / (d + proj_a);
  };

  // Traceable: the hit projects on screen, and the pixel there shows the same object at the
  // hit's depth. Depth alone is not enough: where an object stands on a mirror, the floor in
  // front of its base is within the tolerance of the base's depth, and the screen-space ideal
  // would read the floor. `own_reflector` (a mesh index, or -1) is never its own reflection.
  // `hp` gets the hit's pixel (GL convention).
  auto visible_on_screen = [&](const RayHit& hit, int own_reflector, glm::vec2& hp) {
    const glm::dvec4 clip = view_proj * glm::dvec4(glm::dvec3(hit.position), 1.0);
    if (clip.w <= 1e-9) return false;
    const glm::dvec2 uv = glm::dvec2(clip) / clip.w * 0.5 + 0.5;
    if (!(uv.x >= 0 && uv.x < 1 && uv.y >= 0 && uv.y < 1)) return false;
    const int hx = std::min(static_cast<int>(uv.x * w), w - 1);
    const int hy = std::min(static_cast<int>(uv.y * h), h - 1);
    hp = glm::vec2(hx, hy);
    const double z_hit = (view * glm::dvec4(glm::dvec3(hit.position), 1.0)).z;
    const std::size_t j = static_cast<std::size_t>(hy) * w + hx;
    const bool same_object = depth[j] > 0.0f && material[j * 4 + 3] == hit.mesh;
    return same_object && hit.mesh != own_reflector &&
           std::abs(view_z_at(hx, hy) - z_hit) <= params_.depth_tolerance * std::abs(z_hit) + 1e-4;
  };

  // --- per pixel: its samples -------------------------------------------------------------------
  std::vector<std::size_t> pixel_start(npx + 1, 0);  // 8K x 4096 samples overflows int
  for (std::size_t i = 0; i < npx; ++i) {
    const bool reflective = depth[i] > 0.0f && (material[i * 4 + 2] & MATERIAL_FLAG_REFLECTIVE);
    const float rough = std::clamp(normal_rough[i * 4 + 3], 0.0f, 1.0f);
    const int n = !reflective ? 0 : (rough < params_.mirror_roughness ? 1 : params_.samples);
    pixel_start[i + 1] = pixel_start[i] + static_cast<std::size_t>(n);
  }
  const std::size_t total = pixel_start[npx];
  rays_ = total;
  std::vector<std::uint8_t> cls(npx, static_cast<std::uint8_t>(PixelClass::NotReflective));
  // Rows [batch_y0, batch_y1) are traced into `samples` (indexed from batch_first), shaded on
  // the GPU, and dropped: memory stays bounded at any size and sample count.
  int batch_y0 = 0, batch_y1 = 0;
  std::size_t batch_first = 0;
  std::vector<shared::ReferenceSample> samples;

  // Multi-bounce truth: `bounces` segments a sample, segment 0 the reflection ray itself. A hit
  // on a reflective surface (a reflector, or F0 at the frame's threshold, as the G-buffer marks
  // reflective pixels) continues along its own reflection, so the GPU can shade it with what
  // it reflects: L = shade(hit) + specular_weight * L(next segment).
  const std::size_t bounces = static_cast<std::size_t>(params_.bounces);
  std::vector<bool> reflective_mesh(scene.meshes.size());
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const glm::vec3 f0 = material_f0(scene.materials[static_cast<std::size_t>(scene.meshes[m].material)]);
    reflective_mesh[m] = scene.meshes[m].reflector > 0 ||
                         std::max({f0.x, f0.y, f0.z}) >= in.settings.reflective_f0;
  }
  // Writes a ray's hit into its segment: position and material, the shading normal with the
  // ray cone's texture footprint (`cone_width`: the cone's width at the hit, world units), uv
  // and tangent. The hit's pixel (segment 0 only) is the caller's.
  auto record_hit = [&](shared::ReferenceSample& s, const RayHit& hit, double cone_width) {
    s.position = glm::vec4(hit.position, static_cast<float>(scene.meshes[static_cast<std::size_t>(hit.mesh)].material));
    const double footprint = cone_width / std::max(static_cast<double>(hit.cos_incidence), 0.05) *
                             static_cast<double>(hit.uv_density);
    s.normal = glm::vec4(hit.normal, static_cast<float>(std::log2(std::max(footprint, 1e-30))));
    s.hit_pixel = glm::vec4(0, 0, hit.uv);
    s.tangent = hit.tangent;
  };
  auto follow_bounces = [&](RayHit hit, glm::vec3 dir, double dist, shared::ReferenceSample* seg, unsigned x,
                            unsigned y, unsigned k) {
    for (std::size_t b = 1; b < bounces; ++b) {
      if (!reflective_mesh[static_cast<std::size_t>(hit.mesh)]) return;
      const Material& mt = scene.materials[static_cast<std::size_t>(scene.meshes[static_cast<std::size_t>(hit.mesh)].material)];
      glm::vec3 next = glm::reflect(dir, hit.normal);
      if (mt.roughness >= params_.mirror_roughness) {
        const glm::vec2 xi = shared::sample_xi(x, y, k + 0x10000u * static_cast<unsigned>(b),
                                               static_cast<unsigned>(params_.seed));
        const glm::vec3 g = shared::sample_reflection(hit.normal, -dir, mt.roughness, xi);
        if (glm::dot(g, hit.normal) > 0.0f) next = g;
      }
      next = glm::normalize(next);
      const glm::dvec3 p(hit.position);
      const double mag = std::max({1.0, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
      const glm::vec3 origin = glm::vec3(p + glm::dvec3(hit.normal) * (4e-6 * mag + 1e-5 * dist));
      const RayHit nh = bvh_->trace(origin, next);
      shared::ReferenceSample& s = seg[b];
      s.direction = glm::vec4(next, 0.0f);
      if (!nh.hit) {
        s.position = glm::vec4(0, 0, 0, -1);
        return;
      }
      dist += nh.t;
      record_hit(s, nh, pixel_angle * dist);
      hit = nh;
      dir = next;
    }
  };
  // An unused segment (the path ended before it) adds nothing.
  auto unused_segment = [] {
    shared::ReferenceSample s{};
    s.position = glm::vec4(0, 0, 0, -2);
    return s;
  };

  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::atomic<int> next_row{0};
  auto worker = [&] {
    for (int y; (y = next_row.fetch_add(1)) < batch_y1;) {
      for (int x = 0; x < w; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * w + x;
        const int n = static_cast<int>(pixel_start[i + 1] - pixel_start[i]);
        if (n == 0) continue;
        const glm::dvec4 ndc((x + 0.5) / w * 2 - 1, (y + 0.5) / h * 2 - 1, depth[i], 1.0);
        glm::dvec4 pv = inv_proj * ndc;
        pv /= pv.w;
        glm::dvec3 p_ws = glm::dvec3(inv_view * pv);
        // Depth from a GPU rasterizer is not exact: NVIDIA's reversed-Z D32F was measured off
        // llvmpipe's by 8.6e-7 on gallery's floor and by 5e-6 (2.4e-3 relative) at
        // hard-grazing's horizon, which put points under the floor, so that mirror rays hit
        // the floor itself. The eye ray through the pixel centre (where the rasterizer
        // sampled too) finds the surface exactly. It is taken where it agrees with the depth
        // to 2% and hits the object the G-buffer shows; elsewhere (a silhouette the two see
        // differently, e.g. a mirror's border with its frame 1 cm behind) the depth's point stays.
        RayHit primary;
        {
          const glm::dvec3 to_p = p_ws - eye;
          const double dist = glm::length(to_p);
          primary = bvh_->trace(glm::vec3(eye), glm::vec3(to_p / dist), 0.0f);
          primary.hit = primary.hit && primary.mesh == material[i * 4 + 3] &&
                        std::abs(static_cast<double>(primary.t) - dist) <= 0.02 * dist + 1e-4;
          if (primary.hit) p_ws = glm::dvec3(primary.position);
        }
        glm::dvec3 n_vs(normal_rough[i * 4], normal_rough[i * 4 + 1], normal_rough[i * 4 + 2]);
        const double nl = glm::length(n_vs);
        n_vs = nl > 1e-4 ? n_vs / nl : glm::dvec3(0, 0, 1);
        glm::vec3 n_ws = glm::normalize(glm::vec3(glm::dmat3(inv_view) * n_vs));
        // The G-buffer's normal is half float: up to 2.4e-4 off per component, which moves a
        // mirror ray's hit by a few hundredths of a pixel and flips reflected silhouettes
        // (pedestal's wall mirror: 34.5 dB against the planar oracle, all of it at edges).
        // Where the eye ray found the surface and no normal map perturbs it, the mesh's own
        // interpolated normal is the exact one.
        if (primary.hit && !(material[i * 4 + 2] & MATERIAL_FLAG_NORMAL_MAPPED)) n_ws = primary.normal;
        const glm::vec3 v_ws = glm::vec3(glm::normalize(eye - p_ws));
        const float rough = std::clamp(normal_rough[i * 4 + 3], 0.0f, 1.0f);
        const double cam_dist = glm::length(eye - p_ws);
        const double cos_phi = std::abs(pv.z) / std::max(glm::length(glm::dvec3(pv)), 1e-30);
        // Offset along the normal by a few ulps of the position's magnitude: no self-hits,
        // also 1e4 units from the origin.
        const double mag = std::max({1.0, std::abs(p_ws.x), std::abs(p_ws.y), std::abs(p_ws.z)});
        const glm::vec3 origin = glm::vec3(p_ws + glm::dvec3(n_ws) * (4e-6 * mag + 1e-5 * cam_dist));
        int traceable = 0, missing = 0, sky = 0;
        for (int k = 0; k < n; ++k) {
          glm::vec3 dir;
          if (n == 1) {
            dir = glm::reflect(-v_ws, n_ws);
          } else {
            const glm::vec2 xi = shared::sample_xi(static_cast<unsigned>(x), static_cast<unsigned>(y),
                                                   static_cast<unsigned>(k), static_cast<unsigned>(params_.seed));
            dir = shared::sample_reflection(n_ws, v_ws, rough, xi);
            // Directions under the surface carry no light (and would hit the surface itself).
            if (glm::dot(dir, n_ws) <= 0.0f) dir = glm::reflect(-v_ws, n_ws);
          }
          dir = glm::normalize(dir);
          const std::size_t first_segment = (pixel_start[i] + static_cast<std::size_t>(k) - batch_first) * bounces;
          shared::ReferenceSample& s = samples[first_segment];
          s.direction = glm::vec4(dir, 0.0f);
          const RayHit hit = bvh_->trace(origin, dir);
          if (!hit.hit) {
            s.position = glm::vec4(0, 0, 0, -1);
            ++sky;
            continue;
          }
          // GL picks the LOD of the longer footprint axis; off the view axis a pixel subtends
          // cos(phi) times the central angle along that axis.
          record_hit(s, hit, pixel_angle * cos_phi * (cam_dist + hit.t));
          glm::vec2 hp(0);
          const bool visible = visible_on_screen(hit, material[i * 4] > 0 ? material[i * 4 + 3] : -1, hp);
          s.direction.w = visible ? 1.0f : 0.0f;
          s.hit_pixel = glm::vec4(hp, hit.uv);
          (visible ? traceable : missing)++;
          if (bounces > 1)
            follow_bounces(hit, dir, cam_dist + hit.t, &samples[first_segment], static_cast<unsigned>(x),
                           static_cast<unsigned>(y), static_cast<unsigned>(k));
        }
        PixelClass c = PixelClass::Sky;
        if (2 * traceable > n) c = PixelClass::Traceable;
        else if (missing >= sky) c = PixelClass::Missing;
        cls[i] = static_cast<std::uint8_t>(c);
      }
    }
  };
  // --- GPU shading of the hits, in batches ------------------------------------------------------
  std::vector<shared::ReferenceMaterial> mats;
  // Texture slots: an image is uploaded twice, as sRGB albedo and as linear normal map.
  std::vector<int> albedo_slot(scene.images.size(), -1), normal_slot(scene.images.size(), -1);
  std::vector<GLuint> slot_textures;
  auto slot_for = [&](int image, bool normal) {
    if (image < 0) return -1;
    int& s = (normal ? normal_slot : albedo_slot)[static_cast<std::size_t>(image)];
    if (s < 0) {
      if (slot_textures.size() >= REFERENCE_MAX_TEXTURES)
        throw RuntimeError("the reference shades at most " + std::to_string(REFERENCE_MAX_TEXTURES) +
                           " albedo and normal maps; this scene has more.");
      s = static_cast<int>(slot_textures.size());
      slot_textures.push_back(normal ? in.gpu_scene.normal_texture(image)
                                     : in.gpu_scene.albedo_texture(image));
    }
    return s;
  };
  for (const Material& mt : scene.materials) {
    const int albedo = slot_for(mt.albedo_texture, false), normal = slot_for(mt.normal_texture, true);
    mats.push_back({glm::vec4(mt.albedo, mt.metallic),
                    glm::vec4(mt.roughness, mt.reflectance, static_cast<float>(albedo), static_cast<float>(normal)),
                    glm::vec4(mt.emission, mt.normal_strength)});
  }
  gl::Buffer mat_buf = gl::make_buffer("reference materials",
                                       static_cast<GLsizeiptr>(mats.size() * sizeof(mats[0])), mats.data(), 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSBO_REF_MATERIALS, mat_buf.id());
  for (std::size_t s = 0; s < slot_textures.size(); ++s)
    glBindTextureUnit(TEX_REF_MAP0 + static_cast<GLuint>(s), slot_textures[s]);

  if (ideal_.width() != w || ideal_.height() != h) ideal_ = gl::Texture2D("reference ideal", GL_RGBA16F, w, h);
  const float zero[4] = {0, 0, 0, 0};
  glClearTexImage(reflection.id(), 0, GL_RGBA, GL_FLOAT, zero);
  glClearTexImage(ideal_.id(), 0, GL_RGBA, GL_FLOAT, zero);
  glBindImageTexture(IMG_REF_TRUTH, reflection.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glBindImageTexture(IMG_REF_IDEAL, ideal_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glUseProgram(program_.id());
  glProgramUniform1i(program_.id(), 1, static_cast<int>(bounces));

  std::vector<shared::ReferencePixel> pixels;
  // Shades `pixels` from `samples` into the images bound at IMG_REF_TRUTH and IMG_REF_IDEAL.
  // The buffers live for this call only: it waits for the GPU.
  auto shade = [&](const char* what) {
    gl::Buffer sbuf = gl::make_buffer(std::string(what) + " samples",
                                      static_cast<GLsizeiptr>(samples.size() * sizeof(shared::ReferenceSample)),
                                      samples.data(), 0);
    gl::Buffer pbuf = gl::make_buffer(std::string(what) + " pixels",
                                      static_cast<GLsizeiptr>(pixels.size() * sizeof(shared::ReferencePixel)),
                                      pixels.data(), 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSBO_REF_SAMPLES, sbuf.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSBO_REF_PIXELS, pbuf.id());
    glProgramUniform1i(program_.id(), 0, static_cast<int>(pixels.size()));
    glDispatchCompute(static_cast<GLuint>((pixels.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glFinish();
  };
  while (batch_y1 < h) {
    // Whole rows, as many as fit in one batch (at least one).
    batch_y0 = batch_y1;
    batch_first = pixel_start[static_cast<std::size_t>(batch_y0) * w];
    do {
      ++batch_y1;
    } while (batch_y1 < h && (pixel_start[static_cast<std::size_t>(batch_y1 + 1) * w] - batch_first) * bounces <= kMaxBatchSamples);
    const std::size_t batch_end = pixel_start[static_cast<std::size_t>(batch_y1) * w];
    if (batch_end == batch_first) continue;  // no reflective pixel in these rows
    samples.assign((batch_end - batch_first) * bounces, unused_segment());
    next_row = batch_y0;
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(worker);
    // The workers never touch the GL, so this (GL) thread may draw a progress bar meanwhile.
    if (progress)
      for (int taken; (taken = next_row.load()) < batch_y1;) {
        progress(static_cast<double>(taken) / h);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
    for (auto& t : pool) t.join();

    pixels.clear();
    for (std::size_t i = static_cast<std::size_t>(batch_y0) * w; i < static_cast<std::size_t>(batch_y1) * w; ++i) {
      const int n = static_cast<int>(pixel_start[i + 1] - pixel_start[i]);
      if (n == 0) continue;
      pixels.push_back({glm::ivec4(static_cast<int>(i % static_cast<std::size_t>(w)),
                                   static_cast<int>(i / static_cast<std::size_t>(w)),
                                   static_cast<int>(pixel_start[i] - batch_first), n)});
    }
    shade("reference");
  }

  // --- refraction through transparent surfaces, with the tracers' thin-surface model ----------
  // The view ray bends once at the nearest transparent surface (refract with 1/ior; total
  // internal reflection reflects) and goes on straight to the opaque scene behind it (glass is
  // not in the BVH). Truth: the hit shaded from the ray, or the environment. Ideal: the lit
  // colour at the hit's pixel where a screen-space tracer could find it there, else confidence
  // 0, so that the composite shows the unbent background as it does for a tracer that finds
  // nothing. The pixel's class becomes its refraction's: glass covers its reflection.
  if (ideal_refraction_.width() != w || ideal_refraction_.height() != h)
    ideal_refraction_ = gl::Texture2D("reference ideal refraction", GL_RGBA16F, w, h);
  glClearTexImage(ideal_refraction_.id(), 0, GL_RGBA, GL_FLOAT, zero);
  glClearTexImage(in.refraction->id(), 0, GL_RGBA, GL_FLOAT, zero);  // non-glass pixels: none
  if (in.gpu_scene.has_transparent()) {
    const std::vector<float> glass_depth =
        gl::read_texture<float>(in.gbuffer.glass_depth, GL_DEPTH_COMPONENT, GL_FLOAT, 1, gl::Rows::GlOrder);
    const std::vector<float> glass_surface =
        gl::read_texture<float>(in.gbuffer.glass_surface, GL_RGBA, GL_FLOAT, 4, gl::Rows::GlOrder);
    pixels.clear();
    for (std::size_t i = 0; i < npx; ++i)
      if (glass_surface[i * 4 + 3] >= 1.0f)
        pixels.push_back({glm::ivec4(static_cast<int>(i % static_cast<std::size_t>(w)),
                                     static_cast<int>(i / static_cast<std::size_t>(w)),
                                     static_cast<int>(pixels.size()), 1)});
    samples.assign(pixels.size() * bounces, unused_segment());
    std::atomic<std::size_t> next{0};
    auto glass_worker = [&] {
      for (std::size_t g; (g = next.fetch_add(1)) < pixels.size();) {
        const int x = pixels[g].data.x, y = pixels[g].data.y;
        const std::size_t i = static_cast<std::size_t>(y) * w + x;
        const glm::dvec4 ndc((x + 0.5) / w * 2 - 1, (y + 0.5) / h * 2 - 1, glass_depth[i], 1.0);
        glm::dvec4 pv = inv_proj * ndc;
        pv /= pv.w;
        const glm::vec3 d = glm::normalize(glm::vec3(pv));
        const glm::vec3 n = glm::normalize(glm::vec3(glass_surface[i * 4], glass_surface[i * 4 + 1], glass_surface[i * 4 + 2]));
        glm::vec3 dir_vs = glm::refract(d, n, 1.0f / glass_surface[i * 4 + 3]);
        if (glm::dot(dir_vs, dir_vs) < 1e-6f) dir_vs = glm::reflect(d, n);
        const glm::vec3 dir = glm::normalize(glm::vec3(glm::dmat3(inv_view) * glm::dvec3(dir_vs)));
        const glm::dvec3 p_ws = glm::dvec3(inv_view * pv);
        const double cam_dist = glm::length(glm::dvec3(pv));
        shared::ReferenceSample& s = samples[g * bounces];
        s.direction = glm::vec4(dir, 0.0f);
        const RayHit hit = bvh_->trace(glm::vec3(p_ws), dir);
        PixelClass c = PixelClass::Sky;
        if (!hit.hit) {
          s.position = glm::vec4(0, 0, 0, -1);
        } else {
          record_hit(s, hit, pixel_angle * (cam_dist + hit.t));
          glm::vec2 hp(0);
          const bool visible = visible_on_screen(hit, -1, hp);
          s.direction.w = visible ? 1.0f : 0.0f;
          s.hit_pixel = glm::vec4(hp, hit.uv);
          c = visible ? PixelClass::Traceable : PixelClass::Missing;
          if (bounces > 1)
            follow_bounces(hit, dir, cam_dist + hit.t, &samples[g * bounces], static_cast<unsigned>(x),
                           static_cast<unsigned>(y), 0u);
        }
        cls[i] = static_cast<std::uint8_t>(c);
      }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(glass_worker);
    for (auto& t : pool) t.join();
    rays_ += pixels.size();
    if (!pixels.empty()) {
      glBindImageTexture(IMG_REF_TRUTH, in.refraction->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
      glBindImageTexture(IMG_REF_IDEAL, ideal_refraction_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
      glProgramUniform1i(program_.id(), 2, 1);
      shade("reference refraction");
      glProgramUniform1i(program_.id(), 2, 0);
    }
  }

  // Classes, flipped to row 0 = top like every read-back image.
  classes_.assign(npx, PixelClass::NotReflective);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      classes_[static_cast<std::size_t>(h - 1 - y) * w + x] =
          static_cast<PixelClass>(cls[static_cast<std::size_t>(y) * w + x]);
}

}  // namespace ssr
