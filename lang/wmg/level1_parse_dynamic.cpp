// Level-1 sentences about the actors: who they are ("There are 2 vehicles, Car1 and Car2."),
// where they start ("Ego is in R1") and what they do (the SSMS: "When ..., Car1 cuts in. Ego
// operates autonomously."). English needs a look ahead in two places: a comma after a WHEN
// condition may start another condition or the first phase, and a full stop may end the phases
// or continue them (". Car1 then stops").
#include <functional>

#include "lang/wmg/level1_parse_parts.hpp"
#include "lang/wmg/level1_phrases.hpp"
#include "lang/wmg/parser_cursor.hpp"

namespace scenfuzz::wmg::detail {

namespace {

namespace phrases = level1_phrases;

std::string quoted(const std::string& text) { return "'" + text + "'"; }
std::string after_previous(const SentenceCursor& cursor) { return quoted(cursor.previous().text); }

// Words that join or end clauses, never names.
bool is_joining_word(const SentenceCursor& cursor, std::size_t ahead) {
  return cursor.at_word("and", ahead) || cursor.at_word("then", ahead) ||
         cursor.at_word("And", ahead) || cursor.at_phrase("at its", ahead);
}

bool at_action(const SentenceCursor& cursor, std::size_t ahead) {
  return cursor.match(phrases::action(), ahead) > 0;
}

// `ID [then] MANOEUVRE` starts `ahead` tokens from here. A word that starts a manoeuvre is not
// a name: in ", then is cutting out" the phase has no actor of its own.
bool at_actor_clause(const SentenceCursor& cursor, std::size_t ahead) {
  if (!cursor.at(TokenKind::word, ahead) || is_joining_word(cursor, ahead) ||
      at_action(cursor, ahead))
    return false;
  if (at_action(cursor, ahead + 1)) return true;
  return cursor.at_word("then", ahead + 1) && at_action(cursor, ahead + 2);
}

bool at_condition(const SentenceCursor& cursor, std::size_t ahead) {
  return cursor.at_phrase("the traffic light", ahead) || at_actor_clause(cursor, ahead);
}

bool at_place(const SentenceCursor& cursor, std::size_t ahead) {
  return cursor.match(phrases::relation(), ahead) > 0 ||
         cursor.match(phrases::preposition(), ahead) > 0;
}

// The name after a place word, when one is written: not a word that joins clauses, and not the
// actor of the next clause.
bool at_place_target(const SentenceCursor& cursor) {
  return cursor.at(TokenKind::word) && !is_joining_word(cursor, 0) && !at_place(cursor, 0) &&
         !at_actor_clause(cursor, 0);
}

ManoeuvrePlace parse_place(SentenceCursor& cursor) {
  ManoeuvrePlace place;
  SourceLocation first = cursor.peek().location;
  if (cursor.match(phrases::relation()) > 0) place.relation = cursor.label(phrases::relation(), "");
  if (cursor.match(phrases::preposition()) > 0) {
    place.preposition = cursor.label(phrases::preposition(), "");
    place.target = cursor.name("a road, junction or actor", quoted(place.preposition->text));
  } else if (at_place_target(cursor)) {
    place.target = cursor.name("a road, junction or actor", "");
  }
  place.location = cursor.span_from(first);
  return place;
}

// DOES_SOMETHING [[,] SPEED_CHANGE [,]] PLACE* [at its REL_POSITION]
Level1Manoeuvre parse_manoeuvre(SentenceCursor& cursor, const std::string& after) {
  Level1Manoeuvre manoeuvre;
  SourceLocation first = cursor.peek().location;
  manoeuvre.action = cursor.label(phrases::action(), after);
  bool comma_before_speed =
      cursor.at(TokenKind::comma) && cursor.match(phrases::speed_change(), 1) > 0;
  if (comma_before_speed) cursor.take();
  if (cursor.match(phrases::speed_change()) > 0) {
    manoeuvre.speed_change = cursor.label(phrases::speed_change(), "");
    bool comma_after_speed =
        cursor.at(TokenKind::comma) && (at_place(cursor, 1) || cursor.at_phrase("at its", 1));
    if (comma_after_speed) cursor.take();
  }
  while (at_place(cursor, 0)) {
    manoeuvre.places.push_back(parse_place(cursor));
    bool joined = (cursor.at(TokenKind::comma) || cursor.at_word("and")) && at_place(cursor, 1);
    if (joined) cursor.take();
  }
  if (cursor.at_phrase("at its")) {
    cursor.take(2);
    // "front rigth" would read as "front" and leave "rigth" behind: suggest the two-word one.
    bool second_word_misspelt =
        cursor.match(phrases::relative_position()) == 1 && cursor.at(TokenKind::word, 1) &&
        cursor.match(phrases::relative_position(), 1) == 0 && !is_joining_word(cursor, 1) &&
        closest_spelling({"left", "right"}, cursor.peek(1).text);
    if (second_word_misspelt)
      cursor.fail_expected("the relative position (" +
                               quoted_alternatives(phrases::relative_position().phrases) + ")",
                           "'at its'",
                           {cursor.peek().text + " left", cursor.peek().text + " right"});
    manoeuvre.position = cursor.label(phrases::relative_position(), "'at its'");
  }
  manoeuvre.location = cursor.span_from(first);
  return manoeuvre;
}

ActorClause parse_actor_clause(SentenceCursor& cursor, const std::string& after) {
  ActorClause clause;
  clause.actor = cursor.id("an actor", after);
  clause.manoeuvre = parse_manoeuvre(cursor, quoted(clause.actor.name));
  clause.location = cursor.span_from(clause.actor.location);
  return clause;
}

// the traffic light REL_ACTION_LOCATION ID is TRAFFIC_LIGHT_COLOUR
TrafficLightClause parse_traffic_light_clause(SentenceCursor& cursor) {
  TrafficLightClause clause;
  SourceLocation first = cursor.expect_phrase("the traffic light", "");
  clause.relation = cursor.label(phrases::relation(), "'the traffic light'");
  clause.reference = cursor.name("the actor, road or junction the light is seen from",
                                 quoted(clause.relation.text));
  cursor.expect_phrase("is", after_previous(cursor));
  Label colour = cursor.label(phrases::traffic_light_colour(), "'is'");
  const std::vector<std::string>& colours = phrases::traffic_light_colour().phrases;
  for (std::size_t i = 0; i < colours.size(); ++i)
    if (colours[i] == colour.text) clause.colour.value = static_cast<TrafficLightColour>(i);
  clause.colour.location = colour.location;
  clause.location = cursor.span_from(first);
  return clause;
}

Level1Condition parse_condition(SentenceCursor& cursor, const std::string& after) {
  if (cursor.at_phrase("the traffic light")) return parse_traffic_light_clause(cursor);
  if (!cursor.at(TokenKind::word))
    cursor.fail_expected(
        "a condition such as 'Ego is driving' or 'the traffic light ahead of Ego is red'", after);
  return parse_actor_clause(cursor, after);
}

// WHEN_CONDITION [(, WHEN_CONDITION)* and WHEN_CONDITION]. After the first condition a comma
// starts either more conditions or the first phase: more conditions only if the list goes on to
// "and CONDITION" followed by the comma before the phases.
std::vector<Level1Condition> parse_conditions(SentenceCursor& cursor, const std::string& after) {
  std::vector<Level1Condition> conditions{parse_condition(cursor, after)};
  if (cursor.at_word("and") && at_condition(cursor, 1)) {
    cursor.take();
    conditions.push_back(parse_condition(cursor, "'and'"));
  } else if (cursor.at(TokenKind::comma) && at_condition(cursor, 1)) {
    std::vector<Level1Condition> more;
    bool listed = cursor.attempt([&] {
      do {
        cursor.take();
        more.push_back(parse_condition(cursor, "','"));
      } while (cursor.at(TokenKind::comma) && at_condition(cursor, 1));
      cursor.expect_phrase("and", "");
      if (!at_condition(cursor, 0)) cursor.fail(cursor.peek().location, "not a condition");
      more.push_back(parse_condition(cursor, "'and'"));
      if (!cursor.at(TokenKind::comma)) cursor.fail(cursor.peek().location, "no comma");
    });
    if (listed) conditions.insert(conditions.end(), more.begin(), more.end());
  }
  return conditions;
}

// [then] [ID] [then] MANOEUVRE: a later phase; without a name it is the previous actor's.
PhaseClause parse_later_phase(SentenceCursor& cursor, const Identifier& previous_actor,
                              const std::string& after) {
  PhaseClause phase;
  SourceLocation first = cursor.peek().location;
  std::size_t start = cursor.position();
  if (cursor.at_word("then")) cursor.take();
  if (at_actor_clause(cursor, 0)) {
    phase.actor = cursor.id("an actor", "");
    if (cursor.at_word("then")) cursor.take();
  } else {
    phase.actor = previous_actor;
    phase.actor_written = false;
  }
  phase.manoeuvre =
      parse_manoeuvre(cursor, cursor.position() != start ? after_previous(cursor) : after);
  phase.location = cursor.span_from(first);
  return phase;
}

// The phases after the conditions: FIRST_PHASE (OTHER_PHASE)* '.', where a later phase follows
// ',' or 'and' (', and'), or a full stop and then 'And' or an actor's name.
std::vector<PhaseClause> parse_phases(SentenceCursor& cursor, const std::string& after) {
  std::vector<PhaseClause> phases;
  {
    PhaseClause first;
    ActorClause clause = parse_actor_clause(cursor, after);
    first.actor = clause.actor;
    first.manoeuvre = clause.manoeuvre;
    first.location = clause.location;
    phases.push_back(first);
  }
  while (true) {
    const Identifier& previous_actor = phases.back().actor;
    if (cursor.at(TokenKind::comma)) {
      cursor.take();
      if (cursor.at_word("and")) cursor.take();
      phases.push_back(parse_later_phase(cursor, previous_actor, after_previous(cursor)));
    } else if (cursor.at_word("and")) {
      cursor.take();
      phases.push_back(parse_later_phase(cursor, previous_actor, "'and'"));
    } else if (cursor.at(TokenKind::dot) && cursor.at_word("And", 1)) {
      cursor.take(2);
      phases.push_back(parse_later_phase(cursor, previous_actor, "'And'"));
    } else if (cursor.at(TokenKind::dot) && at_actor_clause(cursor, 1)) {
      cursor.take();
      phases.push_back(parse_later_phase(cursor, previous_actor, "'.'"));
    } else if (cursor.at(TokenKind::dot)) {
      cursor.take();
      return phases;
    } else {
      cursor.fail_expected("',', 'and' or '.'", "the phase of '" + previous_actor.name + "'");
    }
  }
}

// One PHASES group: the conditions (unless a trigger without 'when' or 'as' leaves them out),
// a comma and the phases.
PhaseGroup parse_group(SentenceCursor& cursor, bool with_conditions, const std::string& after) {
  PhaseGroup group;
  SourceLocation first = cursor.peek().location;
  if (with_conditions) {
    group.conditions = parse_conditions(cursor, after);
    cursor.expect(TokenKind::comma, "the conditions");
    group.phases = parse_phases(cursor, "the conditions' ','");
  } else {
    group.phases = parse_phases(cursor, after);
  }
  group.location = cursor.span_from(first);
  return group;
}

bool at_trigger(const SentenceCursor& cursor) {
  return (cursor.at_word("Also") || cursor.at_word("Next")) && cursor.at(TokenKind::comma, 1);
}

bool at_autonomous_sentence(const SentenceCursor& cursor) {
  return cursor.at(TokenKind::word) && cursor.at_phrase("operates autonomously", 1);
}

}  // namespace

bool at_actor_sentence(const SentenceCursor& cursor) {
  return (cursor.at_phrase("There is") || cursor.at_phrase("There are")) &&
         cursor.at(TokenKind::number, 2);
}

// There (is | are) INT ACTOR_TYPE, ID [(, ID)* and ID].
ActorSentence parse_actor_sentence(SentenceCursor& cursor) {
  ActorSentence sentence;
  SourceLocation first = cursor.expect_phrase("There", "");
  if (cursor.at_word("is") || cursor.at_word("are"))
    cursor.take();
  else
    cursor.fail_expected("'is' or 'are'", "'There'", {"is", "are"});
  sentence.count = cursor.whole_number("the number of actors", after_previous(cursor));
  Label type = cursor.label(phrases::actor_type(), quoted(cursor.previous().text));
  const std::vector<std::string>& types = phrases::actor_type().phrases;
  // The list is vehicle, pedestrian, cyclist and then their plurals, in ActorType's order.
  for (std::size_t i = 0; i < types.size(); ++i)
    if (types[i] == type.text) sentence.type.value = static_cast<ActorType>(i % 3);
  sentence.type.location = type.location;
  cursor.expect(TokenKind::comma, quoted(type.text));
  sentence.names.push_back(cursor.id("an actor's name", quoted(type.text + ",")));
  while (true) {
    bool comma = cursor.at(TokenKind::comma);
    if (!comma && !cursor.at_word("and")) break;
    cursor.take();
    sentence.names.push_back(cursor.id("an actor's name", after_previous(cursor)));
    if (!comma) break;
  }
  cursor.expect(TokenKind::dot, "the actors' names");
  sentence.location = cursor.span_from(first);
  return sentence;
}

bool at_location_sentence(const SentenceCursor& cursor) {
  return cursor.at(TokenKind::word) && cursor.at_phrase("is in", 1);
}

// ID is in ID [(, ID is in ID)* and ID is in ID].
std::vector<ActorLocation> parse_location_sentence(SentenceCursor& cursor) {
  std::vector<ActorLocation> locations;
  auto location = [&](const std::string& after) {
    ActorLocation result;
    result.actor = cursor.id("an actor", after);
    cursor.expect_phrase("is in", quoted(result.actor.name));
    result.place = cursor.name("a road or junction", "'is in'");
    result.location = cursor.span_from(result.actor.location);
    locations.push_back(result);
  };
  location("");
  while (true) {
    bool comma = cursor.at(TokenKind::comma);
    if (!comma && !cursor.at_word("and")) break;
    cursor.take();
    location(after_previous(cursor));
    if (!comma) break;
  }
  cursor.expect(TokenKind::dot, "the actors' locations");
  return locations;
}

// When PHASES (NEXT_TRIGGER PHASES)* ID operates autonomously.
Level1Ssms parse_ssms(SentenceCursor& cursor) {
  Level1Ssms ssms;
  SourceLocation first = cursor.expect_phrase("When", "");
  ssms.groups.push_back(parse_group(cursor, true, "'When'"));
  while (true) {
    if (at_trigger(cursor)) {
      Label trigger{cursor.peek().text, false, cursor.peek().location};
      cursor.take(2);
      bool with_conditions = cursor.at_word("when") || cursor.at_word("as");
      std::optional<Label> trigger_word;
      if (with_conditions) {
        trigger_word = Label{cursor.peek().text, false, cursor.peek().location};
        cursor.take();
      }
      PhaseGroup group = parse_group(cursor, with_conditions, after_previous(cursor));
      group.trigger = trigger;
      group.trigger_word = trigger_word;
      group.location = cursor.span_from(trigger.location);
      ssms.groups.push_back(std::move(group));
    } else if (at_autonomous_sentence(cursor)) {
      ssms.autonomous_actor = cursor.id("the actor under test", "");
      cursor.take(2);
      cursor.expect(TokenKind::dot, "'operates autonomously'");
      break;
    } else if (cursor.at(TokenKind::word) && cursor.at(TokenKind::word, 1) &&
               closest_spelling({"operates"}, cursor.peek(1).text)) {
      Identifier actor = cursor.id("the actor under test", "");
      cursor.expect_phrase("operates autonomously", "'" + actor.name + "'");
    } else {
      cursor.fail_expected(
          "'Also, when ...', 'Next, ...' or the actor under test ('Ego operates autonomously.')",
          "the phases", {"Also", "Next"});
    }
  }
  ssms.location = cursor.span_from(first);
  return ssms;
}

}  // namespace scenfuzz::wmg::detail
