// Standard normal draws by the ziggurat method (Marsaglia and Tsang, 2000), for the perception
// model's noise. Nearly every draw costs one generator output, a multiplication and a comparison;
// the polar method it replaced needed about 2.5 outputs, a logarithm and a square root per draw.
// The distribution is exact: the rare draws outside the ziggurat's boxes are decided against the
// density itself, and the tail beyond the base layer by Marsaglia's exact tail method.
#pragma once

#include <array>
#include <cstdint>

#include "physics/ego/xoshiro256.hpp"

namespace scenfuzz {

constexpr int kZigguratLayers = 128;

// edge[i] is layer i's right edge and height[i] the (unnormalised) density there; layer i >= 1
// spans heights height[i]..height[i + 1]. edge[0] is the base layer's width as if its tail were
// a box.
struct Ziggurat {
  std::array<double, kZigguratLayers + 1> edge{};
  std::array<double, kZigguratLayers + 1> height{};
};

// Built once, at static initialisation (ziggurat_normal.cpp).
extern const Ziggurat kZiggurat;

// A draw that fell outside its layer's box: the wedge or the tail. `bits` is the rejected output.
double standard_normal_outside_box(Xoshiro256& random, std::uint64_t bits);

// Inline: the box test is the whole cost of nearly every draw, and a call would double it.
inline double standard_normal(Xoshiro256& random) {
  // One output gives the layer (low 7 bits), the sign (bit 7) and the position (top 53 bits).
  const std::uint64_t bits = random();
  const auto layer = static_cast<std::size_t>(bits & (kZigguratLayers - 1));
  const double x = static_cast<double>(bits >> 11) * 0x1.0p-53 * kZiggurat.edge[layer];
  if (x < kZiggurat.edge[layer + 1]) return (bits & kZigguratLayers) != 0 ? -x : x;
  return standard_normal_outside_box(random, bits);
}

}  // namespace scenfuzz
