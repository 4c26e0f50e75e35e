// The AVUnit elaborator's Scenario(...) call: its parts, the names of its actors and flows
// (elaborator_class.hpp).
#include "lang/avunit/elaborator_class.hpp"

namespace scenfuzz::avunit {

Item Elaborator::scenario(const Syntax& syntax) {
  std::size_t slots = syntax.children.size();
  if (slots < 5 || slots > 7)
    return fail(syntax.location,
                "CreateScenario{...} has " + std::to_string(slots) +
                    " slots; expected 'load(map); ego; vehicles; pedestrians; obstacles;' "
                    "and optionally 'environment;' and 'traffic;'");
  std::vector<Item> items;
  for (const Syntax& child : syntax.children) items.push_back(evaluate(child));
  for (const Item& item : items)
    if (item.kind == ItemKind::error) return make_item(ItemKind::error, syntax.location);
  auto parts = std::make_shared<ScenarioParts>();
  parts->location = syntax.location;
  if (items[0].kind != ItemKind::map) {
    mismatch(items[0], "the map 'load(\"name\")' in the first slot of CreateScenario");
    return make_item(ItemKind::error, syntax.location);
  }
  parts->map = payload_of<MapReference>(items[0]);
  if (items[1].kind != ItemKind::actor || payload_of<Actor>(items[1]).kind != ActorKind::ego) {
    mismatch(items[1], "the ego vehicle AV(...) in the second slot of CreateScenario");
    return make_item(ItemKind::error, syntax.location);
  }
  parts->ego = payload_of<Actor>(items[1]);
  if (parts->ego.name.empty()) parts->ego.name = "ego";
  std::set<std::string> names = {parts->ego.name};
  bool ok =
      collect_actors(items[2], ActorKind::vehicle, "vehicle", parts->vehicles, names) &&
      collect_actors(items[3], ActorKind::pedestrian, "pedestrian", parts->pedestrians, names) &&
      collect_obstacles(items[4], parts->obstacles, names);
  if (!ok) return make_item(ItemKind::error, syntax.location);
  if (slots >= 6 && !(items[5].kind == ItemKind::set && items[5].elements.empty())) {
    if (items[5].kind != ItemKind::environment) {
      mismatch(items[5], "an Environment(...) or {} in the sixth slot of CreateScenario");
      return make_item(ItemKind::error, syntax.location);
    }
    parts->environment = payload_of<Environment>(items[5]);
  }
  if (slots == 7 && !traffic(items[6], *parts, names))
    return make_item(ItemKind::error, syntax.location);
  Item item =
      make_item(ItemKind::scenario, syntax.location, std::shared_ptr<const ScenarioParts>(parts));
  scenarios_.push_back(payload_of<std::shared_ptr<const ScenarioParts>>(item));
  return item;
}

void Elaborator::flatten(const Item& item, std::vector<const Item*>& out) {
  if (item.kind == ItemKind::set || item.kind == ItemKind::tuple) {
    for (const Item& element : item.elements) flatten(element, out);
  } else if (item.kind != ItemKind::empty) {
    out.push_back(&item);
  }
}

std::string Elaborator::fresh_name(const std::string& stem, std::set<std::string>& names) {
  for (int i = 1;; ++i) {
    std::string name = stem + std::to_string(i);
    if (names.insert(name).second) return name;
  }
}

bool Elaborator::claim_name(const std::string& name, SourceLocation where,
                            std::set<std::string>& names) {
  if (names.insert(name).second) return true;
  diagnostics_.error(where, "'" + name + "' appears twice in the scenario");
  return false;
}

bool Elaborator::collect_actors(const Item& slot, ActorKind kind, const std::string& stem,
                                std::vector<Actor>& actors, std::set<std::string>& names) {
  std::vector<const Item*> elements;
  flatten(slot, elements);
  for (const Item* element : elements) {
    if (element->kind != ItemKind::actor || payload_of<Actor>(*element).kind != kind) {
      mismatch(*element,
               std::string(kind == ActorKind::vehicle ? "a Vehicle(...)" : "a Pedestrian(...)") +
                   " in the " + stem + " slot of CreateScenario");
      return false;
    }
    Actor actor = payload_of<Actor>(*element);
    if (actor.name.empty())
      actor.name = fresh_name(stem, names);
    else if (!claim_name(actor.name, element->location, names))
      return false;
    actors.push_back(std::move(actor));
  }
  return true;
}

bool Elaborator::collect_obstacles(const Item& slot, std::vector<Obstacle>& obstacles,
                                   std::set<std::string>& names) {
  std::vector<const Item*> elements;
  flatten(slot, elements);
  for (const Item* element : elements) {
    if (element->kind != ItemKind::obstacle) {
      mismatch(*element, "an Obstacle(...) in the obstacle slot of CreateScenario");
      return false;
    }
    Obstacle obstacle = payload_of<Obstacle>(*element);
    if (obstacle.name.empty())
      obstacle.name = fresh_name("obstacle", names);
    else if (!claim_name(obstacle.name, element->location, names))
      return false;
    obstacles.push_back(std::move(obstacle));
  }
  return true;
}

bool Elaborator::traffic(const Item& slot, ScenarioParts& parts, std::set<std::string>& names) {
  std::vector<const Item*> elements;
  flatten(slot, elements);
  for (const Item* element : elements) {
    if (element->kind == ItemKind::intersection) {
      parts.traffic.intersections.push_back(payload_of<IntersectionControl>(*element));
    } else if (element->kind == ItemKind::speed_limit) {
      parts.traffic.speed_limits.push_back(payload_of<SpeedLimit>(*element));
    } else if (element->kind == ItemKind::flow) {
      TrafficFlow flow = payload_of<TrafficFlow>(*element);
      if (flow.name.empty())
        flow.name = fresh_name("flow", names);
      else if (!claim_name(flow.name, element->location, names))
        return false;
      parts.traffic.flows.push_back(std::move(flow));
    } else if (element->kind == ItemKind::traffic_light) {
      const TrafficLightSetting& light = payload_of<TrafficLightSetting>(*element);
      for (const TrafficLightSetting& earlier : parts.traffic.lights)
        if (earlier.id == light.id) {
          diagnostics_.error(
              element->location,
              "traffic light '" + light.id + "' is given twice in the traffic slot; keep one");
          return false;
        }
      parts.traffic.lights.push_back(light);
    } else if (element->kind == ItemKind::npc_behaviour) {
      if (parts.npc_behaviour) {
        diagnostics_.error(element->location,
                           "NPCBehaviour(...) is given twice in the traffic slot; keep one");
        return false;
      }
      parts.npc_behaviour =
          element->word == "scripted" ? NpcBehaviour::scripted : NpcBehaviour::reactive;
    } else {
      mismatch(*element,
               "an Intersection(...), SpeedLimit(...), Flow(...), NPCBehaviour(...) or "
               "TrafficLight(...) in the traffic slot");
      return false;
    }
  }
  return true;
}

}  // namespace scenfuzz::avunit
