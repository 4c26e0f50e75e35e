// The ziggurat's 128 layers and its rare slow path: the wedges under the curve and the tail.
// Marsaglia and Tsang, "The Ziggurat Method for Generating Random Variables", J. Stat.
// Software 5(8), 2000.
#include "physics/ego/ziggurat_normal.hpp"

#include <cmath>

namespace scenfuzz {
namespace {

// The base layer's right edge and every layer's area, for 128 layers under exp(-x^2/2)
// (Marsaglia and Tsang's constants).
constexpr double kTailStart = 3.442619855899;
constexpr double kLayerArea = 9.91256303526217e-3;

double density(double x) { return std::exp(-0.5 * x * x); }  // unnormalised

Ziggurat build() {
  Ziggurat z;
  z.edge[0] = kLayerArea / density(kTailStart);
  z.edge[1] = kTailStart;
  for (int i = 1; i < kZigguratLayers - 1; ++i)
    z.edge[i + 1] = std::sqrt(-2 * std::log(density(z.edge[i]) + kLayerArea / z.edge[i]));
  z.edge[kZigguratLayers] = 0;
  for (int i = 0; i <= kZigguratLayers; ++i) z.height[i] = density(z.edge[i]);
  return z;
}

// Beyond kTailStart: Marsaglia's method, exact for the normal's tail.
double tail(Xoshiro256& random) {
  for (;;) {
    // 1 - uniform01 lies in (0, 1]: its logarithm is finite.
    const double x = -std::log(1 - uniform01(random)) / kTailStart;
    const double y = -std::log(1 - uniform01(random));
    if (2 * y >= x * x) return kTailStart + x;
  }
}

}  // namespace

const Ziggurat kZiggurat = build();

double standard_normal_outside_box(Xoshiro256& random, std::uint64_t bits) {
  for (;;) {
    const auto layer = static_cast<std::size_t>(bits & (kZigguratLayers - 1));
    const double sign = (bits & kZigguratLayers) != 0 ? -1.0 : 1.0;
    const double x = static_cast<double>(bits >> 11) * 0x1.0p-53 * kZiggurat.edge[layer];
    if (x < kZiggurat.edge[layer + 1]) return sign * x;
    if (layer == 0) return sign * tail(random);
    // In the wedge between the curve and the layer's box: accept below the curve.
    const double low = kZiggurat.height[layer], high = kZiggurat.height[layer + 1];
    if (low + uniform01(random) * (high - low) < density(x)) return sign * x;
    bits = random();
  }
}

}  // namespace scenfuzz
