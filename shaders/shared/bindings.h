// Every binding slot, by name, shared by the C++ passes and the GLSL that reads them. No pass
// uses a raw number; tests/unit/test_bindings.cpp checks that each kind's slots (and ranges) do
// not overlap and that no source file binds a literal unit.
#pragma once
#include "shared/interop.h"

// Uniform buffers
#define UBO_FRAME 0      // FrameUniforms (shared/frame.h)
#define UBO_DRAW 1       // DrawUniforms: per G-buffer draw (shared/frame.h)
#define UBO_TECHNIQUE 2  // the running technique's Params struct (shared/<technique>.h)
#define UBO_PASS 3       // a technique-internal pass's own parameters (classification, denoiser stages)
#define UBO_PPR_REFLECTORS 4  // ppr's projection: the SSBO_PPR_REFLECTORS buffer's first PprReflector

// Shader storage buffers
#define SSBO_LIGHTS 0          // GpuLight[]
#define SSBO_REF_SAMPLES 1     // reference: ReferenceSample[] (shared/reference.h)
#define SSBO_REF_PIXELS 2      // reference: ReferencePixel[]
#define SSBO_REF_MATERIALS 3   // reference: ReferenceMaterial[]
#define SSBO_PPR_REFLECTORS 4  // ppr: PprReflector[] (shared/ppr.h)
#define SSBO_TILES 5           // classification: TileListHeader + packed trace tiles (shared/classification.h)
#define SSBO_TELEMETRY 6       // instrumented builds: TelemetryHeader, histogram, per-pixel words (shared/telemetry.h)
#define SSBO_RAYS 7            // classification: RayListHeader + packed texels (shared/classification.h)

// Textures (texture units). The frame's resources:
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
#define TEX_HIZ 10              // RG32F Hi-Z pyramid: max (= closest, reversed-Z) and min (farthest) depth per cell
#define TEX_BACK_DEPTH 11       // D32F depth of the nearest back faces (techniques that ask)
#define TEX_DEBUG 12            // RGBA16F technique debug image (display.comp reads its views)
#define TEX_GLASS_DEPTH 13      // D32F nearest transparent surface (else the opaque depth)
#define TEX_GLASS_SURFACE 14    // RGBA16F view-space normal, ior (w = 0: no transparent surface)
#define TEX_GLASS_TINT 15       // RGBA8 transmission tint
#define TEX_REFRACTION 16       // RGBA16F technique refraction: radiance, confidence
#define TEX_MOTION 17           // RG16F motion vectors (shared/frame.h: FrameUniforms.time)
#define TEX_PREV_LIT 18         // history: the previous frame's lit colour
#define TEX_PREV_COLOR 19       // history: the running technique's previous composited colour
#define TEX_PREV_DEPTH 20       // history: the previous frame's depth
#define TEX_PREV_NORMAL_ROUGHNESS 21  // history: the previous frame's normal + roughness
// Technique-private and tool textures:
#define TEX_PPR_FALLBACK 22     // ppr: the fallback tracer's reflection (ppr.fallback != none)
#define TEX_PLANAR_MIRROR_LIT 23  // planar oracle: the mirrored camera's lit colour
#define TEX_DIFF_A 24           // viewer difference pass: side A's display image
#define TEX_DIFF_B 25           // viewer difference pass: side B's display image
#define TEX_REF_MAP0 26         // reference: units TEX_REF_MAP0 .. + REFERENCE_MAX_TEXTURES - 1
#define REFERENCE_MAX_TEXTURES 8  // albedo and normal maps the reference's shading can sample
#define TEX_CLASS 34            // classification: R8 class / CLASS_LEVELS per pixel (shared/classification.h)
#define TEX_BLUE_NOISE 35       // R8 spatio-temporal blue noise, slices stacked vertically
#define TEX_TRACE_RADIANCE 36   // denoiser input: the trace's radiance, confidence (trace resolution)
#define TEX_TRACE_RAY 37        // denoiser input: hit vector (view space), pdf (trace resolution)
#define TEX_STAGE_IN 38         // denoiser: the previous stage's radiance, confidence
                                // (also borrowed by the pass-floor microbenchmark for its source, eval/pass_floor.h)
#define TEX_STAGE_STATS 39      // denoiser: the previous stage's variance, ray length / history length
#define TEX_HISTORY 40          // denoiser: last frame's accumulated radiance (persistent)
#define TEX_HISTORY_STATS 41    // denoiser: last frame's variance, history length (persistent)
#define TEX_STAGE_VIEW 42       // display: the technique texture a stage view shows (TechniqueDecl::stage_views)
#define TEX_PPR_PROJECTED 43    // ppr resolve: this frame's intermediate (r32ui), read as a texture

// Images (image units; GL guarantees 8)
#define IMG_OUT 0               // the running pass's main output
#define IMG_OUT2 1              // its second output (techniques: the debug image)
#define IMG_REFRACTION 2        // techniques write the refracted radiance of transparent pixels here
#define IMG_PPR_INTERMEDIATE 3  // ppr: r32ui; project: written with imageAtomicMin; resolve: the other one, cleared to PPR_EMPTY
#define IMG_MOTION 4            // the lighting pass writes the background's motion vectors
#define IMG_REF_TRUTH 5         // reference: the truth's reflection
#define IMG_REF_IDEAL 6         // reference: the screen-space ideal
#define IMG_DIFF_OUT 7          // viewer difference pass: the heat map
#define IMG_HIZ_LEVELS 0        // the Hi-Z pyramid's build, before the techniques bind theirs, borrows
                                // units 0..HIZ_LEVELS_PER_DISPATCH (shared/hiz.h) for the levels it writes

// G-buffer material flags (TEX_MATERIAL.z)
#define MATERIAL_FLAG_REFLECTIVE 1u
#define MATERIAL_FLAG_TRANSPARENT 2u
#define MATERIAL_FLAG_NORMAL_MAPPED 4u
