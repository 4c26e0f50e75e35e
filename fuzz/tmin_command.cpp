// `scenfuzz tmin FINDING [-o OUT]`: minimise a failing scenario (fuzz/tmin_finding.hpp) and say
// what was removed, what was written and how to replay it.
#include <ostream>

#include "fuzz/cli.hpp"
#include "fuzz/commands.hpp"
#include "fuzz/tmin_finding.hpp"

namespace scenfuzz {

int run_tmin(const TminCommandOptions& options, std::ostream& out, std::ostream& err) {
  const TminResult result = minimize_finding(options.path, TminOptions{options.out_path, {}});
  if (!result.ok()) {
    err << "scenfuzz: error: " << result.error << "\n";
    return kExitBadInput;
  }
  out << "failure mode: " << result.mode << "\n";
  for (const std::string& change : result.changes) out << change << "\n";
  if (result.changes.empty()) out << "nothing could be removed or changed\n";
  out << "actors " << result.actors_before << " -> " << result.actors_before - result.actors_removed
      << ", significant digits " << result.digits_before << " -> " << result.digits_after << ", "
      << result.replays << " replays\n";
  out << "wrote " << result.out_path << "\n";
  out << "replay: " << result.replay << "\n";
  return kExitSuccess;
}

}  // namespace scenfuzz
