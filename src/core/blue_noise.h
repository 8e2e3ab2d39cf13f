// Blue-noise dither textures that ssrlab makes itself (issue 14): no third-party noise data.
//
// The generator is Ulichney's void-and-cluster method (R. Ulichney, "The void-and-cluster method
// for dither array generation", Proc. SPIE 1913, Human Vision, Visual Processing, and Digital
// Display IV, 1993) on a toroidal grid, so the texture tiles without seams.
//
// The animated texture ranks all its slices in lockstep with one extra energy term along time,
// after Wolfe et al., "Spatiotemporal Blue Noise Masks" (EGSR 2022): each slice is blue noise on
// its own, and each pixel's values across the slices are spread apart too (a pixel that is dark in
// one frame tends to be bright in the next ones), so averaging over frames converges faster than
// with independent slices. Details in blue_noise.cpp.
#pragma once
#include <cstdint>
#include <vector>

namespace ssr {

// One size x size blue-noise threshold map, row-major, values 0..255 with every value equally
// often (size*size/256 times each when 256 divides size*size). Deterministic in (size, seed,
// sigma) on every platform: the energies are integers. sigma is the Gaussian energy filter's
// standard deviation in pixels (Ulichney: 1.5; 1.9 is the common choice). InputError unless
// size is in [2, 512] and sigma in [0.5, 8].
std::vector<std::uint8_t> void_and_cluster(int size, std::uint32_t seed, float sigma = 1.9f);

struct BlueNoise {
  int size = 0, slices = 0;
  std::vector<std::uint8_t> texels;  // slice-major: texels[(slice * size + y) * size + x]
  // Wraps all three coordinates (the texture tiles in space and loops in time), so
  // at(x, y, frame) is the value of pixel (x, y) in frame `frame`.
  std::uint8_t at(int x, int y, int slice) const;
};

// `slices` maps of size x size, each blue spatially (as void_and_cluster's) with a uniform
// histogram, different from one another, and spread apart along time at each pixel (the slices
// form a loop: the last one is followed by the first). InputError unless size is in [2, 512]
// and slices in [1, 64]. 128 x 128 x 8 takes about 0.2 s.
BlueNoise spatiotemporal_blue_noise(int size = 128, int slices = 8, std::uint32_t seed = 1);

// spatiotemporal_blue_noise(128, 8, 1), made on first use, once per process (thread-safe), and
// kept: generating it (~0.2 s) is cheap enough that it is not shipped as data.
const BlueNoise& default_blue_noise();

}  // namespace ssr
