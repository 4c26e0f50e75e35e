// A campaign search's task and result as bytes, for the MPI ranks that run searches for rank 0
// (mpi_round.hpp). A result carries its findings' files (the scenario and its sidecars), so that
// rank 0 can record the failure modes whether or not the worker's disk is its own.
#pragma once

#include <string>
#include <vector>

#include "fuzz/campaign/campaign_search.hpp"

namespace scenfuzz {

// A file a worker wrote, by its path relative to the campaign folder.
struct WireFile {
  std::string path;
  std::string content;
};

std::string encode_task(const CampaignSearchTask& task);
CampaignSearchTask decode_task(const std::string& bytes);

// `files` are those of the result's findings (finding_files() gathers them).
std::string encode_result(const CampaignSearchResult& result, const std::vector<WireFile>& files);
CampaignSearchResult decode_result(const std::string& bytes, std::vector<WireFile>& files);

// The files of `result`'s findings as they are on this rank's disk: each finding's sidecars
// (mode_files.hpp), then its scenario file. An error message names a file that cannot be read.
std::vector<WireFile> finding_files(const CampaignSearchResult& result, std::string& error);

// Writes the files a worker sent where they are missing (atomically, in order, so a scenario
// file appears after its sidecars); an error message or empty.
std::string place_files(const std::vector<WireFile>& files);

}  // namespace scenfuzz
