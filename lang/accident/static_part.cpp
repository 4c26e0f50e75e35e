// The STATIC part: the road layout (exactly one ROAD), trees, traffic lights, level crossings
// and stop signs.
#include "lang/accident/parts.hpp"
#include "lang/accident/values.hpp"

namespace scenfuzz::accident {

void PartReader::read_static(const Token& keyword) {
  file.static_at = keyword.location;
  const Block block =
      blocks.read(keyword, Context::statics, [&](const Token& key, const std::string& name, bool) {
        if (name == "ROAD") return read_road(key);
        if (name == "TREE") return read_tree(key);
        if (name == "LIGHT") return read_light(key);
        if (name == "CROSSING") return read_marker(key, Context::crossing);
        read_marker(key, Context::stop_sign);
      });
  blocks.require(block, "ROAD",
                 "the STATIC part has no ROAD: add 'ROAD [ KIND = crossroad; ]' (or "
                 "straightroad, turn_left, turn_right)");
}

void PartReader::read_road(const Token& keyword) {
  const bool second = first_road.known();
  if (second)
    cursor.error(keyword.location,
                 "a second ROAD: a description has one road layout (the first "
                 "ROAD is at " +
                     place(first_road) + ")");
  else
    first_road = keyword.location;
  Road road;
  const Block block =
      blocks.read(keyword, Context::road, [&](const Token& key, const std::string&, bool again) {
        auto kind = read_word_property(cursor, key, road_kinds());
        if (kind && !again) road.kind = *kind;
      });
  blocks.require(block, "KIND",
                 "this ROAD has no KIND: add 'KIND = crossroad;' (or straightroad, turn_left, "
                 "turn_right)");
  road.location = block.location;
  if (!second) file.road = road;
}

void PartReader::read_tree(const Token& keyword) {
  Tree tree;
  const Block block = blocks.read(keyword, Context::tree,
                                  [&](const Token& key, const std::string& name, bool again) {
                                    if (name == "ID") {
                                      auto id = read_name_property(cursor, key, "the ID");
                                      if (id && !again) tree.id = *id;
                                    } else {
                                      auto point = read_point_property(cursor, key);
                                      if (point && !again) tree.coords = *point;
                                    }
                                  });
  blocks.require(block, "ID", "this TREE has no ID: add 'ID = tree1;'");
  blocks.require(block, "COORD", "this TREE has no COORD: add 'COORD = (x, y);' in metres");
  tree.location = block.location;
  file.trees.push_back(tree);
}

void PartReader::read_light(const Token& keyword) {
  Light light;
  const Block block = blocks.read(keyword, Context::light,
                                  [&](const Token& key, const std::string& name, bool again) {
                                    if (name == "ID") {
                                      auto id = read_name_property(cursor, key, "the ID");
                                      if (id && !again) light.id = *id;
                                    } else if (name == "COLOR") {
                                      auto colour = read_word_property(cursor, key, colours());
                                      if (colour && !again) light.colour = *colour;
                                    } else {
                                      auto point = read_point_property(cursor, key);
                                      if (point && !again) light.coords = *point;
                                    }
                                  });
  blocks.require(block, "ID", "this LIGHT has no ID: add 'ID = light1;'");
  blocks.require(block, "COLOR",
                 "this LIGHT has no COLOR: add 'COLOR = red;' (or orange, green, inactive)");
  blocks.require(block, "COORD", "this LIGHT has no COORD: add 'COORD = (x, y);' in metres");
  light.location = block.location;
  file.lights.push_back(light);
}

void PartReader::read_marker(const Token& keyword, Context context) {
  Point coords;
  const Block block =
      blocks.read(keyword, context, [&](const Token& key, const std::string&, bool again) {
        auto point = read_point_property(cursor, key);
        if (point && !again) coords = *point;
      });
  const std::string name = upper(keyword.text);
  blocks.require(block, "COORD", "this " + name + " has no COORD: add 'COORD = (x, y);' in metres");
  if (context == Context::crossing)
    file.crossings.push_back({coords, block.location});
  else
    file.stop_signs.push_back({coords, block.location});
}

}  // namespace scenfuzz::accident
