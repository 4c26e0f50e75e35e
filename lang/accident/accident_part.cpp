// The ACCIDENT part: the collisions, each an actor (a vehicle), a victim (a vehicle or a static
// object with an ID) with the part of each that was hit, and where it happened.
#include "lang/accident/parts.hpp"
#include "lang/accident/values.hpp"

namespace scenfuzz::accident {

void PartReader::read_accident(const Token& keyword) {
  file.accident_at = keyword.location;
  const Block block =
      blocks.read(keyword, Context::accident,
                  [&](const Token& key, const std::string&, bool) { read_collision(key); });
  blocks.require(block, "COLLISION",
                 "the ACCIDENT part lists no COLLISION: add 'COLLISION [ ACTOR = car1, front; "
                 "VICTIM = car2, rear; ]'");
}

void PartReader::read_collision(const Token& keyword) {
  Collision collision;
  const Block block = blocks.read(
      keyword, Context::collision, [&](const Token& key, const std::string& name, bool again) {
        if (name == "COORD") {
          auto point = read_point_property(cursor, key);
          if (point && !again) collision.coords = *point;
          return;
        }
        auto involvement = read_involvement_property(cursor, key);
        auto& field = name == "ACTOR" ? collision.actor : collision.victim;
        if (involvement && !again) field = *involvement;
      });
  blocks.require(block, "ACTOR",
                 "this COLLISION has no ACTOR: add 'ACTOR = car1, front;' (the vehicle that hit)");
  blocks.require(block, "VICTIM",
                 "this COLLISION has no VICTIM: add 'VICTIM = car2, rear;' (what was hit)");
  collision.location = block.location;
  file.collisions.push_back(collision);
}

}  // namespace scenfuzz::accident
