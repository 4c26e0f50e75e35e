// Small text formats the commands share: CSV fields, robustness in JSON (which has no
// infinities), responsibility in words, and words quoted for a POSIX shell.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace scenfuzz {

// A CSV field, quoted as RFC 4180 says when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text);

// A robustness for JSON: the number, or the strings "inf" and "-inf".
nlohmann::json robustness_json(double robustness);

// "the ego's fault", "not the ego's fault", "shared fault" for a responsibility's name ("ego",
// "other", "shared"; oracle/responsibility.hpp).
std::string responsibility_words(const std::string& responsibility);

// `text` as one word for a POSIX shell (unquoted when that is safe).
std::string shell_quote(const std::string& text);

}  // namespace scenfuzz
