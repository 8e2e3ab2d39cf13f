// The frame's render targets, owned by the Renderer and read by techniques.
#pragma once
#include "gl/objects.h"

namespace ssr {

struct GBuffer {
  gl::Texture2D depth;             // D32F, reversed-Z, cleared to 0
  gl::Texture2D normal_roughness;  // RGBA16F: view-space normal, perceptual roughness
  gl::Texture2D albedo_metallic;   // RGBA8: linear albedo, metallic
  gl::Texture2D material;          // RGBA16UI: reflector id, reflectance*255, flags, object (mesh) id
  gl::Texture2D emission;          // RGBA16F: emitted radiance
  gl::Framebuffer fbo;
  gl::Texture2D back_depth;        // D32F: nearest back faces, drawn only for techniques that ask
  gl::Framebuffer back_fbo;
  // Transparent surfaces in front of the opaque ones (only drawn when the scene has some).
  gl::Texture2D glass_depth;       // D32F: opaque depth, then the nearest transparent surface
  gl::Texture2D glass_surface;     // RGBA16F: view-space normal, ior (w = 0: no glass here)
  gl::Texture2D glass_tint;        // RGBA8: linear albedo (transmission tint)
  gl::Framebuffer glass_fbo;
};

}  // namespace ssr
