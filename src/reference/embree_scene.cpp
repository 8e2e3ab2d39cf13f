#include "reference/embree_scene.h"

#include <cmath>
#include <limits>

#include <embree3/rtcore.h>

#include "core/errors.h"

namespace ssr {

struct EmbreeScene::Impl {
  const Scene* scene = nullptr;
  RTCDevice device = nullptr;
  RTCScene rtc = nullptr;
  std::vector<std::vector<float>> uv_density;  // per mesh, per triangle
};

EmbreeScene::EmbreeScene(const Scene& scene) : impl_(std::make_unique<Impl>()) {
  impl_->scene = &scene;
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) throw RuntimeError("Embree could not create a device.");
  impl_->rtc = rtcNewScene(impl_->device);
  rtcSetSceneBuildQuality(impl_->rtc, RTC_BUILD_QUALITY_HIGH);
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    impl_->uv_density.emplace_back();
    // Transparent meshes are not in the opaque G-buffer either: the reflections the ground
    // truth traces see the same opaque world the screen-space tracers do.
    if (scene.materials[static_cast<std::size_t>(mesh.material)].transparent) continue;
    RTCGeometry geom = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertices.size()));
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      vb[3 * i + 0] = mesh.vertices[i].position.x;
      vb[3 * i + 1] = mesh.vertices[i].position.y;
      vb[3 * i + 2] = mesh.vertices[i].position.z;
    }
    const std::size_t ntri = mesh.indices.size() / 3;
    auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), ntri));
    std::vector<float> density(ntri, 0.0f);
    for (std::size_t t = 0; t < ntri; ++t) {
      const Vertex& a = mesh.vertices[mesh.indices[3 * t]];
      const Vertex& b = mesh.vertices[mesh.indices[3 * t + 1]];
      const Vertex& c = mesh.vertices[mesh.indices[3 * t + 2]];
      for (int k = 0; k < 3; ++k) ib[3 * t + static_cast<std::size_t>(k)] = mesh.indices[3 * t + static_cast<std::size_t>(k)];
      const float world_area = 0.5f * glm::length(glm::cross(b.position - a.position, c.position - a.position));
      const glm::vec2 e1 = b.uv - a.uv, e2 = c.uv - a.uv;
      const float uv_area = 0.5f * std::abs(e1.x * e2.y - e1.y * e2.x);
      density[t] = world_area > 0 ? std::sqrt(uv_area / world_area) : 0.0f;
    }
    impl_->uv_density.back() = std::move(density);
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(impl_->rtc, geom, static_cast<unsigned>(m));
    rtcReleaseGeometry(geom);
  }
  rtcCommitScene(impl_->rtc);
  if (rtcGetDeviceError(impl_->device) != RTC_ERROR_NONE)
    throw RuntimeError("Embree could not build the scene's BVH.");
}

EmbreeScene::~EmbreeScene() {
  if (impl_->rtc) rtcReleaseScene(impl_->rtc);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

RayHit EmbreeScene::trace(const glm::vec3& origin, const glm::vec3& dir, float t_near) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh;
  rh.ray.org_x = origin.x;
  rh.ray.org_y = origin.y;
  rh.ray.org_z = origin.z;
  rh.ray.dir_x = dir.x;
  rh.ray.dir_y = dir.y;
  rh.ray.dir_z = dir.z;
  rh.ray.tnear = t_near;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = 0xFFFFFFFFu;
  rh.ray.flags = 0;
  rh.ray.time = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->rtc, &ctx, &rh);

  RayHit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  const Mesh& mesh = impl_->scene->meshes[rh.hit.geomID];
  const std::size_t tri = rh.hit.primID;
  const Vertex& a = mesh.vertices[mesh.indices[3 * tri]];
  const Vertex& b = mesh.vertices[mesh.indices[3 * tri + 1]];
  const Vertex& c = mesh.vertices[mesh.indices[3 * tri + 2]];
  const float u = rh.hit.u, v = rh.hit.v, w = 1.0f - u - v;
  hit.hit = true;
  hit.t = rh.ray.tfar;
  hit.mesh = static_cast<int>(rh.hit.geomID);
  hit.position = w * a.position + u * b.position + v * c.position;
  hit.uv = w * a.uv + u * b.uv + v * c.uv;
  hit.tangent = glm::vec4(glm::vec3(w * a.tangent + u * b.tangent + v * c.tangent), a.tangent.w < 0.0f ? -1.0f : 1.0f);
  // Two-sided like the G-buffer: the front face is counter-clockwise seen from the viewer.
  glm::vec3 ng = glm::cross(b.position - a.position, c.position - a.position);
  const float ng_len = glm::length(ng);
  ng = ng_len > 0 ? ng / ng_len : -dir;
  const bool front = glm::dot(ng, dir) < 0.0f;
  glm::vec3 n = w * a.normal + u * b.normal + v * c.normal;
  const float n_len = glm::length(n);
  n = n_len > 1e-8f ? n / n_len : ng;
  hit.normal = front ? n : -n;
  hit.cos_incidence = std::abs(glm::dot(ng, dir));
  hit.uv_density = impl_->uv_density[rh.hit.geomID][tri];
  return hit;
}

}  // namespace ssr
