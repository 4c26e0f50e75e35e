// The pieces of the level-1 parser (internal to the WMG front end): one function per kind of
// sentence, shared by the top level in level1_parser.cpp.
#pragma once

#include "lang/wmg/level1_cursor.hpp"
#include "lang/wmg/level1_syntax.hpp"

namespace scenfuzz::wmg::detail {

// ---- scenery and environment (level1_parse_scenery.cpp) ----
EnvironmentSentence parse_environment_sentence(SentenceCursor& cursor);
bool at_junction_sentence(const SentenceCursor& cursor);
JunctionSentence parse_junction_sentence(SentenceCursor& cursor);
bool at_connection_sentence(const SentenceCursor& cursor);
ConnectionSentence parse_connection_sentence(SentenceCursor& cursor);
bool at_road_sentence(const SentenceCursor& cursor);
RoadSentence parse_road_sentence(SentenceCursor& cursor);
bool at_road_feature_sentence(const SentenceCursor& cursor);
RoadFeatureSentence parse_road_feature_sentence(SentenceCursor& cursor);

// ---- actors and what they do (level1_parse_dynamic.cpp) ----
bool at_actor_sentence(const SentenceCursor& cursor);
ActorSentence parse_actor_sentence(SentenceCursor& cursor);
bool at_location_sentence(const SentenceCursor& cursor);
std::vector<ActorLocation> parse_location_sentence(SentenceCursor& cursor);
Level1Ssms parse_ssms(SentenceCursor& cursor);

// ---- names (level1_references.cpp) ----
// Reports every reference to an actor, road or junction that the file does not declare, actor
// counts that differ from the names listed, and names level 2 cannot carry.
void check_references(const Level1File& file, Diagnostics& diagnostics);

}  // namespace scenfuzz::wmg::detail
