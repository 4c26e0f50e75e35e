// Reads back what a picture's readers see of its text: the root's size in pixels and every
// <text> element's box (estimated as the renderer estimates it), so that tests can check that no
// label leaves the canvas or covers another. Only text drawn in the root's own coordinates can
// be measured; text inside a nested <svg> or a transformed group is reported as a problem.
#pragma once

#include <charconv>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "physics/trace/label_placement.hpp"

namespace scenfuzz::test {

struct SvgLabel {
  std::string text;
  PixelBox box;
};

struct SvgLabels {
  double width = 0;  // the root's width and height attributes, pixels
  double height = 0;
  std::vector<SvgLabel> labels;
  std::vector<std::string> problems;  // text that cannot be measured, malformed attributes
};

inline std::string xml_unescaped(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '&') {
      out += text[i];
      continue;
    }
    for (const auto& [entity, c] : {std::pair<std::string_view, char>{"&amp;", '&'},
                                    {"&lt;", '<'},
                                    {"&gt;", '>'},
                                    {"&quot;", '"'},
                                    {"&apos;", '\''}})
      if (text.substr(i).starts_with(entity)) {
        out += c;
        i += entity.size() - 1;
        break;
      }
  }
  return out;
}

// The value of attribute `name` in a start tag, or "".
inline std::string_view svg_attribute(std::string_view tag, std::string_view name) {
  const std::string marker = " " + std::string(name) + "=\"";
  const std::size_t at = tag.find(marker);
  if (at == std::string_view::npos) return {};
  const std::size_t start = at + marker.size();
  const std::size_t end = tag.find('"', start);
  return end == std::string_view::npos ? std::string_view() : tag.substr(start, end - start);
}

inline bool svg_number(std::string_view text, double& value) {
  if (text.empty()) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

inline SvgLabels svg_labels(std::string_view svg) {
  SvgLabels result;
  // Open elements: whether each moves its content out of the root's coordinates.
  std::vector<bool> moved;
  int root_depth = -1;
  for (std::size_t at = svg.find('<'); at != std::string_view::npos; at = svg.find('<', at + 1)) {
    const std::size_t end = svg.find('>', at);
    if (end == std::string_view::npos) break;
    const std::string_view tag = svg.substr(at, end - at + 1);
    if (tag.starts_with("<?") || tag.starts_with("<!")) continue;
    if (tag.starts_with("</")) {
      if (!moved.empty()) moved.pop_back();
      continue;
    }
    const bool self_closing = tag.ends_with("/>");
    const bool is_svg = tag.starts_with("<svg ") || tag.starts_with("<svg>");
    if (is_svg && root_depth < 0) {
      root_depth = static_cast<int>(moved.size());
      if (!svg_number(svg_attribute(tag, "width"), result.width) ||
          !svg_number(svg_attribute(tag, "height"), result.height))
        result.problems.push_back("root without a width and height in pixels");
      const std::string_view view_box = svg_attribute(tag, "viewBox");
      if (view_box != "0 0 " + std::string(svg_attribute(tag, "width")) + " " +
                          std::string(svg_attribute(tag, "height")))
        result.problems.push_back("root viewBox '" + std::string(view_box) + "' is not in pixels");
    }
    if (tag.starts_with("<text")) {
      const std::size_t close = svg.find("</text>", end);
      const std::string text = xml_unescaped(svg.substr(end + 1, close - end - 1));
      bool inside_moved = false;
      for (const bool m : moved) inside_moved = inside_moved || m;
      double x = 0, y = 0, size = 0;
      if (inside_moved) {
        result.problems.push_back("'" + text + "' is inside a nested or transformed element");
      } else if (!svg_number(svg_attribute(tag, "x"), x) ||
                 !svg_number(svg_attribute(tag, "y"), y) ||
                 !svg_number(svg_attribute(tag, "font-size"), size) ||
                 svg_attribute(tag, "text-anchor") != "" || svg_attribute(tag, "transform") != "") {
        result.problems.push_back("'" + text +
                                  "' has no plain x, y and font-size: " + std::string(tag));
      } else {
        const TextFont font{size, svg_attribute(tag, "font-weight") == "bold"};
        result.labels.push_back({text, text_box(x, y, text, font)});
      }
      at = close;
      continue;
    }
    if (self_closing) continue;
    const bool nested_svg = is_svg && root_depth != static_cast<int>(moved.size());
    moved.push_back(nested_svg || svg_attribute(tag, "transform") != "");
  }
  return result;
}

// What is wrong with a picture's labels and shape, one line each: text that cannot be measured,
// a label leaving the canvas or covering another, sides further apart than 1:3.
inline std::string layout_problems(std::string_view svg) {
  const SvgLabels read = svg_labels(svg);
  std::ostringstream problems;
  for (const std::string& problem : read.problems) problems << problem << "\n";
  if (read.width <= 0 || read.height <= 0) return problems.str() + "no size\n";
  const double ratio = read.width / read.height;
  if (ratio > 3 || ratio < 1.0 / 3)
    problems << "aspect ratio " << read.width << " x " << read.height << "\n";
  const PixelBox canvas{0, 0, read.width, read.height};
  for (const SvgLabel& label : read.labels)
    if (!contains(canvas, label.box))
      problems << "'" << label.text << "' leaves the canvas (" << label.box.left << ", "
               << label.box.top << " to " << label.box.right << ", " << label.box.bottom << ")\n";
  for (std::size_t i = 0; i < read.labels.size(); ++i)
    for (std::size_t j = i + 1; j < read.labels.size(); ++j)
      if (overlaps(read.labels[i].box, read.labels[j].box))
        problems << "'" << read.labels[i].text << "' overlaps '" << read.labels[j].text << "'\n";
  if (read.labels.empty()) problems << "no labels at all\n";
  return problems.str();
}

}  // namespace scenfuzz::test
