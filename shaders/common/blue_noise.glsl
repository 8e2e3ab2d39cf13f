// The spatio-temporal blue noise (src/core/blue_noise.h) as a texture: 128 x 128 slices stacked
// vertically (R8). Frame f reads slice f mod slices; each full loop of slices shifts every value
// by the golden ratio (Cranley-Patterson rotation) so later loops do not repeat the first.
layout(binding = TEX_BLUE_NOISE) uniform sampler2D blue_noise_tex;

// Two numbers in (0, 1) for pixel p in frame `frame_index`; `seed` shifts the tiling. The second
// reads the tile half a period away: a void-and-cluster map is decorrelated from itself there.
vec2 blue_noise_xi(ivec2 p, int frame_index, int seed) {
  ivec2 size = textureSize(blue_noise_tex, 0);
  int tile = size.x, slices = size.y / size.x;
  ivec2 q = p + ivec2(seed * 37, seed * 91);
  int slice = frame_index % slices;
  float rotation = fract(float(frame_index / slices) * 0.61803398875);
  ivec2 a = ivec2(q.x & (tile - 1), (q.y & (tile - 1)) + slice * tile);
  ivec2 b = ivec2((q.x + tile / 2) & (tile - 1), ((q.y + tile / 2) & (tile - 1)) + slice * tile);
  // Texel values k/255 -> (k + 0.5) / 256: strictly inside (0, 1).
  vec2 v = (vec2(texelFetch(blue_noise_tex, a, 0).r, texelFetch(blue_noise_tex, b, 0).r) * 255.0 + 0.5) / 256.0;
  return fract(v + rotation);
}
