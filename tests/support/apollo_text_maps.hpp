// Tiny Apollo text maps written by tests that need a map file of their own (search paths, error
// messages), shared by the physics and command-line tests.
#pragma once

#include <string>

namespace scenfuzz::test {

// The smallest Apollo text map the reader accepts: one 10 m lane. The lane id tells which file
// was read when several could have been.
inline std::string one_lane_map(const std::string& lane_id) {
  return "header { projection { proj: \"+proj=utm +zone=10 +ellps=WGS84\" } }\n"
         "lane {\n"
         "  id { id: \"" +
         lane_id +
         "\" }\n"
         "  central_curve { segment { line_segment {\n"
         "    point { x: 0 y: 0 } point { x: 10 y: 0 } } } }\n"
         "}\n";
}

// A syntax error on line 5: a number expected, a word found.
inline constexpr const char* kBrokenMap =
    "header {\n"
    "  projection { proj: \"x\" }\n"
    "}\n"
    "lane {\n"
    "  speed_limit: fast\n"
    "}\n";
inline constexpr int kBrokenMapLine = 5;

}  // namespace scenfuzz::test
