// Named binding slots, shared by the C++ passes and the GLSL that reads them.
#pragma once
#include "shared/interop.h"

// Uniform buffers
#define UBO_FRAME 0      // FrameUniforms (shared/frame.h)
#define UBO_DRAW 1       // DrawUniforms: per G-buffer draw (shared/frame.h)
#define UBO_TECHNIQUE 2  // the running technique's Params struct (shared/<technique>.h)

// Shader storage buffers
#define SSBO_LIGHTS 0    // GpuLight[]

// Textures (texture units)
#define TEX_DEPTH 0             // D32F reversed-Z
#define TEX_NORMAL_ROUGHNESS 1  // RGBA16F view-space normal, perceptual roughness
#define TEX_ALBEDO_METALLIC 2   // RGBA8 linear albedo, metallic
#define TEX_MATERIAL 3          // RGBA16UI reflector id, reflectance*255, flags, object (mesh) id
#define TEX_LIT 4               // RGBA16F lit colour (no reflections)
#define TEX_REFLECTION 5        // RGBA16F technique output
#define TEX_COLOR 6             // RGBA16F composited HDR colour
#define TEX_EMISSION 7          // RGBA16F emitted radiance (G-buffer)
#define TEX_ALBEDO_MAP 8        // material albedo texture (G-buffer draw)
#define TEX_NORMAL_MAP 9        // material normal map (G-buffer draw)
#define TEX_HIZ 11              // R32F Hi-Z pyramid, max (= closest, reversed-Z) depth per cell
#define TEX_BACK_DEPTH 13       // D32F depth of the nearest back faces (techniques that ask)
#define TEX_DEBUG 14            // RGBA16F tracer debug: steps, hit share, hit distance
#define TEX_GLASS_DEPTH 15      // D32F nearest transparent surface (else the opaque depth)
#define TEX_GLASS_SURFACE 16    // RGBA16F view-space normal, ior (w = 0: no transparent surface)
#define TEX_GLASS_TINT 17       // RGBA8 transmission tint
#define TEX_REFRACTION 18       // RGBA16F technique refraction: radiance, confidence

// Images (image units)
#define IMG_OUT 0
#define IMG_OUT2 1
#define IMG_REFRACTION 2  // techniques write the refracted radiance of transparent pixels here

// G-buffer material flags (TEX_MATERIAL.z)
#define MATERIAL_FLAG_REFLECTIVE 1u
#define MATERIAL_FLAG_TRANSPARENT 2u
#define MATERIAL_FLAG_NORMAL_MAPPED 4u
