// Where the lang tests find their inputs: the bundled corpus, the shared examples, golden data.
#pragma once

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz::test {

inline std::filesystem::path lang_data_dir() { return SCENFUZZ_TEST_DATA_DIR; }

inline std::filesystem::path corpus_dir() {
  return lang_data_dir().parent_path().parent_path().parent_path() / "corpora" / "avunit";
}

// Files under `folder` whose names end with one of `extensions`, sorted.
inline std::vector<std::filesystem::path> files_in(const std::filesystem::path& folder,
                                                   const std::vector<std::string>& extensions) {
  std::vector<std::filesystem::path> files;
  if (!std::filesystem::is_directory(folder)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    for (const std::string& extension : extensions)
      if (entry.path().extension() == extension) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

inline SourceFile load(const std::filesystem::path& path) {
  std::optional<SourceFile> file = read_source_file(path.string());
  if (!file) throw std::runtime_error("cannot read " + path.string());
  return std::move(*file);
}

inline avunit::ParseResult parse_text(const std::string& text,
                                      const std::string& path = "test.avu") {
  return avunit::parse(SourceFile(path, text));
}

}  // namespace scenfuzz::test

namespace scenfuzz {

// GoogleTest shows a template as the AVUnit it prints to, with its parameters.
inline void PrintTo(const ScenarioTemplate& scenario, std::ostream* out) {
  *out << "\n" << avunit::print(scenario);
  for (const Parameter& parameter : scenario.parameters)
    *out << "// parameter " << parameter.name << " [" << parameter.lower << ", " << parameter.upper
         << "] " << parameter.unit << "\n";
}

}  // namespace scenfuzz
