// The checks a level-1 file needs beyond its sentences' form: every actor, road and junction a
// sentence refers to is declared (roads by a road sentence, junctions by a junction sentence,
// actors by an actor sentence), declared once, and located; actor counts match their names.
// A file that passes can always be converted to level 2.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "lang/wmg/level1_parse_parts.hpp"

namespace scenfuzz::wmg::detail {

namespace {

class ReferenceChecker {
 public:
  ReferenceChecker(const Level1File& file, Diagnostics& diagnostics)
      : file_(file), diagnostics_(diagnostics) {}

  void run() {
    declare_roads();
    declare_junctions();
    declare_actors();
    check_scenery_references();
    check_locations();
    for (const Level1Ssms& ssms : file_.sequences) check_ssms(ssms);
  }

 private:
  void report(SourceLocation where, const std::string& message) {
    diagnostics_.error(where, message);
  }

  std::string suggestion(const std::set<std::string>& names, const std::string& written) const {
    if (diagnostics_.too_many_errors()) return "";
    std::vector<std::string> candidates(names.begin(), names.end());
    std::optional<std::string> closest = closest_spelling(candidates, written);
    return closest ? "; did you mean '" + *closest + "'?" : "";
  }

  void declare_roads() {
    for (const RoadSentence& sentence : file_.roads)
      for (const Identifier& road : sentence.roads)
        if (!roads_.insert(road.name).second)
          report(road.location, "road " + road.name + " is described twice");
  }

  void declare_junctions() {
    for (const JunctionSentence& junction : file_.junctions) {
      // Level 2 writes a junction's name unbracketed where these words are keywords.
      if (junction.id.name == "None" || junction.id.name == "Roads")
        report(junction.id.location,
               "'" + junction.id.name + "' cannot name a junction: it is a level-2 keyword");
      if (!junctions_.insert(junction.id.name).second)
        report(junction.id.location, "junction " + junction.id.name + " is described twice");
    }
  }

  void declare_actors() {
    for (const ActorSentence& sentence : file_.actors) {
      if (sentence.count.value != static_cast<std::int64_t>(sentence.names.size()))
        report(sentence.count.location, "the sentence counts " +
                                            std::to_string(sentence.count.value) + " but names " +
                                            std::to_string(sentence.names.size()));
      for (const Identifier& name : sentence.names) {
        if (junctions_.count(name.name) > 0)
          report(name.location, "'" + name.name + "' names both a junction and an actor");
        else if (!actors_.insert(name.name).second)
          report(name.location, "actor " + name.name + " is declared twice");
      }
    }
  }

  // A road a junction lists may be new, so only a feature sentence suggests a known one.
  void expect_road(const Identifier& road, const std::string& context, bool suggest) {
    if (roads_.count(road.name) == 0)
      report(road.location, "road " + road.name + " " + context +
                                " but no road sentence describes it (add '" + road.name +
                                " is a straight, minor road.')" +
                                (suggest ? suggestion(roads_, road.name) : ""));
  }

  void check_scenery_references() {
    for (const JunctionSentence& junction : file_.junctions) {
      std::set<std::string> connected;
      for (const Identifier& road : junction.roads) {
        expect_road(road, "connects to " + junction.id.name, false);
        // A road written twice would be a junction with no way through it at level 2.
        if (!connected.insert(road.name).second)
          report(road.location,
                 "road " + road.name + " is named twice among the roads of " + junction.id.name);
      }
      for (const ConnectionSentence& connection : junction.connections)
        for (const Identifier* road : {&connection.from, &connection.to})
          if (connected.count(road->name) == 0)
            report(road->location, "road " + road->name + " is not one of the roads of " +
                                       junction.id.name + suggestion(connected, road->name));
    }
    for (const RoadFeatureSentence& sentence : file_.road_features)
      for (const Identifier& road : sentence.roads) expect_road(road, "has features", true);
  }

  void check_locations() {
    std::set<std::string> located;
    for (const ActorLocation& location : file_.locations) {
      expect_actor(location.actor);
      if (!located.insert(location.actor.name).second)
        report(location.actor.location, "actor " + location.actor.name + " is located twice");
      if (roads_.count(location.place.name) == 0 && junctions_.count(location.place.name) == 0) {
        std::set<std::string> places = roads_;
        places.insert(junctions_.begin(), junctions_.end());
        report(location.place.location, "'" + location.place.name +
                                            "' is neither a road nor a junction of the scenery" +
                                            suggestion(places, location.place.name));
      }
    }
    for (const ActorSentence& sentence : file_.actors)
      for (const Identifier& name : sentence.names)
        if (located.count(name.name) == 0)
          report(name.location, "actor " + name.name + " has no location: add '" + name.name +
                                    " is in R1' (its road or junction)");
  }

  void expect_actor(const Identifier& actor) {
    if (actors_.count(actor.name) == 0)
      report(actor.location, "unknown actor '" + actor.name +
                                 "': no 'There is ...' sentence declares it" +
                                 suggestion(actors_, actor.name));
  }

  void expect_anything(const Identifier& name) {
    if (actors_.count(name.name) || roads_.count(name.name) || junctions_.count(name.name)) return;
    std::set<std::string> all = actors_;
    all.insert(roads_.begin(), roads_.end());
    all.insert(junctions_.begin(), junctions_.end());
    report(name.location, "'" + name.name + "' is not an actor, road or junction of the scenario" +
                              suggestion(all, name.name));
  }

  void check_manoeuvre(const Level1Manoeuvre& manoeuvre) {
    for (const ManoeuvrePlace& place : manoeuvre.places)
      if (place.target) expect_anything(*place.target);
  }

  void check_ssms(const Level1Ssms& ssms) {
    for (const PhaseGroup& group : ssms.groups) {
      for (const Level1Condition& condition : group.conditions) {
        if (const auto* actor = std::get_if<ActorClause>(&condition)) {
          expect_actor(actor->actor);
          check_manoeuvre(actor->manoeuvre);
        } else {
          expect_anything(std::get<TrafficLightClause>(condition).reference);
        }
      }
      for (const PhaseClause& phase : group.phases) {
        if (phase.actor_written) expect_actor(phase.actor);
        check_manoeuvre(phase.manoeuvre);
      }
    }
    expect_actor(ssms.autonomous_actor);
  }

  const Level1File& file_;
  Diagnostics& diagnostics_;
  std::set<std::string> roads_;
  std::set<std::string> junctions_;
  std::set<std::string> actors_;
};

}  // namespace

void check_references(const Level1File& file, Diagnostics& diagnostics) {
  ReferenceChecker(file, diagnostics).run();
}

}  // namespace scenfuzz::wmg::detail
