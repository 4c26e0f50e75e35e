// A CH-Scenario file, a line at a time: a section header, `import from MAP`, a road's or a
// constraint's first line, a `key: value` line, or more points of the boundary above. Which keys a
// section takes is in the tables of fields.cpp; what a whole file must hold is checked at the end.
#include "lang/chs/parser.hpp"

#include <set>
#include <string>

#include "lang/chs/constraints.hpp"
#include "lang/chs/fields.hpp"
#include "lang/chs/lines.hpp"
#include "lang/chs/values.hpp"

namespace scenfuzz::chs {

namespace {

enum class Section {
  none,
  blank_map,
  road_network,
  weather,
  disaster,
  high_risk,
  entities,
  constraints
};

class Parser {
 public:
  explicit Parser(const SourceFile& source) : source_(source) {}

  ParseResult run() {
    for (const Line& line : split_lines(source_)) {
      if (result_.diagnostics.too_many_errors()) break;
      read(line);
    }
    close_entity();
    constraints_.finish();
    check_file();
    if (!result_.diagnostics.has_errors()) result_.file = std::move(file_);
    return std::move(result_);
  }

 private:
  void error(SourceLocation where, std::string message) {
    result_.diagnostics.error(where, std::move(message));
  }

  void read(const Line& line) {
    const std::string key = normalised(line.text);
    if (read_header(line, key)) return;
    if (key == "importfrommap") return start_blank_map(line);
    if (section_ == Section::constraints && constraints_.read_start(line)) return;
    // A road line opens the road network, as the weather's keys open the weather.
    if (section_ != Section::constraints && starts_road(line.text)) {
      close_entity();
      section_ = Section::road_network;
      return start_road(line);
    }
    if (line.text.front() == '(') return more_points(line);
    const std::size_t colon = line.text.find(':');
    if (colon == std::string_view::npos)
      return error(line.whole(),
                   "expected a section (such as 'Weather'), 'key: value' or a "
                   "road's points, found '" +
                       std::string(line.text) + "'");
    read_field(line, colon);
  }

  bool read_header(const Line& line, const std::string& key) {
    std::optional<Header> header = header_of(key);
    if (!header) return false;
    close_entity();
    last_points_ = nullptr;
    switch (*header) {
      case Header::road_network: section_ = Section::road_network; break;
      case Header::weather:
        section_ = Section::weather;
        file_.weather.location = line.whole();
        break;
      case Header::disaster:
        section_ = Section::disaster;
        file_.disaster.location = line.whole();
        break;
      case Header::high_risk:
        section_ = Section::high_risk;
        file_.high_risk.location = line.whole();
        break;
      case Header::entities: section_ = Section::entities; break;
      case Header::static_entity: open_entity(line, EntityKind::static_entity); break;
      case Header::dynamic_entity: open_entity(line, EntityKind::dynamic_entity); break;
      case Header::constraints: section_ = Section::constraints; break;
    }
    return true;
  }

  void start_blank_map(const Line& line) {
    if (file_.map.kind != MapSource::Kind::none)
      return error(line.whole(), "the map is given twice");
    file_.map.kind = MapSource::Kind::blank;
    file_.map.location = line.whole();
    section_ = Section::blank_map;
    keys_.clear();
  }

  // The word `road` (any case) and a blank, on a line without a colon.
  static bool starts_road(std::string_view text) {
    return text.size() > 4 && normalised(text.substr(0, 4)) == "road" &&
           (text[4] == ' ' || text[4] == '\t') && text.find(':') == std::string_view::npos;
  }

  // `road NAME`, `road → name NAME` or `road -> name NAME`; a name is one word.
  void start_road(const Line& line) {
    std::size_t at = 4;
    auto skip = [&](std::string_view word) {
      while (at < line.text.size() && line.text[at] == ' ') ++at;
      if (line.text.substr(at).starts_with(word)) at += word.size();
    };
    skip("→");
    skip("->");
    skip("name");
    while (at < line.text.size() && line.text[at] == ' ') ++at;
    const std::string_view name = trimmed(line.text.substr(at));
    if (name.empty() || name.find_first_of(" \t") != std::string_view::npos)
      return error(line.at(at, name.size()), "expected the road's name, one word, after 'road'");
    Road road;
    road.name = {std::string(name), line.at(at, name.size())};
    road.location = line.whole();
    file_.roads.push_back(std::move(road));
    keys_.clear();
    last_points_ = nullptr;
  }

  void more_points(const Line& line) {
    if (last_points_ == nullptr)
      return error(line.at(0, 1),
                   "points belong to a road's boundary or centre line: start "
                   "them with 'left boundary:', 'centre line:' or 'right "
                   "boundary:'");
    read_points(line, 0, *last_points_, result_.diagnostics);
  }

  void read_field(const Line& line, std::size_t colon) {
    const std::string key = normalised(line.text.substr(0, colon));
    const SourceLocation key_at = line.at(0, colon);
    std::size_t value_begin = colon + 1;
    while (value_begin < line.text.size() && line.text[value_begin] == ' ') ++value_begin;
    const Value value{line, value_begin};
    if (key == "map") return read_map_name(line, value);
    if (read_global(key, key_at, value, file_, global_keys_, result_.diagnostics)) return;
    switch (section_) {
      case Section::blank_map:
        if (read_blank_map(key, key_at, value, file_.map, keys_, result_.diagnostics)) return;
        break;
      case Section::road_network: return read_road_field(line, key, key_at, value);
      case Section::entities: return read_entity_field(line, key, key_at, value);
      case Section::constraints:
        if (constraints_.read_field(key, key_at, value)) return;
        break;
      default: break;
    }
    if (boundary_of(probe_, key) != nullptr)
      return error(key_at, "a boundary belongs to a road: start one with 'road NAME'");
    error(key_at, unknown_key_message(line.text.substr(0, colon), key, section_name()));
  }

  void read_map_name(const Line& line, const Value& value) {
    if (file_.map.kind != MapSource::Kind::none)
      return error(line.whole(), "the map is given twice");
    std::optional<Text> name = read_text(value, result_.diagnostics, "the map's name");
    if (!name) return;
    file_.map.kind = MapSource::Kind::named;
    file_.map.name = *name;
    file_.map.location = line.whole();
    section_ = Section::none;
  }

  void read_road_field(const Line& line, const std::string& key, SourceLocation key_at,
                       const Value& value) {
    if (key == "name" || key == "road") {
      std::optional<Text> name = read_text(value, result_.diagnostics, "the road's name");
      if (!name) return;
      Road road;
      road.name = *name;
      road.location = line.whole();
      file_.roads.push_back(std::move(road));
      keys_.clear();
      last_points_ = nullptr;
      return;
    }
    std::vector<Point>* points = nullptr;
    if (!file_.roads.empty()) points = boundary_of(file_.roads.back(), key);
    if (points == nullptr && boundary_of(probe_, key) != nullptr)
      return error(key_at, "a boundary belongs to a road: start one with 'road NAME'");
    if (points == nullptr)
      return error(key_at, unknown_key_message(line.text.substr(0, key_at.length), key, "a road"));
    if (!keys_.insert(key).second)
      return error(key_at, "this road's " + std::string(line.text.substr(0, key_at.length)) +
                               " is given twice");
    last_points_ = points;
    read_points(line, value.begin, *points, result_.diagnostics);
  }

  void open_entity(const Line& line, EntityKind kind) {
    section_ = Section::entities;
    entity_ = PendingEntity{};
    entity_.kind = kind;
    entity_.open = true;
    entity_.location = line.whole();
  }

  void read_entity_field(const Line& line, const std::string& key, SourceLocation key_at,
                         const Value& value) {
    if (key == "name" && (!entity_.open || entity_.named)) {
      close_entity();
      entity_ = PendingEntity{};
      entity_.open = true;
      entity_.location = line.whole();
    }
    if (!entity_.open) return error(key_at, "an entity starts with 'name:'");
    read_entity_key(entity_, key, key_at, line.text.substr(0, key_at.length), value,
                    result_.diagnostics);
  }

  void close_entity() {
    if (!entity_.open) return;
    entity_.open = false;
    if (!entity_.named) return error(entity_.location, "this entity has no 'name:'");
    if (entity_.kind == EntityKind::dynamic_entity) {
      entity_.dynamic_entity.location = entity_.location;
      file_.dynamic_entities.push_back(entity_.dynamic_entity);
    } else {
      entity_.static_entity.location = entity_.location;
      file_.static_entities.push_back(entity_.static_entity);
    }
  }

  std::string section_name() const {
    switch (section_) {
      case Section::blank_map: return "the map";
      case Section::road_network: return "the road network";
      case Section::weather: return "the weather";
      case Section::disaster: return "the natural disasters";
      case Section::high_risk: return "the special high-risk conditions";
      case Section::entities: return "an entity";
      case Section::constraints: return "the constraint list";
      case Section::none: break;
    }
    return "the file";
  }

  // Only for a file whose lines all read: a value already reported would be reported again.
  void check_file() {
    if (!result_.diagnostics.has_errors()) check_whole_file(file_, result_.diagnostics);
  }

  const SourceFile& source_;
  ParseResult result_;
  File file_;
  Section section_ = Section::none;
  std::set<std::string> keys_;         // of the road or blank map being read
  std::set<std::string> global_keys_;  // weather, disasters, high-risk conditions
  std::vector<Point>* last_points_ = nullptr;
  PendingEntity entity_;
  Road probe_;  // only asked which keys name a boundary
  ConstraintReader constraints_{file_, result_.diagnostics};
};

}  // namespace

ParseResult parse(const SourceFile& source) { return Parser(source).run(); }

}  // namespace scenfuzz::chs
