// The accident part (translation.hpp): each collision as an expected collision, its place on the
// map when the description gives one. The reconstruction's objective reads them
// (oracle/collision_reconstruction.hpp).
#include "lang/accident/translation.hpp"

namespace scenfuzz::accident {

namespace {

VehiclePart part_of(Part part) {
  switch (part) {
    case Part::front: return VehiclePart::front;
    case Part::rear: return VehiclePart::rear;
    case Part::leftside: return VehiclePart::left_side;
    case Part::rightside: return VehiclePart::right_side;
    case Part::unknown: return VehiclePart::unknown;
  }
  return VehiclePart::unknown;
}

}  // namespace

void translate_collisions(Translation& translation) {
  for (const Collision& collision : translation.file.collisions) {
    ExpectedCollision expected;
    expected.striker = collision.actor.id.text;
    expected.victim = collision.victim.id.text;
    expected.striker_part = part_of(collision.actor.part.value);
    expected.victim_part = part_of(collision.victim.part.value);
    expected.location = collision.location;
    if (collision.coords) {
      const PlanePoint on_map =
          translation.layout.on_map({collision.coords->x, collision.coords->y});
      Position position;
      position.x = constant_value(on_map.x, collision.coords->x_at);
      position.y = constant_value(on_map.y, collision.coords->y_at);
      position.location = collision.coords->location;
      expected.position = position;
    }
    translation.scenario.expected_collisions.push_back(std::move(expected));
  }
}

}  // namespace scenfuzz::accident
