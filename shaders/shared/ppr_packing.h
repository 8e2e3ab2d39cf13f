// Pixel-projected reflections (Cichocki 2017; Kim 2018): one reflected pixel's screen offset
// packed into the 32-bit intermediate buffer, shared by GLSL (the passes) and C++ (the tests).
//
// The intermediate buffer is an r32ui image cleared to PPR_EMPTY (0xFFFFFFFF). The projection
// pass writes imageAtomicMin(ppr_pack(offset, fb)), so the smallest packed value wins: the major
// axis distance sits in the top bits, so the closest reflected pixel wins. The reflection pass
// reads ppr_unpack(value, fb) unless ppr_is_empty(value).
//
// offset = destination pixel position (float, sub-pixel fraction kept) - source pixel.
// Orientation: the dominant direction of the offset, as in the thesis' 4 coordinate systems:
//   |y| >= |x| (ties and the zero offset go to y): 0 = +y, 2 = -y   (major = |y|, minor = x)
//   |y| <  |x|:                                    1 = +x, 3 = -x   (major = |x|, minor = y)
// The minor component is stored as it is (signed, not rotated into the orientation's frame).
//
// Layout (bit 31 = most significant). The field positions never change; the image size only
// moves the binary point inside the two value fields (I integer bits, F = 14 - I fraction bits):
//
//   bit  31       0                        reserved, always 0: every packed value is < 2^31,
//                                          so ppr_pack never returns PPR_EMPTY
//   bits 30..17   major  (14 bits)         round(|major| * 2^F), unsigned: I int . F frac
//   bits 16..2    minor  (15 bits)         round(minor * 2^F) + 2^14, biased: (I+1) int . F frac
//   bits  1..0    orientation (2 bits)     0 = +y, 1 = +x, 2 = -y, 3 = -x
//
// Unsigned comparison therefore orders by major distance first, then by minor, then by
// orientation. Guaranteed: a smaller quantised major distance gives a smaller packed value, for
// two offsets of the same orientation and also across orientations (every orientation keeps its
// non-negative major distance in the same top field), so imageAtomicMin keeps the closest.
//
// I = ppr_integer_bits(width, height) = the smallest I with 2^I >= max(width, height), at most 14;
// F = ppr_fraction_bits(width, height) = 14 - I. Offsets inside the image are below
// max(width, height) in magnitude, so none of them clamps:
//
//   largest dimension       I    F   step (px)  major range          minor range
//   <= 1024                <=10 >=4  <= 1/16    [0, 2^I - 2^-F]      [-2^I, 2^I - 2^-F]
//   1025..2048 (1920x1080)  11   3   1/8        [0, 2047.875]        [-2048, 2047.875]
//   2049..4096 (3840x2160)  12   2   1/4        [0, 4095.75]         [-4096, 4095.75]
//   4097..8192 (7680x4320)  13   1   1/2        [0, 8191.5]          [-8192, 8191.5]
//   8193..16384             14   0   1          [0, 16383]           [-16384, 16383]
//   > 16384                 14   0   1          offsets past 16383 px clamp
//
// Quantisation rounds to the nearest step, computed exactly: with t = v * 2^F,
// q = floor(t) + (t - floor(t) >= 0.5 ? 1 : 0). The major distance |major| is what is rounded (a
// tie rounds away from the source pixel); the signed minor offset rounds ties toward +infinity.
// The integer and fraction bits of a field are the two's-complement split of q, i.e.
// v ~ floor(v) + frac with frac in [0, 1) also for negative v (the seeds took frac() of a
// negative value but truncated the integer part with int(), so their negative offsets decoded
// wrongly: ARCHITECTURE §9).
// Offsets beyond the ranges above CLAMP per component (the major to 2^I - 2^-F, the minor to its
// range) instead of wrapping (the seeds' 12-bit fields wrapped past 4095 px). The orientation is
// still chosen from the unclamped offset. Offsets must be finite (NaN gives an unspecified value).
// ppr_unpack(ppr_pack(o, F), F) equals o rounded to the step 2^-F on each axis (within half a step).
#pragma once
#include "shared/interop.h"

SSR_SHARED_BEGIN

const uint PPR_EMPTY = 0xFFFFFFFFu;  // the cleared intermediate buffer: nothing projected here
const uint PPR_VALUE_BITS = 14u;     // I + F: integer plus fraction bits of the major distance
const uint PPR_MAJOR_SHIFT = 17u;    // bits 30..17
const uint PPR_MAJOR_MASK = 0x3FFFu;  // 14 bits
const uint PPR_MINOR_SHIFT = 2u;     // bits 16..2
const uint PPR_MINOR_MASK = 0x7FFFu;  // 15 bits
const uint PPR_MINOR_BIAS = 0x4000u;  // 2^14: the minor field holds round(minor * 2^F) + 2^14
const uint PPR_ORIENT_MASK = 3u;     // bits 1..0

const uint PPR_POS_Y = 0u;
const uint PPR_POS_X = 1u;
const uint PPR_NEG_Y = 2u;
const uint PPR_NEG_X = 3u;

// Integer bits the offsets of a width x height image need: the smallest I with
// 2^I >= max(width, height), at most PPR_VALUE_BITS (14).
SSR_FN uint ppr_integer_bits(uint width, uint height) {
  uint largest = max(max(width, height), 1u);
  uint bits = 0u;
  while (bits < PPR_VALUE_BITS && (1u << bits) < largest) bits += 1u;
  return bits;
}

// Fraction bits F for a width x height image (the step is 2^-F px): 3 at 1920x1080, 2 at
// 3840x2160, 1 at 7680x4320.
SSR_FN uint ppr_fraction_bits(uint width, uint height) {
  return PPR_VALUE_BITS - ppr_integer_bits(width, height);
}

// v * 2^fraction_bits rounded to the nearest integer (ties up), clamped to [lo, hi]. Exact: the
// scale is a power of two and t - floor(t) loses nothing, so C++ and GLSL agree bit for bit.
SSR_FN int ppr_quantize(float v, uint fraction_bits, float lo, float hi) {
  float t = v * float(1u << fraction_bits);
  float q = floor(t);
  if (t - q >= 0.5f) q += 1.0f;
  return int(clamp(q, lo, hi));
}

// The orientation (PPR_POS_Y, PPR_POS_X, PPR_NEG_Y, PPR_NEG_X) of an offset.
SSR_FN uint ppr_orientation_of(vec2 offset) {
  if (abs(offset.y) < abs(offset.x)) return offset.x < 0.0f ? PPR_NEG_X : PPR_POS_X;
  return offset.y < 0.0f ? PPR_NEG_Y : PPR_POS_Y;
}

// Packs `offset` (destination - source, in pixels) for imageAtomicMin; never PPR_EMPTY.
// fraction_bits: ppr_fraction_bits(width, height) of the image (any value in 0..14 works).
SSR_FN uint ppr_pack(vec2 offset, uint fraction_bits) {
  uint orient = ppr_orientation_of(offset);
  bool x_major = (orient & 1u) == 1u;
  float along = abs(x_major ? offset.x : offset.y);  // major-axis distance
  float across = x_major ? offset.y : offset.x;       // minor-axis offset, signed
  int major_q = ppr_quantize(along, fraction_bits, 0.0f, float(PPR_MAJOR_MASK));
  int minor_q = ppr_quantize(across, fraction_bits, -float(PPR_MINOR_BIAS), float(PPR_MINOR_BIAS - 1u));
  uint minor_field = uint(minor_q + int(PPR_MINOR_BIAS));
  return (uint(major_q) << PPR_MAJOR_SHIFT) | (minor_field << PPR_MINOR_SHIFT) | orient;
}

// True where nothing was projected (the clear value).
SSR_FN bool ppr_is_empty(uint value) { return value == PPR_EMPTY; }

// The orientation bits of a packed value.
SSR_FN uint ppr_orientation(uint value) { return value & PPR_ORIENT_MASK; }

// The major-axis distance (pixels, >= 0) of a packed value.
SSR_FN float ppr_major_distance(uint value, uint fraction_bits) {
  return ldexp(float((value >> PPR_MAJOR_SHIFT) & PPR_MAJOR_MASK), -int(fraction_bits));
}

// The offset (destination - source, pixels) of a packed value, quantised to 2^-fraction_bits.
// Only meaningful where !ppr_is_empty(value); fraction_bits must be the one used to pack.
SSR_FN vec2 ppr_unpack(uint value, uint fraction_bits) {
  float along = ppr_major_distance(value, fraction_bits);
  int minor_q = int((value >> PPR_MINOR_SHIFT) & PPR_MINOR_MASK) - int(PPR_MINOR_BIAS);
  float across = ldexp(float(minor_q), -int(fraction_bits));
  uint orient = value & PPR_ORIENT_MASK;
  if (orient == PPR_POS_Y) return vec2(across, along);
  if (orient == PPR_POS_X) return vec2(along, across);
  if (orient == PPR_NEG_Y) return vec2(across, -along);
  return vec2(-along, across);
}

SSR_SHARED_END
