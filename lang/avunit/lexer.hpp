// Splits AVUnit / scenest text into tokens. Comments (`//`, `#`, `/* */`) and white space are
// skipped; straight and typographic quotes both delimit strings.
#pragma once

#include <vector>

#include "lang/avunit/token.hpp"
#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz::avunit {

// Always ends with an end_of_file token. Bad characters are reported and skipped.
std::vector<Token> tokenize(const SourceFile& file, Diagnostics& diagnostics);

}  // namespace scenfuzz::avunit
