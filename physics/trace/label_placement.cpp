// The width estimate and the search for a free place. Widths are DejaVu Sans's advances rounded
// up by character class (a viewer with a narrower font leaves more room, never less).
#include "physics/trace/label_placement.hpp"

#include <array>
#include <cmath>
#include <string_view>

namespace scenfuzz {
namespace {

constexpr double ascent = 0.95;   // of the font size above the baseline (DejaVu: 0.93)
constexpr double descent = 0.25;  // below it (DejaVu: 0.24)
constexpr double halo = 2;        // pixels of white outline around the glyphs

// In ems, regular and bold.
double advance(unsigned char c, bool bold) {
  static constexpr std::string_view narrow = "iIjlf!|.,:;'`()[]{}/\\ tr";
  static constexpr std::string_view wide = "mwMW%@&=<>+~#";
  if ((c & 0xC0) == 0x80) return 0;          // a UTF-8 continuation byte: counted with its lead
  if (c >= 0x80) return bold ? 1.15 : 1.05;  // a non-ASCII character: as wide as an em dash
  if (narrow.find(static_cast<char>(c)) != std::string_view::npos) return bold ? 0.5 : 0.45;
  if (wide.find(static_cast<char>(c)) != std::string_view::npos) return bold ? 1.12 : 1.0;
  if (c >= 'A' && c <= 'Z') return bold ? 0.88 : 0.8;
  return bold ? 0.72 : 0.65;
}

}  // namespace

bool overlaps(const PixelBox& a, const PixelBox& b) {
  return a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
}

bool contains(const PixelBox& outer, const PixelBox& inner) {
  return inner.left >= outer.left && inner.right <= outer.right && inner.top >= outer.top &&
         inner.bottom <= outer.bottom;
}

double estimated_text_width(std::string_view text, const TextFont& font) {
  double ems = 0;
  for (const char c : text) ems += advance(static_cast<unsigned char>(c), font.bold);
  return ems * font.size;
}

PixelBox text_box(double x, double baseline, std::string_view text, const TextFont& font) {
  return {x - halo, baseline - ascent * font.size - halo,
          x + estimated_text_width(text, font) + halo, baseline + descent * font.size + halo};
}

PlacedLabel label_at(double left, double top, std::string_view text, const TextFont& font) {
  const double x = left + halo;
  const double baseline = top + halo + ascent * font.size;
  return {text_box(x, baseline, text, font), x, baseline};
}

bool LabelPlacer::free(const PixelBox& box) const {
  if (!contains(area_, box)) return false;
  for (const PixelBox& taken : taken_)
    if (overlaps(taken, box)) return false;
  return true;
}

std::optional<PlacedLabel> LabelPlacer::place(double x, double y, double clearance,
                                              std::string_view text, const TextFont& font) {
  const PlacedLabel probe = label_at(0, 0, text, font);
  const double width = probe.box.width(), height = probe.box.height();
  // Eight directions around the anchor, right and above first (where people look for a name);
  // then the same at growing distances.
  static constexpr std::array<std::array<double, 2>, 8> directions{
      {{1, -1}, {1, 1}, {-1, -1}, {-1, 1}, {1, 0}, {-1, 0}, {0, -1}, {0, 1}}};
  constexpr int rings = 6;
  for (int ring = 0; ring < rings; ++ring) {
    const double gap = std::max(clearance, 2.0) + 3 + ring * (height + 2);
    for (const auto& [dx, dy] : directions) {
      // The box's corner or edge nearest the anchor sits `gap` away from it.
      const double left = dx > 0   ? x + gap * (dy == 0 ? 1 : 0.7)
                          : dx < 0 ? x - gap * (dy == 0 ? 1 : 0.7) - width
                                   : x - width / 2;
      const double top = dy > 0   ? y + gap * (dx == 0 ? 1 : 0.7)
                         : dy < 0 ? y - gap * (dx == 0 ? 1 : 0.7) - height
                                  : y - height / 2;
      const PlacedLabel label = label_at(left, top, text, font);
      if (!free(label.box)) continue;
      taken_.push_back(label.box);
      return label;
    }
  }
  return std::nullopt;
}

}  // namespace scenfuzz
