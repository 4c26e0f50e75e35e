#include "lang/source_file.hpp"

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "lang/line_break.hpp"

namespace scenfuzz {

SourceFile::SourceFile(std::string path, std::string text)
    : path_(std::move(path)), text_(std::move(text)) {
  // LF, CRLF and a lone CR each end a line, as they do for the lexers' line numbers.
  std::string_view all(text_);
  line_starts_.push_back(0);
  for (std::size_t i = find_line_break(all, 0); i < all.size();
       i = find_line_break(all, line_starts_.back())) {
    line_starts_.push_back(i + line_break_width(all, i));
  }
}

std::string_view SourceFile::line_text(std::uint32_t line) const {
  if (line == 0 || line > line_starts_.size()) return {};
  std::string_view text(text_);
  std::size_t begin = line_starts_[line - 1];
  return text.substr(begin, find_line_break(text, begin) - begin);
}

std::optional<SourceFile> read_source_file(const std::string& path) {
  // An ifstream opens a directory and reads nothing from it.
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    errno = EISDIR;
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return SourceFile(path, buffer.str());
}

}  // namespace scenfuzz
