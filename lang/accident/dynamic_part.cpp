// The DYNAMIC part: the vehicles, each with its ID, its kind, where it comes from and goes, and
// the chain of events it goes through.
#include "lang/accident/parts.hpp"
#include "lang/accident/values.hpp"

namespace scenfuzz::accident {

void PartReader::read_dynamic(const Token& keyword) {
  file.dynamic_at = keyword.location;
  const Block block =
      blocks.read(keyword, Context::dynamics,
                  [&](const Token& key, const std::string&, bool) { read_vehicle(key); });
  blocks.require(block, "VEHICLE",
                 "the DYNAMIC part lists no VEHICLE: add 'VEHICLE [ ID = car1; KIND = car; ]'");
}

void PartReader::read_vehicle(const Token& keyword) {
  Vehicle vehicle;
  const Block block = blocks.read(
      keyword, Context::vehicle, [&](const Token& key, const std::string& name, bool again) {
        if (name == "ID") {
          auto id = read_name_property(cursor, key, "the ID");
          if (id && !again) vehicle.id = *id;
        } else if (name == "KIND") {
          auto kind = read_word_property(cursor, key, vehicle_kinds());
          if (kind && !again) vehicle.kind = *kind;
        } else if (name == "INITDIRECTION") {
          auto direction = read_word_property(cursor, key, directions());
          if (direction && !again) vehicle.init_direction = *direction;
        } else if (name == "STARTSIGN" || name == "ENDSIGN") {
          auto sign = read_sign_property(cursor, key);
          auto& field = name == "STARTSIGN" ? vehicle.start_sign : vehicle.end_sign;
          if (sign && !again) field = *sign;
        } else {
          Vehicle scratch;  // a second CHAIN is read for its mistakes, then dropped
          read_chain(key, again ? scratch : vehicle);
        }
      });
  blocks.require(block, "ID", "this VEHICLE has no ID: add 'ID = car1;'");
  blocks.require(block, "KIND", "this VEHICLE has no KIND: add 'KIND = car;' (or truck)");
  vehicle.location = block.location;
  file.vehicles.push_back(vehicle);
}

void PartReader::read_chain(const Token& keyword, Vehicle& vehicle) {
  const Block block =
      blocks.read(keyword, Context::chain, [&](const Token& key, const std::string& name, bool) {
        read_event(key, name == "CRITICAL_EVENT", vehicle);
      });
  if (block.closed && block.clean && vehicle.chain.empty())
    cursor.error(keyword.location,
                 "this CHAIN lists no EVENT: add 'EVENT [ KIND = driving_forward; ]' or leave "
                 "the CHAIN out");
}

void PartReader::read_event(const Token& keyword, bool critical, Vehicle& vehicle) {
  Event event;
  event.critical = critical;
  const Block block =
      blocks.read(keyword, Context::event, [&](const Token& key, const std::string&, bool again) {
        auto kind = read_word_property(cursor, key, event_kinds());
        if (kind && !again) event.kind = *kind;
      });
  blocks.require(block, "KIND",
                 "this " + upper(keyword.text) +
                     " has no KIND: add 'KIND = driving_forward;' (or turn_left, turn_right, "
                     "stop, overtake, change_lane_left, change_lane_right)");
  event.location = block.location;
  vehicle.chain.push_back(event);
}

}  // namespace scenfuzz::accident
