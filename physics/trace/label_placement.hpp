// Text labels of a picture placed so that none leaves its area or covers another: each label's
// box is estimated from its characters (conservatively, for DejaVu Sans, the widest common
// sans-serif), and a placer tries positions around the label's anchor until one is free.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

namespace scenfuzz {

// An axis-aligned rectangle in pixels, y down.
struct PixelBox {
  double left = 0;
  double top = 0;
  double right = 0;
  double bottom = 0;

  double width() const { return right - left; }
  double height() const { return bottom - top; }
};

bool overlaps(const PixelBox& a, const PixelBox& b);
bool contains(const PixelBox& outer, const PixelBox& inner);

struct TextFont {
  double size = 12;  // pixels
  bool bold = false;
};

// At least the advance of `text` (UTF-8) in `font`.
double estimated_text_width(std::string_view text, const TextFont& font);

// The box a <text x y> (start-anchored, y its baseline) covers, with its white halo.
PixelBox text_box(double x, double baseline, std::string_view text, const TextFont& font);

// Where a label goes: its box, and the text's start and baseline inside it.
struct PlacedLabel {
  PixelBox box;
  double x = 0;
  double baseline = 0;
};

// The text's start and baseline that give it the box whose top-left corner is (left, top).
PlacedLabel label_at(double left, double top, std::string_view text, const TextFont& font);

class LabelPlacer {
 public:
  // Labels go inside `area`.
  explicit LabelPlacer(const PixelBox& area) : area_(area) {}

  // Something no label may cover (a label placed elsewhere, a body, a legend).
  void block(const PixelBox& box) { taken_.push_back(box); }

  // A free place for `text` near (x, y), at least `clearance` pixels from it (the size of what
  // it labels), trying nearer places first; nullopt when there is none within reach. The place
  // is taken.
  std::optional<PlacedLabel> place(double x, double y, double clearance, std::string_view text,
                                   const TextFont& font);

  // Whether `box` is inside the area and covers nothing taken.
  bool free(const PixelBox& box) const;

 private:
  PixelBox area_;
  std::vector<PixelBox> taken_;
};

}  // namespace scenfuzz
