// FNV-1a (Fowler, Noll, Vo), 64 bits: offset basis 0xcbf29ce484222325, prime 0x100000001b3.
#include "fuzz/content_hash.hpp"

#include <cstdio>
#include <fstream>
#include <iterator>

namespace scenfuzz {

std::uint64_t fnv1a_64(std::string_view bytes) {
  std::uint64_t state = 0xCBF29CE484222325ull;
  for (const char c : bytes) {
    state ^= static_cast<unsigned char>(c);
    state *= 0x100000001B3ull;
  }
  return state;
}

std::string content_hash(std::string_view bytes) {
  char digits[17];
  std::snprintf(digits, sizeof digits, "%016llx", static_cast<unsigned long long>(fnv1a_64(bytes)));
  return digits;
}

std::optional<std::string> file_content_hash(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return std::nullopt;
  return content_hash(bytes);
}

}  // namespace scenfuzz
