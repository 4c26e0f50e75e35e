// Which vehicle an overtake overtakes (overtaken.hpp says the rule).
#include "lang/accident/overtaken.hpp"

#include <cstddef>
#include <optional>

#include "lang/accident/way_in.hpp"
#include "lang/demand.hpp"

namespace scenfuzz::accident {

bool overtakes(const Vehicle& vehicle) {
  for (const Event& event : vehicle.chain)
    if (event.kind.value == EventKind::overtake) return true;
  return false;
}

const Vehicle* overtaken_vehicle(const File& file, const SceneLayout& layout,
                                 const Vehicle& overtaker) {
  if (!overtakes(overtaker)) return nullptr;
  const std::optional<Direction> heading = way_in_heading(file, layout, overtaker);
  if (!heading) return nullptr;
  const std::optional<int> lane = fixed_start_lane(file, overtaker, layout.lanes);
  std::size_t at = 0;
  while (at < file.vehicles.size() && &file.vehicles[at] != &overtaker) ++at;
  SCENFUZZ_DEMAND(at < file.vehicles.size());  // the overtaker is one of the file's vehicles
  const Vehicle* nearest = nullptr;
  std::size_t nearest_distance = file.vehicles.size();
  for (std::size_t i = 0; i < file.vehicles.size(); ++i) {
    const Vehicle& other = file.vehicles[i];
    if (i == at || overtakes(other) || way_in_heading(file, layout, other) != heading) continue;
    const std::optional<int> other_lane = fixed_start_lane(file, other, layout.lanes);
    if (other_lane && other_lane != lane) continue;
    const std::size_t distance = i < at ? at - i : i - at;
    if (distance < nearest_distance) {  // strictly: the earlier of two as near stays
      nearest = &other;
      nearest_distance = distance;
    }
  }
  return nearest;
}

const Vehicle* overtaker_of(const File& file, const SceneLayout& layout, const Vehicle& vehicle) {
  for (const Vehicle& other : file.vehicles)
    if (&other != &vehicle && overtaken_vehicle(file, layout, other) == &vehicle) return &other;
  return nullptr;
}

}  // namespace scenfuzz::accident
