// Level-1 sentences about the world: the environment sentence, junctions and their connections,
// road geometry and the "Also, ..." road features.
#include <array>
#include <functional>

#include "lang/wmg/level1_parse_parts.hpp"
#include "lang/wmg/level1_phrases.hpp"
#include "lang/wmg/parser_cursor.hpp"

namespace scenfuzz::wmg::detail {

namespace {

namespace phrases = level1_phrases;

std::string quoted(const std::string& text) { return "'" + text + "'"; }

// The words just read, quoted, for "after ..." in messages.
std::string after_previous(const SentenceCursor& cursor) { return quoted(cursor.previous().text); }

// A list written `A`, `A and B` or `A, B and C` (the grammar's `ID (, ID)* (and ID)`), of items
// that `at_item` recognises `ahead` tokens from here.
template <typename Item>
std::vector<Item> english_list(SentenceCursor& cursor,
                               const std::function<bool(std::size_t ahead)>& at_item,
                               const std::function<Item()>& item) {
  std::vector<Item> items{item()};
  while (true) {
    if (cursor.at(TokenKind::comma) && at_item(1)) {
      cursor.take();
      items.push_back(item());
    } else if (cursor.at_word("and") && at_item(1)) {
      cursor.take();
      items.push_back(item());
      break;
    } else {
      break;
    }
  }
  return items;
}

std::vector<Identifier> road_list(SentenceCursor& cursor, const std::string& what,
                                  const std::string& after) {
  bool first = true;
  return english_list<Identifier>(
      cursor,
      [&](std::size_t ahead) {
        return cursor.at(TokenKind::word, ahead) && is_road_id(cursor.peek(ahead).text);
      },
      [&] {
        Identifier road = cursor.road_id(what, first ? after : after_previous(cursor));
        first = false;
        return road;
      });
}

struct FeatureVocabulary {
  EnvironmentFeatureKind kind;
  const Vocabulary& (*vocabulary)();
};

const std::array<FeatureVocabulary, 4> kEnvironmentFeatures{{
    {EnvironmentFeatureKind::particulates, &phrases::particulates},
    {EnvironmentFeatureKind::snowfall, &phrases::snowfall},
    {EnvironmentFeatureKind::wind, &phrases::wind},
    {EnvironmentFeatureKind::rainfall, &phrases::rainfall},
}};

EnvironmentFeature parse_environment_feature(SentenceCursor& cursor, const std::string& after) {
  std::size_t best = 0;
  EnvironmentFeature feature;
  for (const FeatureVocabulary& candidate : kEnvironmentFeatures) {
    std::string phrase;
    std::size_t length = cursor.match(candidate.vocabulary(), 0, &phrase);
    if (length > best) {
      best = length;
      feature.kind = candidate.kind;
      feature.phrase.text = phrase;
    }
  }
  if (best == 0) {
    std::vector<std::string> all;
    for (const FeatureVocabulary& candidate : kEnvironmentFeatures)
      for (const std::string& phrase : candidate.vocabulary().phrases) all.push_back(phrase);
    cursor.fail_expected("a weather feature (rain, snow, a breeze or particulates: " +
                             quoted_alternatives(all) + ")",
                         after, all);
  }
  SourceLocation first = cursor.peek().location;
  cursor.take(best);
  feature.phrase.location = feature.location = cursor.span_from(first);
  return feature;
}

std::vector<Label> road_features(SentenceCursor& cursor, const std::string& after) {
  bool first = true;
  return english_list<Label>(
      cursor,
      [&](std::size_t ahead) {
        return cursor.at(TokenKind::string, ahead) ||
               cursor.match(phrases::road_feature(), ahead) > 0;
      },
      [&] {
        Label feature =
            cursor.label(phrases::road_feature(), first ? after : after_previous(cursor));
        first = false;
        return feature;
      });
}

}  // namespace

// During the TIME_OF_DAY, there is a LIGHT [, CLOUD] sky (, [with] FEATURE)* [and [with] FEATURE].
EnvironmentSentence parse_environment_sentence(SentenceCursor& cursor) {
  EnvironmentSentence sentence;
  SourceLocation first = cursor.expect_phrase("During the", "the header");
  sentence.time_of_day = cursor.label(phrases::time_of_day(), "'During the'");
  cursor.expect(TokenKind::comma, quoted("During the " + sentence.time_of_day.text));
  cursor.expect_phrase("there is a", quoted("During the " + sentence.time_of_day.text + ","));
  sentence.light = cursor.label(phrases::light_condition(), "'there is a'");
  if (cursor.at(TokenKind::comma)) {
    cursor.take();
    sentence.cloud = cursor.label(phrases::cloud_condition(), quoted(sentence.light.text + ","));
  } else if (cursor.at(TokenKind::string) || cursor.match(phrases::cloud_condition()) > 0) {
    sentence.cloud = cursor.label(phrases::cloud_condition(), quoted(sentence.light.text));
  }
  cursor.expect_phrase("sky", after_previous(cursor));
  // The first feature may follow "sky" directly when it starts with "with".
  bool first_feature = cursor.at_word("with");
  while (first_feature || cursor.at(TokenKind::comma) || cursor.at_word("and")) {
    bool last = cursor.at_word("and");
    if (!first_feature) cursor.take();
    first_feature = false;
    if (cursor.at_word("with")) cursor.take();
    sentence.features.push_back(parse_environment_feature(cursor, after_previous(cursor)));
    if (last) break;
  }
  if (!cursor.at(TokenKind::dot))
    cursor.fail_expected("',', 'and' or '.'",
                         "the environment sentence's " +
                             std::string(sentence.features.empty() ? "'sky'" : "weather features"));
  cursor.take();
  sentence.location = cursor.span_from(first);
  return sentence;
}

bool at_junction_sentence(const SentenceCursor& cursor) {
  return cursor.at_phrase("There is a") || cursor.at_phrase("There is an");
}

// There is a JUNCTION_TYPE, ID, which has connections with ROAD_ID_LIST.
JunctionSentence parse_junction_sentence(SentenceCursor& cursor) {
  JunctionSentence sentence;
  SourceLocation first = cursor.peek().location;
  cursor.expect_phrase("There is", "");
  if (cursor.at_word("an"))
    cursor.take();
  else
    cursor.expect_phrase("a", "'There is'");
  sentence.type = cursor.label(phrases::junction_type(), after_previous(cursor));
  cursor.expect(TokenKind::comma, "the junction type");
  sentence.id = cursor.id("a junction name such as J1", "the junction type");
  cursor.expect(TokenKind::comma, "the junction's name");
  cursor.expect_phrase("which has connections with", "the junction's name");
  sentence.roads = road_list(cursor, "a connected road", "'connections with'");
  cursor.expect(TokenKind::dot, "the junction's roads");
  sentence.location = cursor.span_from(first);
  return sentence;
}

bool at_connection_sentence(const SentenceCursor& cursor) {
  return cursor.at(TokenKind::word) && is_road_id(cursor.peek().text) && cursor.at_word("to", 1);
}

// ROAD_ID to ROAD_ID is CONNECTION_TYPE.
ConnectionSentence parse_connection_sentence(SentenceCursor& cursor) {
  ConnectionSentence sentence;
  sentence.from = cursor.road_id("the road the connection starts from", "");
  cursor.expect_phrase("to", after_previous(cursor));
  sentence.to = cursor.road_id("the road the connection leads to", "'to'");
  cursor.expect_phrase("is", after_previous(cursor));
  sentence.connection = cursor.label(phrases::connection_type(), "'is'");
  cursor.expect(TokenKind::dot, "the connection");
  sentence.location = cursor.span_from(sentence.from.location);
  return sentence;
}

bool at_road_sentence(const SentenceCursor& cursor) {
  return cursor.at(TokenKind::word) && is_road_id(cursor.peek().text) && !cursor.at_word("to", 1);
}

// (ROAD_ID is a | ROAD_ID_LIST are) HORIZONTAL_GEOMETRY [,] ROAD_TYPE [with TRAFFIC traffic].
RoadSentence parse_road_sentence(SentenceCursor& cursor) {
  RoadSentence sentence;
  SourceLocation first = cursor.peek().location;
  sentence.roads = road_list(cursor, "a road", "");
  if (sentence.roads.size() == 1 && cursor.at_word("is")) {
    cursor.take();
    if (cursor.at_word("an"))
      cursor.take();
    else
      cursor.expect_phrase("a", "'" + sentence.roads[0].name + " is'");
  } else if (cursor.at_word("are")) {
    cursor.take();
  } else {
    cursor.fail_expected(sentence.roads.size() == 1 ? "'is a' or 'are'" : "'are'", "the road names",
                         {"is", "are"});
  }
  sentence.horizontal_geometry =
      cursor.label(phrases::horizontal_geometry(), after_previous(cursor));
  std::string after_geometry = sentence.horizontal_geometry.text;
  if (cursor.at(TokenKind::comma)) {
    cursor.take();
    after_geometry += ",";
  }
  sentence.road_type = cursor.label(phrases::road_type(), quoted(after_geometry));
  if (cursor.at_word("with")) {
    cursor.take();
    sentence.traffic = cursor.label(phrases::traffic_amount(), "'with'");
    cursor.expect_phrase("traffic", quoted("with " + sentence.traffic->text));
  }
  if (!cursor.at(TokenKind::dot))
    cursor.fail_expected(sentence.traffic ? "'.'" : "'with ... traffic' or '.'", "the road type");
  cursor.take();
  sentence.location = cursor.span_from(first);
  return sentence;
}

bool at_road_feature_sentence(const SentenceCursor& cursor) {
  return cursor.at_word("Also") && cursor.at(TokenKind::comma, 1) &&
         cursor.at(TokenKind::word, 2) && is_road_id(cursor.peek(2).text);
}

// Also, (ROAD_ID has | ROAD_ID_LIST have) FEATURE [(, FEATURE)* and FEATURE].
RoadFeatureSentence parse_road_feature_sentence(SentenceCursor& cursor) {
  RoadFeatureSentence sentence;
  SourceLocation first = cursor.expect_phrase("Also", "");
  cursor.expect(TokenKind::comma, "'Also'");
  sentence.roads = road_list(cursor, "a road", "'Also,'");
  if (cursor.at_word("has") || cursor.at_word("have"))
    cursor.take();
  else
    cursor.fail_expected("'has' or 'have'", "the road names", {"has", "have"});
  sentence.features = road_features(cursor, after_previous(cursor));
  cursor.expect(TokenKind::dot, "the road features");
  sentence.location = cursor.span_from(first);
  return sentence;
}

}  // namespace scenfuzz::wmg::detail
