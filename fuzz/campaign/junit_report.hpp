// A campaign run as JUnit XML, for CI systems (Jenkins, GitLab, GitHub test reporters): one
// <testsuite> per seed scenario, one <testcase> per known failure mode of it. A mode that is new,
// still failing, flaky or regressed in this run is a <failure> whose message names its status,
// spec, responsibility and replay command; a fixed one passes; one whose replay met an error
// (and no search found it) is an <error>; one this run neither replayed nor found is <skipped>.
// docs/campaigns.md, "Regression replay and CI outputs", has an example.
#pragma once

#include <string>

#include "fuzz/campaign/run_summary.hpp"

namespace scenfuzz {

// The XML document, UTF-8, with its declaration.
std::string junit_xml(const RunSummary& summary);

}  // namespace scenfuzz
