// Loading scenes from the command line's "--scene S": a built-in name, a .json scene file
// (placing OBJ meshes with materials), or a bare .obj (+ .mtl) file.
//
// Every loader validates what it read (indices, finite numbers, ranges) and throws InputError
// with one sentence naming the file and the problem. Debian's tinyobjloader rc10 accepts
// out-of-range negative face indices (CVE-2020-28589), so indices are checked after loading.
#pragma once
#include <filesystem>
#include <string>

#include "scene/scene.h"

namespace ssr {

// Built-in name, or a path ending in .json or .obj.
Scene load_scene(const std::string& name_or_path);

// A JSON scene file; mesh paths inside are relative to the file's directory.
Scene load_scene_json(const std::filesystem::path& path);

// A bare OBJ (with its MTL, if any) as a scene: default lights, a camera framing its bounds,
// a sky. Materials come from the MTL (Kd -> albedo, Pm/Pr if present, else from Ns).
Scene load_scene_obj(const std::filesystem::path& path);

// Appends the meshes, materials and textures of one OBJ file to `scene`, transformed by
// `transform`; `material_override` >= 0 replaces the MTL materials. Returns the number of meshes.
int append_obj(Scene& scene, const std::filesystem::path& path, const glm::mat4& transform,
               int material_override = -1);

}  // namespace ssr
