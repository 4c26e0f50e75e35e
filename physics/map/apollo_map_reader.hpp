// Reads Apollo HD maps (apollo.hdmap.Map) in protobuf text format (base_map.txt) and binary
// format (base_map.bin): lanes, junctions, signals, stop and yield signs, crosswalks, the lanes
// each of them meets (from the map's overlaps) and the header's projection. Fields scenfuzz does
// not use are skipped.
#pragma once

#include <filesystem>

#include "physics/map/map_description.hpp"

namespace scenfuzz {

// Both throw MapError naming the file (and line:column for text) for unreadable, malformed or
// truncated input.
MapDescription read_apollo_map_text(const std::filesystem::path& file);
MapDescription read_apollo_map_binary(const std::filesystem::path& file);
// By extension: ".txt" is text, anything else binary.
MapDescription read_apollo_map(const std::filesystem::path& file);

}  // namespace scenfuzz
