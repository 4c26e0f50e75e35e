#include "fuzz/report_format.hpp"

#include <cmath>

namespace scenfuzz {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

nlohmann::json robustness_json(double robustness) {
  if (std::isinf(robustness)) return robustness > 0 ? "inf" : "-inf";
  return robustness;
}

std::string shell_quote(const std::string& text) {
  if (!text.empty() && text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                              "0123456789_-./:=+") == std::string::npos)
    return text;
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string responsibility_words(const std::string& responsibility) {
  if (responsibility == "ego") return "the ego's fault";
  if (responsibility == "other") return "not the ego's fault";
  if (responsibility == "shared") return "shared fault";
  return responsibility;
}

}  // namespace scenfuzz
