// What `scenfuzz reconstruct` says of a driver tested on the reconstruction (driver_test.hpp): the
// verdict in one line with the collision's details under it, the picture's headline, and the
// summary's "driver_test" object.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fuzz/driver_test.hpp"

namespace scenfuzz {

// Who was tested where: the driver (the reference driver, or the plugin library) in the named
// described vehicle's place.
struct DriverSeat {
  std::string driver;   // "the reference driver" or the plugin's path
  std::string vehicle;  // the described vehicle the ego replaces
};

// "the reference driver in car1's place: hit by truck1 at 2.35 s, truck1's fault, and braking
// could not have avoided it": the verdict in words, "finding: " first when it is one.
std::string driver_test_headline(const DriverTest& test, const DriverSeat& seat);

// The headline, then the ego's first collision, whose fault it was with its triage numbers, and
// the avoidability's reasoning, each an indented line.
std::vector<std::string> driver_test_lines(const DriverTest& test, const DriverSeat& seat);

// {"driver", "ego", "verdict", "finding", "reached_target", "collision", "responsibility",
// "avoidability", "written"}; what did not happen is null.
nlohmann::json driver_test_json(const DriverTest& test, const DriverSeat& seat,
                                const std::vector<std::string>& written);

}  // namespace scenfuzz
