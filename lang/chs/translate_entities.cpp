// CH-Scenario entities to actors and obstacles (translation.hpp; docs/ch-scenario.md, "Entities"):
// which dynamic entity is the ego, where each entity starts when its `position:` is not written,
// and what its words make of it (vocabulary.hpp).
#include <cmath>
#include <numbers>

#include "lang/chs/lane_places.hpp"
#include "lang/chs/overtaking.hpp"
#include "lang/chs/translation.hpp"
#include "lang/chs/vocabulary.hpp"
#include "lang/number_format.hpp"

namespace scenfuzz::chs {

namespace {

constexpr double kKilometresPerHour = 1 / 3.6;
// Where entities start when the file does not say (metres; docs/ch-scenario.md lists them).
constexpr double kEgoStart = 50;   // along its road, at most a quarter of the road
constexpr double kAheadGap = 40;   // between the ego and each vehicle ahead, and between them
constexpr double kBehindGap = 25;  // likewise behind the ego
constexpr double kOncomingDistance = 150;  // from the ego to the first oncoming vehicle
constexpr double kStaticAhead = 60;        // from the ego to the first static entity or walker
constexpr double kStaticGap = 20;          // between those
constexpr double kPavement = 2.5;          // from the kerb lane's centre: on the pavement beside it
constexpr double kMinimumHalfWidth = 1.0;  // outline_map.hpp: a narrower half has no lanes
// A static obstacle the words do not size: about a fallen rock or a pile of debris.
constexpr double kObstacleSize[3] = {2, 2, 1};

// How many entities have been placed by default on each side of the ego: the next one's gap.
struct Placed {
  int ahead = 0, behind = 0, oncoming = 0, roadside = 0;
};

// A vehicle whose track overtakes: its index among the scenario's vehicles, and its track.
struct Overtaker {
  std::size_t vehicle = 0;
  SourceLocation location;
};

bool names_the_ego(const std::string& name) {
  std::string joined;
  for (const std::string& word : words_of(name)) joined += word;
  return joined == "ego" || joined == "currentvehicle" || joined == "hostvehicle" ||
         joined == "subjectvehicle" || joined == "egovehicle";
}

// The dynamic entity the driver under test drives: one named as the ego, else the first vehicle.
const DynamicEntity* choose_ego(const File& file) {
  for (const DynamicEntity& entity : file.dynamic_entities)
    if (names_the_ego(entity.name.text)) return &entity;
  for (const DynamicEntity& entity : file.dynamic_entities) {
    const EntityClass kind = classify_entity(entity.name.text, "").kind;
    if (kind == EntityClass::vehicle || kind == EntityClass::unknown) return &entity;
  }
  return nullptr;
}

// Whether a half of the road carries lanes, judged at its start, middle and end as the map layer
// judges the whole half (outline_map.hpp): its mean width is at least a metre.
bool has_lanes(const Road& road, bool forward) {
  const std::vector<Point>& boundary = forward ? road.right_boundary : road.left_boundary;
  const double length = polyline_length(road.centre_lines);
  double total = 0;
  for (double share : {0.0, 0.5, 1.0}) {
    const Station station = station_at(road.centre_lines, share * length);
    total += distance_to(boundary, station.x, station.y);
  }
  return total / 3 >= kMinimumHalfWidth;
}

// The heading a half's traffic starts with.
double start_heading(const Road& road, bool forward) {
  const double length = polyline_length(road.centre_lines);
  if (forward) return station_at(road.centre_lines, 0).heading;
  return station_at(road.centre_lines, length).heading + std::numbers::pi;
}

// The road and direction the ego drives: the half whose heading is nearest the track's compass
// word, else the first road's right half (or its left one, on a one-way road drawn backwards).
std::optional<EgoPlace> choose_ego_place(const File& file, const TrackReading& track) {
  std::optional<EgoPlace> best;
  double best_off = 10;
  for (const Road& road : file.roads)
    for (bool forward : {true, false}) {
      if (!has_lanes(road, forward)) continue;
      double off = 0;
      if (track.heading)
        off = std::abs(
            std::remainder(start_heading(road, forward) - *track.heading, 2 * std::numbers::pi));
      if (!best || off < best_off - 1e-9) {
        best =
            EgoPlace{&road, forward, std::min(kEgoStart, polyline_length(road.centre_lines) / 4)};
        best_off = off;
      }
    }
  return best;
}

// The manoeuvre of a track's lane change (`change lane left`), else null.
const char* lane_change_of(const TrackReading& track) {
  if (track.manoeuvre == TrackManoeuvre::change_left) return "LaneChangeLeft";
  if (track.manoeuvre == TrackManoeuvre::change_right) return "LaneChangeRight";
  return nullptr;
}

// The manoeuvre of a track's turn (`turn left`), else null.
const char* turn_of(const TrackReading& track) {
  if (track.manoeuvre == TrackManoeuvre::turn_left) return "TurnLeft";
  if (track.manoeuvre == TrackManoeuvre::turn_right) return "TurnRight";
  return nullptr;
}

Position coordinate_position(const Point& point) {
  Position position;
  position.kind = PositionKind::coordinate;
  position.x = constant_value(point.x, point.x_at);
  position.y = constant_value(point.y, point.y_at);
  position.location = point.location;
  return position;
}

// A written point in a lane (lane_places.hpp) as that lane, its arc length standing at the x's
// text and its lateral offset at the y's, which chs::print_concrete writes back as a point.
Position written_lane_position(const Point& point, const LanePlace& place) {
  Position position;
  position.kind = PositionKind::lane;
  position.lane = lane_id(*place.road, place.forward, place.lane);
  position.s = constant_value(place.s, point.x_at);
  position.lateral = constant_value(place.lateral, point.y_at);
  position.location = point.location;
  return position;
}

Position lane_position(const std::string& lane, double s, SourceLocation at) {
  Position position;
  position.kind = PositionKind::lane;
  position.lane = lane;
  position.s = constant_value(s);
  position.location = at;
  return position;
}

Position relative_position(const std::string& ego, double s, const char* sector,
                           std::optional<double> lateral, SourceLocation at) {
  Position position;
  position.kind = PositionKind::relative;
  position.reference = ego;
  position.s = constant_value(s);
  position.relative_location = sector;
  if (lateral) position.lateral = constant_value(*lateral);
  position.location = at;
  return position;
}

class EntityTranslator {
 public:
  explicit EntityTranslator(Translation& translation)
      : t_(translation), file_(translation.file), diagnostics_(translation.diagnostics) {}

  void run() {
    const DynamicEntity* ego = choose_ego(file_);
    if (!ego) {
      diagnostics_.error({1, 1, 0, 0},
                         "the file has no dynamic entity that is a vehicle, so none can be "
                         "driven by the system under test (docs/ch-scenario.md, \"The ego\")");
      return;
    }
    if (!translate_ego(*ego)) return;
    for (const DynamicEntity& entity : file_.dynamic_entities)
      if (&entity != ego) dynamic_entity(entity);
    for (const StaticEntity& entity : file_.static_entities) static_entity(entity);
    // Once every road user is known: whom an overtake may pass, meet or have beside it.
    for (const Overtaker& overtaker : overtakers_) overtake(overtaker);
  }

 private:
  bool translate_ego(const DynamicEntity& entity) {
    Actor& ego = t_.scenario.ego;
    ego.kind = ActorKind::ego;
    ego.name = entity.name.text;
    ego.location = entity.location;
    ego.type = actor_type(entity.name, "");
    const TrackReading track = read_track(entity.track.text);
    warn_of_track(entity, track, true);
    if (entity.position) {
      ego.initial.position = vehicle_position(*entity.position, &ego_forward_);
      ego_point_ = {entity.position->x, entity.position->y};
      const std::optional<LanePlace> place =
          lane_place_at(file_.roads, entity.position->x, entity.position->y);
      if (place) ego_road_ = place->road->name.text;
    } else if (file_.map.kind == MapSource::Kind::named) {
      diagnostics_.error(entity.location, "on the named map '" + file_.map.name.text + "', " +
                                              entity.name.text +
                                              " (the ego) needs a 'position: (x, y)'");
      return false;
    } else {
      t_.ego_place = choose_ego_place(file_, track);
      if (!t_.ego_place) return false;  // the map layer reports a network without lanes
      ego.initial.position = lane_position(lane_id(*t_.ego_place->road, t_.ego_place->forward, 0),
                                           t_.ego_place->s, entity.location);
      ego_forward_ = t_.ego_place->forward;
      ego_point_ = point_of({t_.ego_place->road, t_.ego_place->forward, 0, t_.ego_place->s, 0});
      ego_road_ = t_.ego_place->road->name.text;
    }
    ego.initial.speed = located(entity.speed, kKilometresPerHour);
    ego.initial.location = entity.location;
    aim(entity, ego);
    return true;
  }

  // An aim that names a road of the network is where the ego drives to (the end of that road's
  // lane in its direction); any other aim is a place scenfuzz cannot find.
  void aim(const DynamicEntity& entity, Actor& actor) {
    if (entity.aim.text.empty()) return;
    for (const Road& road : file_.roads)
      if (road.name.text == entity.aim.text) {
        State target;
        target.position = lane_position(lane_id(road, ego_forward_, 0),
                                        polyline_length(road.centre_lines), entity.aim.location);
        target.location = entity.aim.location;
        actor.target = target;
        return;
      }
    diagnostics_.warning(entity.aim.location, "the aim '" + entity.aim.text +
                                                  "' is no road of the network: " +
                                                  entity.name.text + " drives on along its lanes");
  }

  void warn_of_track(const DynamicEntity& entity, const TrackReading& track, bool ego,
                     bool pedestrian = false) {
    if (!track.unread.empty()) {
      std::string words;
      for (const std::string& word : track.unread)
        words += (words.empty() ? "'" : ", '") + word + "'";
      diagnostics_.warning(entity.track.location, "scenfuzz does not read " + words +
                                                      " in a track (docs/ch-scenario.md "
                                                      "lists the words it reads): " +
                                                      entity.name.text + " follows its lane");
    }
    const bool manoeuvre =
        track.manoeuvre != TrackManoeuvre::follow && track.manoeuvre != TrackManoeuvre::stop;
    if (ego && manoeuvre)
      diagnostics_.warning(entity.track.location,
                           "the ego is driven by the system under test, which decides itself when "
                           "to change lanes, overtake or turn");
    else if (pedestrian && manoeuvre)
      diagnostics_.warning(entity.track.location,
                           "changing lanes, overtaking and turning are a vehicle's manoeuvres: " +
                               entity.name.text + ", a pedestrian, crosses the road");
    if (ego && track.manoeuvre == TrackManoeuvre::stop)
      diagnostics_.warning(entity.track.location,
                           "the ego is driven by the system under test, which decides itself "
                           "when to stop");
  }

  // A vehicle's written point: its place in the lane it lies in, else the point itself.
  Position vehicle_position(const Point& point, bool* forward = nullptr) {
    const std::optional<LanePlace> place = lane_place_at(file_.roads, point.x, point.y);
    if (!place) return coordinate_position(point);
    if (forward) *forward = place->forward;
    return written_lane_position(point, *place);
  }

  std::optional<ActorType> actor_type(const Text& name, const std::string& overview) {
    const EntityWords words = classify_entity(name.text, overview);
    if (words.model.empty()) return std::nullopt;
    return ActorType{words.model, true, std::nullopt, std::nullopt, name.location};
  }

  void dynamic_entity(const DynamicEntity& entity) {
    const EntityWords words = classify_entity(entity.name.text, "");
    const TrackReading track = read_track(entity.track.text);
    warn_of_track(entity, track, false, words.kind == EntityClass::pedestrian);
    Actor actor;
    actor.name = entity.name.text;
    actor.location = entity.location;
    actor.type = actor_type(entity.name, "");
    actor.initial.location = entity.location;
    actor.initial.speed = located(entity.speed, kKilometresPerHour);
    if (track.manoeuvre == TrackManoeuvre::stop && entity.speed.value > 0) {
      diagnostics_.warning(
          entity.speed.location,
          entity.name.text +
              " stands, as its track says: its speed is used only when an event drives it off");
      actor.initial.speed = constant_value(0);
    }
    if (words.kind == EntityClass::pedestrian) return walker(entity, track, std::move(actor));
    actor.kind = words.kind == EntityClass::cyclist ? ActorKind::cyclist : ActorKind::vehicle;
    if (entity.position) {
      actor.initial.position = vehicle_position(*entity.position);
    } else {
      auto position = default_vehicle_position(entity, track);
      if (!position) return;
      actor.initial.position = std::move(*position);
    }
    // A lane change is what the vehicle does first, from the start; so is a turn, at the next
    // junction on its way (a map without one is warned of when the scenario is run).
    const char* manoeuvre = lane_change_of(track);
    if (!manoeuvre) manoeuvre = turn_of(track);
    if (manoeuvre) {
      ManoeuvrePhase phase;
      phase.manoeuvre = manoeuvre;
      phase.location = entity.track.location;
      actor.motion.kind = MotionKind::manoeuvres;
      actor.motion.phases.push_back(std::move(phase));
    }
    if (track.manoeuvre == TrackManoeuvre::overtake)
      overtakers_.push_back({t_.scenario.vehicles.size(), entity.track.location});
    t_.scenario.vehicles.push_back(std::move(actor));
  }

  // An overtake's phases come first (events' follow), started by what is around the vehicle.
  void overtake(const Overtaker& overtaker) {
    Actor& actor = t_.scenario.vehicles[overtaker.vehicle];
    std::vector<std::string> others{t_.scenario.ego.name};
    for (const Actor& other : t_.scenario.vehicles)
      if (&other != &actor) others.push_back(other.name);
    actor.motion.kind = MotionKind::manoeuvres;
    actor.motion.phases =
        overtake_phases(actor.name, *actor.initial.speed, others, overtaker.location);
  }

  std::optional<Position> default_vehicle_position(const DynamicEntity& entity,
                                                   const TrackReading& track) {
    const std::string& ego = t_.scenario.ego.name;
    if (track.place == TrackPlace::behind)
      return relative_position(ego, -kBehindGap * ++placed_.behind, "R", std::nullopt,
                               entity.location);
    if (track.place != TrackPlace::oncoming)
      return relative_position(ego, kAheadGap * ++placed_.ahead, "F", std::nullopt,
                               entity.location);
    if (!t_.ego_place) {
      diagnostics_.error(entity.location, "an oncoming " + entity.name.text +
                                              " needs a 'position: (x, y)' when the ego's is "
                                              "written or the map is named");
      return std::nullopt;
    }
    const EgoPlace& place = *t_.ego_place;
    const double length = polyline_length(place.road->centre_lines);
    const double ahead = place.s + kOncomingDistance + kAheadGap * placed_.oncoming++;
    return lane_position(lane_id(*place.road, !place.forward, 0), std::max(0.0, length - ahead),
                         entity.location);
  }

  // A walker starts on the pavement on the ego's right, ahead of it, and crosses the road unless
  // its track says it stands.
  void walker(const DynamicEntity& entity, const TrackReading& track, Actor actor) {
    actor.kind = ActorKind::pedestrian;
    actor.initial.position = entity.position ? coordinate_position(*entity.position)
                                             : roadside_position(entity.location);
    if (track.manoeuvre != TrackManoeuvre::stop) {
      ManoeuvrePhase cross;
      cross.manoeuvre = "Walk_Cross";
      cross.parameters.push_back({"speed", *actor.initial.speed, entity.speed.location});
      cross.location = entity.track.location.known() ? entity.track.location : entity.location;
      actor.motion.kind = MotionKind::manoeuvres;
      actor.motion.phases.push_back(std::move(cross));
    }
    t_.scenario.pedestrians.push_back(std::move(actor));
  }

  Position roadside_position(SourceLocation at) {
    return relative_position(t_.scenario.ego.name, kStaticAhead + kStaticGap * placed_.roadside++,
                             "FSR", kPavement, at);
  }

  void static_entity(const StaticEntity& entity) {
    const EntityWords words = classify_entity(entity.name.text, entity.overview.text);
    switch (words.kind) {
      case EntityClass::pedestrian:
      case EntityClass::cyclist: return standing_walker(entity);
      case EntityClass::vehicle: return parked_vehicle(entity, words);
      case EntityClass::obstacle: return obstacle(entity);
      case EntityClass::traffic_light: return traffic_light(entity, words);
      case EntityClass::unknown:
        diagnostics_.warning(entity.location,
                             "scenfuzz cannot tell what '" + entity.name.text +
                                 "' is from its name and overview (docs/ch-scenario.md lists the "
                                 "words it reads): it is left out");
        return;
    }
  }

  // On a road network, fixed-time lights at the junction nearest the light's point (else the
  // ego's), its colour what the ego's road shows at the start (physics/map/outline_map.hpp,
  // rule 10). A named map's lights are its own.
  void traffic_light(const StaticEntity& entity, const EntityWords& words) {
    if (file_.map.kind == MapSource::Kind::named) {
      diagnostics_.warning(entity.location, "the named map '" + file_.map.name.text +
                                                "' has its own traffic lights: '" +
                                                entity.name.text + "' is left out");
      return;
    }
    if (file_.roads.size() < 2) {
      diagnostics_.warning(entity.location,
                           "a road network of one road has no junction for a "
                           "traffic light to control: '" +
                               entity.name.text + "' is left out");
      return;
    }
    const PlanePoint at =
        entity.position ? PlanePoint{entity.position->x, entity.position->y} : ego_point_;
    t_.scenario.map.signals.push_back(
        {entity.name.text, at.x, at.y, ego_road_, words.colour, entity.location});
  }

  Position static_position(const StaticEntity& entity, bool roadside) {
    if (entity.position) return coordinate_position(*entity.position);
    if (roadside) return roadside_position(entity.location);
    return relative_position(t_.scenario.ego.name, kStaticAhead + kStaticGap * placed_.roadside++,
                             "F", std::nullopt, entity.location);
  }

  void standing_walker(const StaticEntity& entity) {
    Actor actor;
    actor.kind = ActorKind::pedestrian;
    actor.name = entity.name.text;
    actor.location = entity.location;
    actor.initial.position = static_position(entity, true);
    actor.initial.speed = constant_value(0);
    actor.initial.location = entity.location;
    t_.scenario.pedestrians.push_back(std::move(actor));
  }

  void parked_vehicle(const StaticEntity& entity, const EntityWords& words) {
    Actor actor;
    actor.kind = ActorKind::vehicle;
    actor.name = entity.name.text;
    actor.location = entity.location;
    actor.type = ActorType{words.model, true, std::nullopt, std::nullopt, entity.name.location};
    actor.initial.position =
        entity.position ? vehicle_position(*entity.position) : static_position(entity, false);
    actor.initial.speed = constant_value(0);
    actor.initial.location = entity.location;
    actor.motion.kind = MotionKind::uniform;
    t_.scenario.vehicles.push_back(std::move(actor));
  }

  void obstacle(const StaticEntity& entity) {
    Obstacle obstacle;
    obstacle.name = entity.name.text;
    obstacle.position = static_position(entity, false);
    obstacle.shape = Shape{ShapeKind::box,
                           {constant_value(kObstacleSize[0]), constant_value(kObstacleSize[1]),
                            constant_value(kObstacleSize[2])},
                           entity.location};
    obstacle.location = entity.location;
    t_.scenario.obstacles.push_back(std::move(obstacle));
  }

  Translation& t_;
  const File& file_;
  Diagnostics& diagnostics_;
  Placed placed_;
  std::vector<Overtaker> overtakers_;
  bool ego_forward_ = true;  // the direction of the ego's lane, where its aim is
  // Where the ego starts and on which road (empty off the roads): a light without a position
  // controls the junction nearest the ego, and shows its colour to the ego's road.
  PlanePoint ego_point_;
  std::string ego_road_;
};

}  // namespace

void translate_entities(Translation& translation) { EntityTranslator(translation).run(); }

}  // namespace scenfuzz::chs
