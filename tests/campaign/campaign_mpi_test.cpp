// A campaign under mpirun ends with the database of a single process: the small campaign run
// twice (the second run replays the first's failure modes) by one process and by
// `mpirun --oversubscribe -np 3` (rank 0 and two worker ranks) gives the same canonical dump.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

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

  // `scenfuzz campaign run DIR` under mpirun with `ranks` processes; its exit status.
  int mpirun(int ranks, const std::filesystem::path& dir) {
    // Open MPI refuses root without these; CI containers run as root.
    const std::string command =
        "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout -k 5 300 mpirun "
        "--oversubscribe -np " +
        std::to_string(ranks) + " " + shell_quote(SCENFUZZ_EXECUTABLE) + " campaign run " +
        shell_quote(dir.string()) + " -j 1 </dev/null >" +
        shell_quote((dir_ / "mpi.out").string()) + " 2>&1";
    const int status = std::system(command.c_str());
    return status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
};

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

}  // namespace
}  // namespace scenfuzz::test
