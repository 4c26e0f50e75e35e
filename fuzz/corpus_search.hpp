// `scenfuzz --budget N DIR/` (or several files): one search per seed scenario of a corpus, the
// budget shared evenly, each seed's output in a folder of its own under --out, and corpus.json
// listing them (docs/search.md, "Searching a corpus"). Adaptive sharing over nights is what
// `scenfuzz campaign` is for; this is the single run over a folder.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "fuzz/commands.hpp"

namespace scenfuzz {

// Whether the search's FILE arguments name a corpus rather than one scenario: several entries,
// or a folder.
bool is_corpus_search(const std::vector<std::string>& entries);

// The budget of each of `seeds` searches out of `budget`: even shares, the first `budget % seeds`
// one simulation more. Every share is at least 1 (the caller checks budget >= seeds).
std::vector<std::size_t> corpus_budget_shares(std::size_t budget, std::size_t seeds);

// The folder name of each seed under --out: its file name without extension, with "-2", "-3"
// after a name an earlier seed already has.
std::vector<std::string> corpus_folder_names(const std::vector<std::string>& seed_files);

// Searches every seed of the corpus `entries` (files and folders, expanded as a campaign's seeds
// are) with `options`, each in --out/<name>/ with its budget share. Every seed is read and checked
// before any search starts: one with errors stops everything (kExitBadInput). Exit status:
// kExitBadInput when a seed's search could not run or judge anything, else kExitViolated when any
// seed has findings, else kExitSuccess.
int run_corpus_search(const FuzzCommandOptions& options, const std::vector<std::string>& entries,
                      std::ostream& out, std::ostream& err);

}  // namespace scenfuzz
