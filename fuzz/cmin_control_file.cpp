// The control file's lines: JSON objects, a header naming the coverage options, then records.
#include "fuzz/cmin_control_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

namespace scenfuzz {

namespace {

constexpr const char* kFormat = "scenfuzz cmin control";
constexpr int kVersion = 1;

bool is_header(const nlohmann::json& line, const std::string& identity) {
  return line.is_object() && line.value("format", "") == kFormat &&
         line.value("version", 0) == kVersion && line.value("identity", "") == identity;
}

// The record a line holds, or false when it is not one (cut short, or not written by cmin).
bool parse_record(const std::string& text, CminRecord& record) {
  const nlohmann::json line = nlohmann::json::parse(text, nullptr, false);
  if (!line.is_object()) return false;
  try {
    record.hash = line.at("hash").get<std::string>();
    SeedCoverage& coverage = record.coverage;
    coverage.path = line.at("path").get<std::string>();
    coverage.features = line.at("features").get<std::vector<std::string>>();
    coverage.simulations = line.at("simulations").get<std::size_t>();
    coverage.simulated_steps = line.at("simulated_steps").get<std::uint64_t>();
    coverage.file_size = line.at("size").get<std::uintmax_t>();
    coverage.logical = line.at("logical").get<bool>();
    coverage.error = line.at("error").get<std::string>();
  } catch (const nlohmann::json::exception&) {
    return false;
  }
  return !record.hash.empty() && !record.coverage.path.empty();
}

}  // namespace

std::string cmin_control_header(const std::string& identity) {
  const nlohmann::json header = {
      {"format", kFormat}, {"version", kVersion}, {"identity", identity}};
  return header.dump() + "\n";
}

std::string cmin_control_line(const CminRecord& record) {
  const SeedCoverage& coverage = record.coverage;
  // The keys in a fixed order, so that the same coverage is the same line.
  nlohmann::ordered_json line;
  line["path"] = coverage.path;
  line["hash"] = record.hash;
  line["size"] = coverage.file_size;
  line["simulations"] = coverage.simulations;
  line["simulated_steps"] = coverage.simulated_steps;
  line["logical"] = coverage.logical;
  line["features"] = coverage.features;
  line["error"] = coverage.error;
  // Replacement of invalid UTF-8 (a seed's bytes quoted in an error) rather than an exception.
  return line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

CminControlContents read_cmin_control(const std::filesystem::path& path,
                                      const std::string& identity) {
  CminControlContents contents;
  std::ifstream in(path, std::ios::binary);
  if (!in) return contents;
  contents.existed = true;
  std::string text;
  if (!std::getline(in, text) ||
      !is_header(nlohmann::json::parse(text, nullptr, false), identity)) {
    contents.other_identity = true;
    return contents;
  }
  while (std::getline(in, text)) {
    CminRecord record;
    if (!parse_record(text, record)) {
      ++contents.unreadable_lines;
      continue;
    }
    const std::string key = record.coverage.path;
    contents.records[key] = std::move(record);
  }
  return contents;
}

CminControlAppender::~CminControlAppender() {
  if (descriptor_ >= 0) ::close(descriptor_);
}

std::string CminControlAppender::open(const std::filesystem::path& path) {
  path_ = path;
  descriptor_ = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (descriptor_ < 0) return "cannot write '" + path.string() + "': " + std::strerror(errno);
  return {};
}

std::string CminControlAppender::append(const std::string& line) {
  std::lock_guard<std::mutex> lock(mutex_);
  const char* data = line.data();
  std::size_t left = line.size();
  while (left > 0) {
    const ssize_t written = ::write(descriptor_, data, left);
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) return "cannot write '" + path_.string() + "': " + std::strerror(errno);
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  return {};
}

}  // namespace scenfuzz
