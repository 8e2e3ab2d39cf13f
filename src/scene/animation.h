// Scene animation as data (no GL): camera paths and rigid motions of meshes over time.
//
// Meshes stay baked in world space at rest (time 0 of every built-in scene and of pedestal.json
// is exactly the static scene); an ObjectMotion gives a world-space matrix per mesh and time,
// posed_scene() applies it to a copy. Times are in seconds. Every function here is
// deterministic and returns finite values for any finite time (a scene that passed validate()).
//
// scene/scene.h includes this header (Scene holds an Animation); include scene.h to call the
// functions below.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace ssr {

struct Scene;
struct Camera;

struct CameraKey {
  float time = 0;
  glm::vec3 position{0};
  glm::vec3 target{0, 0, -1};
  float fov_y_deg = 60;
  // The camera jumps to this key at its time (no interpolation from the previous key): a camera
  // cut. Not allowed on a path's first key.
  bool cut = false;
};

struct CameraPath {
  std::string name;  // letters, digits, '_', '-', '.'; unique within the scene
  std::string description;
  std::vector<CameraKey> keys;  // sorted by time, strictly increasing
};

struct TransformKey {
  float time = 0;
  glm::vec3 translate{0};
  glm::vec3 rotate_deg{0};  // Euler angles, applied as Rz * Ry * Rx (as the scene files do)
  glm::vec3 scale{1};       // > 0
};

struct ObjectMotion {
  enum class Kind { Keyframes, Spin, Orbit };
  Kind kind = Kind::Keyframes;
  std::vector<int> meshes;  // mesh indices moved together (by Scene::meshes index)
  // Keyframes and spin rotate and scale about this world point; orbit: the orbit's centre.
  glm::vec3 pivot{0};
  // Keyframes: M(t) = T(pivot + translate) * Rz*Ry*Rx * S * T(-pivot), interpolated.
  std::vector<TransformKey> keys;
  glm::vec3 axis{0, 1, 0};  // Spin / Orbit: unit axis
  float period = 1;         // Spin / Orbit: seconds per turn (!= 0); the sign gives the direction
};

struct Animation {
  float duration = 0;  // seconds; how long a playback of the scene runs (0 = no animation)
  std::vector<CameraPath> paths;
  std::vector<ObjectMotion> objects;
  int default_path = -1;  // index into paths chosen by a scene option (path=NAME), or -1
  bool empty() const { return paths.empty() && objects.empty(); }
};

// The world-space matrix of mesh `mesh` at `time`: identity for a mesh no motion moves; a mesh
// moved by several motions gets them applied in list order (the later motion's matrix on the
// left). Every motion is the identity at its rest phase: keyframes at a rest first key (before
// or at its time), spin and orbit at whole turns (time 0 included), exactly.
glm::mat4 mesh_transform(const Scene& scene, int mesh, float time);
// One matrix per mesh of the scene.
std::vector<glm::mat4> mesh_transforms(const Scene& scene, float time);

// A copy of the scene with every moved mesh's vertices transformed (positions; normals by the
// inverse transpose and tangents by the matrix, renormalised, tangent w kept, as
// meshgen::transform does). Meshes whose matrix is exactly the identity are copied untouched
// (bit-identical). Reflector rectangles, lights and cameras are not changed.
Scene posed_scene(const Scene& scene, float time);

// The camera on `path` at `time` (clamped to the first and last key's times). `base` gives up,
// near, far and the name. Position and target follow a Catmull-Rom spline in time (cubic
// Hermite with tangents (P[i+1] - P[i-1]) / (t[i+1] - t[i-1]), one-sided at the ends of a run
// of keys), fov a smoothstep between keys; the camera is exactly at each key at its time. A cut
// key splits the path into runs: before the cut key's time the camera holds the previous key,
// from its time on it follows the run that starts at the cut key.
Camera camera_at(const CameraPath& path, float time, const Camera& base);

// Whether a cut key's time lies in (t0, t1] (false when t1 <= t0).
bool cut_between(const CameraPath& path, float t0, float t1);

// The scene's path of that name; throws InputError with one sentence listing the scene's path
// names (or saying it has none).
const CameraPath& find_path(const Scene& scene, const std::string& name);

}  // namespace ssr
