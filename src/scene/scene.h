// The plain-data scene every pass, technique and the ground truth reads.
//
// Units: world units are metres-ish; the scenes are built so that 1 unit is about 1 m.
// Everything is in world space, right-handed, +Y up. No GL objects live here: the renderer
// uploads a Scene, the reference tracer builds its BVH from the same triangles.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/animation.h"

namespace ssr {

// An RGBA8 image in memory (textures, normal maps). Row 0 is the top row (as in PNG files).
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes
  bool empty() const { return width == 0 || height == 0; }
};

struct Material {
  std::string name;
  glm::vec3 albedo{0.8f};      // linear base colour, each channel in [0,1]
  float metallic = 0.0f;       // [0,1]
  float roughness = 0.5f;      // perceptual roughness r in [0,1]; GGX alpha = r*r
  float reflectance = 0.5f;    // dielectric F0 = 0.16 * reflectance^2 (Filament), [0,1]
  glm::vec3 emission{0.0f};    // linear radiance added to the lit colour, >= 0
  int albedo_texture = -1;     // index into Scene::images, or -1 (multiplies albedo; sRGB)
  int normal_texture = -1;     // index into Scene::images, or -1 (tangent-space, +Y up in image)
  float normal_strength = 1.0f;// scales the tangent-space xy of the normal map, [0,4]
  bool transparent = false;    // refractive (for the refraction work); opaque for now
  float ior = 1.5f;            // index of refraction when transparent, [1,3]
};

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;    // unit length
  glm::vec2 uv;
  glm::vec4 tangent;   // xyz unit tangent along +u, w = handedness (+1/-1)
};

// A triangle mesh with one material. Indices are validated: every index < vertices.size().
struct Mesh {
  std::string name;
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;  // triangle list, 3 per triangle
  int material = 0;                    // index into Scene::materials
  int reflector = 0;                   // 0 = none, else 1-based index into Scene::reflectors
};

// A planar reflector: a rectangle. The mesh tagged with its id is what the G-buffer marks;
// this rectangle is what planar reflection techniques (PPR, planar mirror) project onto.
struct Reflector {
  glm::vec3 center{0.0f};
  glm::vec3 tangent{1, 0, 0};    // unit, in the plane
  glm::vec3 bitangent{0, 0, 1};  // unit, in the plane, orthogonal to tangent
  glm::vec2 half_extents{1.0f};  // along tangent, bitangent (> 0)
  glm::vec3 normal() const { return glm::normalize(glm::cross(bitangent, tangent)); }
};

struct Light {
  enum class Type { Point, Directional };
  Type type = Type::Point;
  glm::vec3 position{0.0f};      // world position (Point)
  glm::vec3 direction{0, -1, 0}; // unit direction the light travels (Directional)
  glm::vec3 color{1.0f};         // linear colour
  float intensity = 1.0f;        // Point: radiant intensity (W/sr-ish); Directional: irradiance
  float range = 20.0f;           // Point: distance where the smooth falloff reaches zero
};

struct Camera {
  std::string name;
  glm::vec3 position{0, 1, 5};
  glm::vec3 target{0, 1, 0};
  glm::vec3 up{0, 1, 0};
  float fov_y_deg = 60.0f;  // vertical field of view, degrees, (1,179)
  float near_plane = 0.05f; // > 0
  float far_plane = 200.0f; // > near_plane
};

// A view along `dir` with this `up` has no roll to form (up parallel to the view direction, to
// a relative 1e-6): what scene validation refuses and camera paths steer around.
inline bool up_along_view(const glm::vec3& dir, const glm::vec3& up) {
  return glm::length(glm::cross(dir, up)) < 1e-6f * glm::length(dir) * glm::length(up);
}

struct Environment {
  enum class Type { Sky, Constant };
  Type type = Type::Sky;
  glm::vec3 zenith{0.25f, 0.45f, 0.85f};   // sky colour straight up (linear radiance)
  glm::vec3 horizon{0.9f, 0.9f, 0.95f};    // sky colour at the horizon
  glm::vec3 ground{0.2f, 0.18f, 0.15f};    // colour below the horizon
  glm::vec3 constant{0.5f};                // used when type == Constant
  float intensity = 1.0f;                  // scales all of the above
};

struct Scene {
  std::string name;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Image> images;
  std::vector<Light> lights;
  std::vector<Camera> cameras;      // cameras[0] is the default
  std::vector<Reflector> reflectors;  // at most kMaxReflectors
  Environment environment;
  float ambient = 0.3f;             // scales the environment's diffuse (ambient) light
  Animation animation;              // camera paths and moving meshes (animation.h); at time 0
                                    // the meshes are as stored above

  static constexpr int kMaxReflectors = 16;
  static constexpr int kMaxLights = 32;
  // One draw (and its uniform buffer) per mesh: a file of one-triangle groups must not turn
  // into millions of them.
  static constexpr int kMaxMeshes = 65536;

  // The camera of that name; throws InputError listing the names when there is none.
  const Camera& camera(const std::string& name) const;
  std::size_t triangle_count() const;
};

// The largest radiance, intensity, ambient, size or scale a scene may give, in a file or in
// the viewer's panels and script: a bound on input, not a physical limit.
inline constexpr float kSceneValueMax = 1e6f;

// The diagonal of the axis-aligned box around every vertex (0 for an empty scene).
float bounding_diagonal(const Scene& scene);

// Specular reflectance at normal incidence (as shaders/common/brdf.glsl's f0_of).
glm::vec3 material_f0(const Material& m);
// Whether any surface of the scene can do reflection or refraction work: a planar reflector, a
// material whose F0 reaches `reflective_f0` in some channel (as the G-buffer decides), or a
// transparent material. Albedo maps only darken, so the material's own albedo decides.
bool has_reflective_surfaces(const Scene& scene, float reflective_f0);

// Checks every invariant above (indices in range, finite values, ranges, unit vectors, counts,
// the animation's keys and motions; planar reflectors may not move) and throws InputError with
// one sentence naming the first problem. Loaders call it last.
void validate(const Scene& scene);
// The lights, environment and ambient part of validate() (the viewer edits those live).
void validate_lighting(const Scene& scene);

}  // namespace ssr
