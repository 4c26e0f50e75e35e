// The level-2 printer's shared pieces (internal): how leaves are written, and the printers of the
// scenery and dynamic sections, each in its own file.
#pragma once

#include <string>
#include <vector>

#include "lang/wmg/syntax.hpp"
#include "lang/wmg/vocabulary.hpp"

namespace scenfuzz::wmg::detail {

std::string number_text(double value);
std::string label_text(const Label& label);
std::string lane_text(const LaneName& lane);
// The canonical phrase of a closed enumeration's value.
template <typename Enumeration>
std::string phrase_of(const Vocabulary& vocabulary, Enumeration value) {
  return vocabulary.phrases.at(static_cast<std::size_t>(value));
}
// `[text]`.
std::string bracketed(const std::string& text);
// The texts joined with ", ".
std::string joined(const std::vector<std::string>& texts, const std::string& separator = ", ");

std::string print_scenery(const Scenery& scenery);
std::string print_dynamics(const Dynamics& dynamics);

}  // namespace scenfuzz::wmg::detail
