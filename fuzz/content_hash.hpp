// The content hash that names seeds (campaigns, cmin, a search's identity) and content-addressed
// files: 64-bit FNV-1a of the exact bytes, as 16 lower-case hex digits. Stable across machines,
// builds and versions (the database keeps these names), not cryptographic: it tells an edited file
// from the original, it does not defend against someone forging one.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace scenfuzz {

std::uint64_t fnv1a_64(std::string_view bytes);

// fnv1a_64 of `bytes` as 16 hex digits ("cbf29ce484222325" for no bytes).
std::string content_hash(std::string_view bytes);

// content_hash of a file's bytes; nullopt when it cannot be read.
std::optional<std::string> file_content_hash(const std::filesystem::path& path);

}  // namespace scenfuzz
