// A campaign under mpirun ends with the database of a single process: the small campaign run
// twice (the second run replays the first's failure modes) by one process and by
// `mpirun --oversubscribe -np 3` (rank 0 and two worker ranks) gives the same canonical dump,
// also when a worker rank is killed in the middle of a search (its search goes to the other).
#include <dirent.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

#include "tests/campaign/campaign_fixture.hpp"

namespace scenfuzz::test {
namespace {

class CampaignMpiTest : public CommandTest {
 protected:
  std::filesystem::path campaign(const std::string& name) {
    const std::filesystem::path dir = dir_ / name;
    std::filesystem::create_directories(dir);
    write(name + "/campaign.toml", campaign_toml(small_campaign_seeds(), "simulations = 320"));
    return dir;
  }

  // `scenfuzz campaign run DIR` under mpirun with `ranks` processes (`options` for mpirun, then
  // `run_options` for campaign run); its exit status.
  int mpirun(int ranks, const std::filesystem::path& dir, const std::string& options = "",
             const std::string& run_options = "") {
    // Open MPI refuses root without these; CI containers run as root.
    const std::string command =
        "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout -k 5 300 mpirun "
        "--oversubscribe " +
        options + " -np " + std::to_string(ranks) + " " + shell_quote(SCENFUZZ_EXECUTABLE) +
        " campaign run " + shell_quote(dir.string()) + " -j 1 " + run_options + " </dev/null >" +
        shell_quote((dir_ / "mpi.out").string()) + " 2>&1";
    const int status = std::system(command.c_str());
    return status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
};

// The process of MPI rank `rank` running a campaign in `dir`, or 0: found by its environment.
pid_t rank_process(int rank, const std::filesystem::path& dir) {
  const std::string wanted = "OMPI_COMM_WORLD_RANK=" + std::to_string(rank);
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const std::string command = slurp(entry.path() / "cmdline");
    const std::string environment = slurp(entry.path() / "environ");
    if (command.find(dir.string()) == std::string::npos) continue;
    for (std::size_t at = 0; at < environment.size();) {
      const std::size_t end = environment.find('\0', at);
      if (environment.substr(at, end - at) == wanted) return static_cast<pid_t>(std::stoi(name));
      if (end == std::string::npos) break;
      at = end + 1;
    }
  }
  return 0;
}

TEST_F(CampaignMpiTest, ThreeRanksEndWithTheDatabaseOfOneProcess) {
  const std::filesystem::path alone = campaign("alone"), ranks = campaign("ranks");
  for (int run = 1; run <= 2; ++run) {
    const Outcome one = scenfuzz({"campaign", "run", alone.string(), "-j", "1"});
    ASSERT_TRUE(one.exit_code == 0 || one.exit_code == 1) << one.err;
    const int status = mpirun(3, ranks);
    ASSERT_EQ(status, one.exit_code) << slurp(dir_ / "mpi.out");
    // Rank 0 alone speaks: each search is reported once, as by one process.
    EXPECT_EQ(slurp(dir_ / "mpi.out").find(one.out), 0u)
        << "mpirun said:\n"
        << slurp(dir_ / "mpi.out") << "one process said:\n"
        << one.out;
  }
  const std::string expected = canonical_dump(alone), got = canonical_dump(ranks);
  EXPECT_NE(expected.find("replay "), std::string::npos) << "the second run replayed nothing";
  EXPECT_EQ(got, expected) << first_difference(got, expected);
}

TEST_F(CampaignMpiTest, AWorkerRankKilledInASearchLosesNothing) {
  const std::filesystem::path alone = campaign("alone"), ranks = campaign("ranks");
  const Outcome one = scenfuzz({"campaign", "run", alone.string(), "-j", "1"});
  ASSERT_TRUE(one.exit_code == 0 || one.exit_code == 1) << one.err;
  // Rank 2 is killed as soon as a search of its is under way (its folder has a journal).
  bool killed = false;
  std::thread killer([&] {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < give_up) {
      const pid_t worker = rank_process(2, ranks);
      if (worker != 0 && std::filesystem::exists(ranks / "searches")) {
        killed = ::kill(worker, SIGKILL) == 0;
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  });
  // --enable-recovery: Open MPI ends the whole job when a rank dies without it.
  // mpirun --enable-recovery exits 0 whatever its ranks' statuses (Open MPI 4.1): the outcome is
  // in rank 0's words and in the database.
  mpirun(3, ranks, "--enable-recovery", "--worker-timeout 2");
  killer.join();
  ASSERT_TRUE(killed) << "rank 2 was never found running";
  const std::string said = slurp(dir_ / "mpi.out");
  EXPECT_NE(said.find(one.out.substr(one.out.rfind("exit status"))), std::string::npos) << said;
  const std::string expected = canonical_dump(alone), got = canonical_dump(ranks);
  EXPECT_EQ(got, expected) << first_difference(got, expected);
}

}  // namespace
}  // namespace scenfuzz::test
