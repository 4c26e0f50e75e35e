// Output files appear whole or not at all: written to a temporary file beside the target, then
// renamed over it, so a crash or a full disk never leaves a half-written finding or drawing.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace scenfuzz {

// Returns an empty string on success, otherwise why it failed, naming the file ("cannot write
// 'path': No space left on device"); the target is then left untouched.
std::string write_file_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace scenfuzz
