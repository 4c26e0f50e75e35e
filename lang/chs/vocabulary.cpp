// The free-text vocabulary of CH-Scenario entities (vocabulary.hpp): small word tables, so that
// what scenfuzz understands is exactly what docs/ch-scenario.md lists.
#include "lang/chs/vocabulary.hpp"

#include <algorithm>
#include <array>
#include <numbers>
#include <utility>

namespace scenfuzz::chs {

namespace {

struct KindWord {
  std::string_view word;
  EntityClass kind;
  std::string_view model;
};

constexpr std::array kKindWords{
    KindWord{"car", EntityClass::vehicle, "car"},
    KindWord{"vehicle", EntityClass::vehicle, "car"},
    KindWord{"sedan", EntityClass::vehicle, "car"},
    KindWord{"suv", EntityClass::vehicle, "car"},
    KindWord{"taxi", EntityClass::vehicle, "car"},
    KindWord{"minibus", EntityClass::vehicle, "van"},
    KindWord{"van", EntityClass::vehicle, "van"},
    KindWord{"bus", EntityClass::vehicle, "bus"},
    KindWord{"coach", EntityClass::vehicle, "bus"},
    KindWord{"truck", EntityClass::vehicle, "truck"},
    KindWord{"lorry", EntityClass::vehicle, "truck"},
    KindWord{"tanker", EntityClass::vehicle, "truck"},
    KindWord{"motorcycle", EntityClass::vehicle, "motorcycle"},
    KindWord{"motorbike", EntityClass::vehicle, "motorcycle"},
    KindWord{"scooter", EntityClass::vehicle, "motorcycle"},
    KindWord{"bicycle", EntityClass::cyclist, "bicycle"},
    KindWord{"bike", EntityClass::cyclist, "bicycle"},
    KindWord{"cyclist", EntityClass::cyclist, "bicycle"},
    KindWord{"pedestrian", EntityClass::pedestrian, "pedestrian"},
    KindWord{"pedestrians", EntityClass::pedestrian, "pedestrian"},
    KindWord{"person", EntityClass::pedestrian, "pedestrian"},
    KindWord{"people", EntityClass::pedestrian, "pedestrian"},
    KindWord{"man", EntityClass::pedestrian, "pedestrian"},
    KindWord{"woman", EntityClass::pedestrian, "pedestrian"},
    KindWord{"boy", EntityClass::pedestrian, "pedestrian"},
    KindWord{"girl", EntityClass::pedestrian, "pedestrian"},
    KindWord{"child", EntityClass::pedestrian, "pedestrian"},
    KindWord{"children", EntityClass::pedestrian, "pedestrian"},
    KindWord{"kid", EntityClass::pedestrian, "pedestrian"},
    KindWord{"walker", EntityClass::pedestrian, "pedestrian"},
    KindWord{"worker", EntityClass::pedestrian, "pedestrian"},
    KindWord{"light", EntityClass::traffic_light, ""},
    KindWord{"signal", EntityClass::traffic_light, ""},
    KindWord{"rock", EntityClass::obstacle, ""},
    KindWord{"rocks", EntityClass::obstacle, ""},
    KindWord{"stone", EntityClass::obstacle, ""},
    KindWord{"stones", EntityClass::obstacle, ""},
    KindWord{"boulder", EntityClass::obstacle, ""},
    KindWord{"debris", EntityClass::obstacle, ""},
    KindWord{"tree", EntityClass::obstacle, ""},
    KindWord{"branch", EntityClass::obstacle, ""},
    KindWord{"cone", EntityClass::obstacle, ""},
    KindWord{"cones", EntityClass::obstacle, ""},
    KindWord{"barrier", EntityClass::obstacle, ""},
    KindWord{"roadblock", EntityClass::obstacle, ""},
    KindWord{"box", EntityClass::obstacle, ""},
    KindWord{"obstacle", EntityClass::obstacle, ""},
};

constexpr std::array<std::string_view, 3> kColours{"red", "yellow", "green"};

struct CompassWord {
  std::string_view word;
  double degrees;  // counter-clockwise from east
};

constexpr std::array kCompass{
    CompassWord{"east", 0},        CompassWord{"eastward", 0},    CompassWord{"eastbound", 0},
    CompassWord{"northeast", 45},  CompassWord{"north", 90},      CompassWord{"northward", 90},
    CompassWord{"northbound", 90}, CompassWord{"northwest", 135}, CompassWord{"west", 180},
    CompassWord{"westward", 180},  CompassWord{"westbound", 180}, CompassWord{"southwest", 225},
    CompassWord{"south", 270},     CompassWord{"southward", 270}, CompassWord{"southbound", 270},
    CompassWord{"southeast", 315},
};

constexpr std::array<std::pair<std::string_view, TrackPlace>, 14> kPlaces{{
    {"ahead", TrackPlace::ahead},
    {"front", TrackPlace::ahead},
    {"leading", TrackPlace::ahead},
    {"lead", TrackPlace::ahead},
    {"behind", TrackPlace::behind},
    {"following", TrackPlace::behind},
    {"rear", TrackPlace::behind},
    {"oncoming", TrackPlace::oncoming},
    {"opposite", TrackPlace::oncoming},
    {"approaching", TrackPlace::oncoming},
    {"cross", TrackPlace::crossing},
    {"crosses", TrackPlace::crossing},
    {"crossing", TrackPlace::crossing},
    {"across", TrackPlace::crossing},
}};

// Words that say the entity keeps to its road: read, and nothing to do.
constexpr std::array<std::string_view, 37> kFollowWords{
    "curve",    "curves",    "curving", "bend",   "bends",   "straight", "follow", "follows",
    "keep",     "keeps",     "drive",   "drives", "driving", "go",       "goes",   "going",
    "continue", "continues", "forward", "on",     "to",      "the",      "a",      "an",
    "of",       "its",       "road",    "lane",   "along",   "towards",  "toward", "direction",
    "in",       "into",      "and",     "then",   "way"};

constexpr std::array<std::string_view, 12> kStopWords{"stop",  "stops", "stopped", "stopping",
                                                      "park",  "parks", "parked",  "stationary",
                                                      "still", "wait",  "waits",   "halt"};

template <std::size_t N>
bool among(const std::array<std::string_view, N>& table, std::string_view word) {
  return std::find(table.begin(), table.end(), word) != table.end();
}

// `turn`, `change` and `overtake` with the side word that follows (or precedes) them.
void read_manoeuvre(const std::vector<std::string>& words, std::size_t i, TrackReading& reading,
                    std::vector<bool>& read) {
  const std::string& word = words[i];
  auto side = [&]() -> std::string {
    for (std::size_t j = (i >= 2 ? i - 2 : 0); j < std::min(words.size(), i + 3); ++j)
      if (words[j] == "left" || words[j] == "right") {
        read[j] = true;
        return words[j];
      }
    return "";
  };
  if (word == "turn" || word == "turns" || word == "turning") {
    const std::string s = side();
    if (s.empty()) return;
    reading.manoeuvre = s == "left" ? TrackManoeuvre::turn_left : TrackManoeuvre::turn_right;
  } else if (word == "change" || word == "changes" || word == "changing") {
    const std::string s = side();
    if (s.empty()) return;
    reading.manoeuvre = s == "left" ? TrackManoeuvre::change_left : TrackManoeuvre::change_right;
  } else if (word == "overtake" || word == "overtakes" || word == "overtaking" ||
             word == "passes" || word == "passing") {
    reading.manoeuvre = TrackManoeuvre::overtake;
  } else if (among(kStopWords, word)) {
    reading.manoeuvre = TrackManoeuvre::stop;
  } else {
    return;
  }
  read[i] = true;
}

}  // namespace

std::vector<std::string> words_of(std::string_view text) {
  std::vector<std::string> words;
  std::string word;
  for (char c : text) {
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    if (letter) word += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    if (!letter && !word.empty()) words.push_back(std::move(word)), word.clear();
  }
  if (!word.empty()) words.push_back(std::move(word));
  return words;
}

EntityWords classify_entity(std::string_view name, std::string_view overview) {
  EntityWords result;
  for (std::string_view text : {name, overview})
    for (const std::string& word : words_of(text)) {
      if (result.colour.empty() && among(kColours, word)) result.colour = word;
      if (result.kind != EntityClass::unknown) continue;
      // "traffic_light" is one word to words_of's eye as "traffic", "light": both read.
      for (const KindWord& known : kKindWords)
        if (known.word == word) {
          result.kind = known.kind;
          result.model = std::string(known.model);
        }
    }
  return result;
}

TrackReading read_track(std::string_view text) {
  TrackReading reading;
  const std::vector<std::string> words = words_of(text);
  std::vector<bool> read(words.size(), false);
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string& word = words[i];
    for (const CompassWord& compass : kCompass)
      if (compass.word == word) {
        reading.heading = compass.degrees * std::numbers::pi / 180;
        read[i] = true;
      }
    for (const auto& [place_word, place] : kPlaces)
      if (place_word == word) {
        reading.place = place;
        read[i] = true;
      }
    if (!read[i]) read_manoeuvre(words, i, reading, read);
  }
  for (std::size_t i = 0; i < words.size(); ++i)
    if (!read[i] && !among(kFollowWords, words[i])) reading.unread.push_back(words[i]);
  return reading;
}

}  // namespace scenfuzz::chs
