#include "fuzz/search_journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "fuzz/report_format.hpp"
#include "lang/number_format.hpp"
#include "oracle/trace_audit.hpp"

namespace scenfuzz {

namespace fs = std::filesystem;

namespace {

// The fixed columns before the parameters and after the specs.
constexpr std::size_t kLeading = 5;  // evaluation, seed, target, status, kind
// audit, endings, violated, responsibility, collision_reason, signature, wall_seconds, reason,
// coverage, sub_robustness
constexpr std::size_t kTrailing = 10;

std::string status_name(const Evaluation& evaluation) {
  return !evaluation.feasible() ? "infeasible" : !evaluation.judged() ? "failed" : "judged";
}

// Splits CSV text into records of fields (RFC 4180: quoted fields may hold commas, quotes and
// line breaks). `complete` is the length of the text up to the end of the last whole record.
std::vector<std::vector<std::string>> split_csv(const std::string& text, std::size_t& complete) {
  std::vector<std::vector<std::string>> records;
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  complete = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c != '"') {
        field += c;
      } else if (i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else {
        quoted = false;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.push_back(std::move(field));
      field.clear();
    } else if (c == '\n') {
      fields.push_back(std::move(field));
      field.clear();
      records.push_back(std::move(fields));
      fields.clear();
      complete = i + 1;
    } else {
      field += c;
    }
  }
  return records;
}

bool parse_number(const std::string& text, double& value) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end;
}

template <typename Integer>
bool parse_integer(const std::string& text, Integer& value) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end && !text.empty();
}

// "off_road=1;yaw_rate_inconsistent=2": the audit's non-zero counts by kind; empty when clean.
std::string audit_text(const std::vector<std::size_t>& counts) {
  std::string text;
  for (std::size_t k = 0; k < counts.size(); ++k)
    if (counts[k] > 0)
      text += (text.empty() ? "" : ";") + std::string(audit_kind_name(static_cast<AuditKind>(k))) +
              "=" + std::to_string(counts[k]);
  return text;
}

bool parse_audit(const std::string& text, std::vector<std::size_t>& counts) {
  counts.clear();
  if (text.empty()) return true;
  counts.assign(kAuditKindCount, 0);
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    const std::string item = text.substr(start, end - start);
    const std::size_t equals = item.find('=');
    if (equals == std::string::npos) return false;
    const std::string name = item.substr(0, equals);
    std::size_t kind = 0;
    while (kind < kAuditKindCount && audit_kind_name(static_cast<AuditKind>(kind)) != name) ++kind;
    if (kind == kAuditKindCount || !parse_integer(item.substr(equals + 1), counts[kind]))
      return false;
    start = end + 1;
  }
  return true;
}

// "reach=time-out;clearance=stuck;speed=start-state": the objectives whose verdict the run's ends
// left open.
std::string endings_text(const std::vector<std::string>& endings,
                         const std::vector<std::string>& objectives) {
  std::string text;
  for (std::size_t k = 0; k < endings.size() && k < objectives.size(); ++k)
    if (!endings[k].empty()) text += (text.empty() ? "" : ";") + objectives[k] + "=" + endings[k];
  return text;
}

bool parse_endings(const std::string& text, const std::vector<std::string>& objectives,
                   std::vector<std::string>& endings) {
  endings.clear();
  if (text.empty()) return true;
  endings.assign(objectives.size(), "");
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    const std::string item = text.substr(start, end - start);
    const std::size_t equals = item.rfind('=');
    if (equals == std::string::npos) return false;
    const auto found = std::find(objectives.begin(), objectives.end(), item.substr(0, equals));
    if (found == objectives.end()) return false;
    endings[static_cast<std::size_t>(found - objectives.begin())] = item.substr(equals + 1);
    start = end + 1;
  }
  return true;
}

// "reach;clearance": the violated objectives by name, the earliest violation first.
std::string violated_text(const std::vector<std::size_t>& violated,
                          const std::vector<std::string>& objectives) {
  std::string text;
  for (std::size_t k : violated)
    if (k < objectives.size()) text += (text.empty() ? "" : ";") + objectives[k];
  return text;
}

bool parse_violated(const std::string& text, const std::vector<std::string>& objectives,
                    std::vector<std::size_t>& violated) {
  violated.clear();
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(';', start);
    if (end == std::string::npos) end = text.size();
    const auto found =
        std::find(objectives.begin(), objectives.end(), text.substr(start, end - start));
    if (found == objectives.end()) return false;
    violated.push_back(static_cast<std::size_t>(found - objectives.begin()));
    start = end + 1;
  }
  return true;
}

// "ego.following;light.day": the run's behaviour-coverage features, in their sorted order.
std::string coverage_text(const std::vector<std::string>& features) {
  std::string text;
  for (const std::string& feature : features) text += (text.empty() ? "" : ";") + feature;
  return text;
}

std::vector<std::string> parse_coverage(const std::string& text) {
  std::vector<std::string> features;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    features.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return features;
}

// "-3.2;0;-inf": the law sub-violations' robustness, exactly.
std::string numbers_text(const std::vector<double>& values) {
  std::string text;
  for (double value : values) text += (text.empty() ? "" : ";") + format_number(value);
  return text;
}

bool parse_numbers(const std::string& text, std::vector<double>& values) {
  values.clear();
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    double value = 0;
    if (!parse_number(text.substr(start, end - start), value)) return false;
    values.push_back(value);
    start = end + 1;
  }
  return true;
}

}  // namespace

SearchJournal::SearchJournal(const ParameterSpace& space, std::vector<std::string> objectives,
                             std::vector<std::string> sub_targets)
    : space_(space), objectives_(std::move(objectives)), target_names_(objectives_) {
  target_names_.insert(target_names_.end(), sub_targets.begin(), sub_targets.end());
  header_ = "evaluation,seed,target,status,kind";
  for (const Dimension& dimension : space_.dimensions) header_ += "," + csv_field(dimension.name);
  for (const Dimension& dimension : space_.dimensions)
    header_ += "," + csv_field("u." + dimension.name);
  for (const std::string& objective : objectives_)
    header_ += "," + csv_field("robustness." + objective);
  for (const std::string& objective : objectives_) header_ += "," + csv_field("guide." + objective);
  header_ +=
      ",audit,endings,violated,responsibility,collision_reason,signature,wall_seconds,reason,"
      "coverage,sub_robustness\n";
}

std::string SearchJournal::row(const EvaluationRecord& record) const {
  const Evaluation& evaluation = record.evaluation;
  std::string row = std::to_string(record.index) + "," + std::to_string(record.seed) + "," +
                    csv_field(target_names_[record.target]) + "," + status_name(evaluation) + "," +
                    csv_field(evaluation.failure_kind);
  const std::vector<double> values = decode(space_, record.point);
  for (std::size_t i = 0; i < space_.dimensions.size(); ++i) {
    const Dimension& dimension = space_.dimensions[i];
    row += "," + (dimension.kind == ParameterKind::discrete
                      ? csv_field(dimension.choices[static_cast<std::size_t>(values[i])])
                      : format_number(values[i]));
  }
  for (double u : record.point) row += "," + format_number(u);
  const bool judged = evaluation.judged();
  for (std::size_t k = 0; k < objectives_.size(); ++k)
    row += "," + (judged ? format_number(evaluation.robustness[k]) : std::string());
  for (std::size_t k = 0; k < objectives_.size(); ++k) {
    const bool differs =
        judged && k < evaluation.guide.size() && evaluation.guide[k] != evaluation.robustness[k];
    row += "," + (differs ? format_number(evaluation.guide[k]) : std::string());
  }
  row += "," + audit_text(evaluation.audit) + "," +
         csv_field(endings_text(evaluation.endings, objectives_)) + "," +
         csv_field(violated_text(evaluation.violated, objectives_)) + "," +
         csv_field(evaluation.responsibility) + "," + csv_field(evaluation.collision_reason) + "," +
         csv_field(evaluation.signature) + "," +
         format_number(std::round(evaluation.wall_seconds * 1e6) / 1e6) + "," +
         csv_field(evaluation.feasible() ? evaluation.failure : evaluation.infeasible) + "," +
         csv_field(coverage_text(evaluation.coverage)) + "," +
         numbers_text(evaluation.sub_robustness) + "\n";
  return row;
}

std::optional<EvaluationRecord> SearchJournal::parse_row(const std::vector<std::string>& fields,
                                                         std::string& error) const {
  const std::size_t d = space_.dimensions.size();
  const std::size_t n = objectives_.size();
  if (fields.size() != kLeading + 2 * d + 2 * n + kTrailing) {
    error = "has " + std::to_string(fields.size()) + " fields";
    return std::nullopt;
  }
  EvaluationRecord record;
  const auto target = std::find(target_names_.begin(), target_names_.end(), fields[2]);
  if (!parse_integer(fields[0], record.index) || !parse_integer(fields[1], record.seed) ||
      target == target_names_.end()) {
    error = "has a bad evaluation, seed or target";
    return std::nullopt;
  }
  record.target = static_cast<std::size_t>(target - target_names_.begin());
  record.point.resize(d);
  for (std::size_t i = 0; i < d; ++i)
    if (!parse_number(fields[kLeading + d + i], record.point[i])) {
      error = "has a bad point";
      return std::nullopt;
    }
  Evaluation& evaluation = record.evaluation;
  const std::string& status = fields[3];
  const std::size_t trailing = kLeading + 2 * d + 2 * n;
  const std::string& reason = fields[trailing + 7];
  evaluation.failure_kind = fields[4];
  if (!parse_audit(fields[trailing], evaluation.audit)) {
    error = "has a bad audit '" + fields[trailing] + "'";
    return std::nullopt;
  }
  if (!parse_endings(fields[trailing + 1], objectives_, evaluation.endings)) {
    error = "has bad endings '" + fields[trailing + 1] + "'";
    return std::nullopt;
  }
  if (!parse_violated(fields[trailing + 2], objectives_, evaluation.violated)) {
    error = "has bad violated specs '" + fields[trailing + 2] + "'";
    return std::nullopt;
  }
  evaluation.responsibility = fields[trailing + 3];
  evaluation.collision_reason = fields[trailing + 4];
  evaluation.signature = fields[trailing + 5];
  parse_number(fields[trailing + 6], evaluation.wall_seconds);
  evaluation.coverage = parse_coverage(fields[trailing + 8]);
  if (!parse_numbers(fields[trailing + 9], evaluation.sub_robustness)) {
    error = "has a bad sub_robustness '" + fields[trailing + 9] + "'";
    return std::nullopt;
  }
  if (status == "infeasible") {
    evaluation.infeasible = reason.empty() ? "infeasible" : reason;
  } else if (status == "failed") {
    evaluation.failure = reason.empty() ? "failed" : reason;
  } else if (status == "judged") {
    evaluation.robustness.resize(n);
    evaluation.guide.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      const std::string& guide = fields[kLeading + 2 * d + n + k];
      if (!parse_number(fields[kLeading + 2 * d + k], evaluation.robustness[k]) ||
          !(guide.empty() ? (evaluation.guide[k] = evaluation.robustness[k], true)
                          : parse_number(guide, evaluation.guide[k]))) {
        error = "has a bad robustness";
        return std::nullopt;
      }
    }
  } else {
    error = "has an unknown status '" + status + "'";
    return std::nullopt;
  }
  return record;
}

std::optional<std::vector<EvaluationRecord>> SearchJournal::read(const fs::path& path,
                                                                 std::string& error) const {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = "cannot read '" + path.string() + "': " + std::strerror(errno);
    return std::nullopt;
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::size_t complete = 0;
  const std::vector<std::vector<std::string>> rows = split_csv(text, complete);
  if (text.compare(0, header_.size(), header_) != 0) {
    error = "'" + path.string() + "' is not the journal of this search (its columns differ)";
    return std::nullopt;
  }
  std::vector<EvaluationRecord> records;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    std::string why;
    std::optional<EvaluationRecord> record = parse_row(rows[r], why);
    if (!record || record->index != records.size()) {
      error = "'" + path.string() + "': row " + std::to_string(r + 1) + " " +
              (record ? "is out of order" : why);
      return std::nullopt;
    }
    records.push_back(std::move(*record));
  }
  if (complete < text.size()) {
    // A row cut short by a kill: the evaluation it recorded runs again.
    std::error_code ignored;
    fs::resize_file(path, complete, ignored);
    if (ignored) {
      error = "cannot truncate '" + path.string() + "': " + ignored.message();
      return std::nullopt;
    }
  }
  return records;
}

std::string append_to_file(const fs::path& path, const std::string& text) {
  const int descriptor = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (descriptor < 0) return "cannot write '" + path.string() + "': " + std::strerror(errno);
  const char* data = text.data();
  std::size_t left = text.size();
  std::string failure;
  while (left > 0) {
    const ssize_t written = ::write(descriptor, data, left);
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) {
      failure = std::strerror(errno);
      break;
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  if (::close(descriptor) != 0 && failure.empty()) failure = std::strerror(errno);
  return failure.empty() ? "" : "cannot write '" + path.string() + "': " + failure;
}

std::string sync_file(const fs::path& path) {
  const int descriptor = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  std::string failure;
  if (descriptor < 0 || ::fsync(descriptor) != 0) failure = std::strerror(errno);
  if (descriptor >= 0) ::close(descriptor);
  return failure.empty() ? "" : "cannot write '" + path.string() + "': " + failure;
}

}  // namespace scenfuzz
