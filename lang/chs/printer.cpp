// Printing a CH-Scenario tree: numbers in their shortest form that reads back exactly, every
// weather value and flag written out, events in the grammar example's form (the guard and action
// on lines of their own, so that a guard named `guard` is not taken for the placeholder).
#include "lang/chs/printer.hpp"

#include <charconv>
#include <string_view>

namespace scenfuzz::chs {

namespace {

std::string number(double value) {
  char buffer[64];
  auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return error == std::errc() ? std::string(buffer, end) : std::string("0");
}

class Printer {
 public:
  std::string run(const File& file) {
    map(file.map);
    roads(file.roads);
    weather(file.weather);
    conditions(file);
    entities(file);
    constraints(file);
    return std::move(out_);
  }

 private:
  void line(int indent, std::string_view text) {
    out_.append(static_cast<std::size_t>(2 * indent), ' ');
    out_ += text;
    out_ += '\n';
  }
  void field(int indent, std::string_view key, const std::string& value) {
    line(indent, std::string(key) + ": " + value);
  }

  void map(const MapSource& map) {
    if (map.kind == MapSource::Kind::named) return field(0, "map", map.name.text);
    line(0, "import from MAP");
    field(1, "length", number(map.length.value));
    field(1, "width", number(map.width.value));
  }

  static std::string points(const std::vector<Point>& polyline) {
    std::string text;
    for (const Point& p : polyline)
      text += (text.empty() ? "(" : " (") + number(p.x) + ", " + number(p.y) + ")";
    return text;
  }

  void roads(const std::vector<Road>& roads) {
    if (roads.empty()) return;
    line(0, "RoadNetwork");
    for (const Road& road : roads) {
      // A road line takes one word; a name given by `name:` may be more. After `→ name` any
      // word reads back, `->` and `name` too.
      const bool one_word = road.name.text.find_first_of(" \t:") == std::string::npos;
      if (one_word) line(1, "road → name " + road.name.text);
      if (!one_word) field(1, "name", road.name.text);
      field(2, "left boundary", points(road.left_boundary));
      field(2, "center lines", points(road.centre_lines));
      field(2, "right boundary", points(road.right_boundary));
    }
  }

  void weather(const Weather& w) {
    line(0, "Weather");
    field(1, "cloudiness", number(w.cloudiness.value));
    field(1, "wetness", number(w.wetness.value));
    field(1, "air_pressure", number(w.air_pressure.value));
    field(1, "precipitation", number(w.precipitation.value));
    field(1, "wind_intensity", number(w.wind_intensity.value));
    field(1, "visibility", number(w.visibility.value));
  }

  void flag(int indent, std::string_view key, const Flag& flag) {
    field(indent, key, flag.value ? "1" : "0");
  }

  void conditions(const File& file) {
    const NaturalDisaster& d = file.disaster;
    line(0, "NaturalDisaster");
    line(1, "MeteorologicalDisaster");
    flag(2, "rainstorm", d.rainstorm);
    flag(2, "sandstorm", d.sandstorm);
    flag(2, "typhoon", d.typhoon);
    flag(2, "tornado", d.tornado);
    line(1, "GeologicalDisaster");
    flag(2, "debrisflow", d.debris_flow);
    flag(2, "landslide", d.landslide);
    flag(2, "collapse", d.collapse);
    const SpecialHighRisk& h = file.high_risk;
    line(0, "SpecialHighRisk");
    flag(1, "rough", h.rough);
    flag(1, "iceroad", h.ice_road);
    flag(1, "steepdescentahead", h.steep_descent_ahead);
    flag(1, "muddy", h.muddy);
    flag(1, "wade", h.wade);
  }

  void text(int indent, std::string_view key, const Text& value) {
    if (!value.text.empty()) field(indent, key, value.text);
  }

  void position(const std::optional<Point>& point) {
    if (point) field(2, "position", points({*point}));
  }

  void entities(const File& file) {
    if (file.static_entities.empty() && file.dynamic_entities.empty()) return;
    line(0, "Entity");
    int n = 0;
    for (const StaticEntity& e : file.static_entities) {
      line(1, "StaticEntity" + std::to_string(++n));
      text(2, "name", e.name);
      text(2, "overview", e.overview);
      position(e.position);
    }
    n = 0;
    for (const DynamicEntity& e : file.dynamic_entities) {
      line(1, "DynamicEntity" + std::to_string(++n));
      text(2, "name", e.name);
      text(2, "timestamp", e.timestamp);
      field(2, "speed", number(e.speed.value));
      field(2, "acceleration", number(e.acceleration.value));
      text(2, "track", e.track);
      text(2, "aim", e.aim);
      position(e.position);
    }
  }

  static std::string expression(const Expression& e) {
    switch (e.kind) {
      case Expression::Kind::name: return e.text;
      case Expression::Kind::number: return number(e.number);
      case Expression::Kind::boolean: return e.boolean ? "true" : "false";
      case Expression::Kind::negation: return "not (" + expression(e.operands[0]) + ")";
      case Expression::Kind::binary:
        return "(" + expression(e.operands[0]) + ") " + e.text + " (" + expression(e.operands[1]) +
               ")";
    }
    return "";
  }

  static std::string action(const std::vector<Statement>& statements) {
    std::string text;
    for (const Statement& s : statements) {
      if (!text.empty()) text += "; ";
      text += s.target.text;
      if (s.kind == Statement::Kind::increment) text += "++";
      if (s.kind == Statement::Kind::decrement) text += "--";
      if (s.kind == Statement::Kind::assign) text += " = " + expression(s.value);
    }
    return text;
  }

  void constraints(const File& file) {
    if (file.safety_protocols.empty() && file.constraints.empty()) return;
    line(0, "ConstraintList");
    for (const Expression& protocol : file.safety_protocols)
      field(1, "safety_protocol", expression(protocol));
    for (const Constraint& c : file.constraints) {
      std::string related;
      for (const Text& name : c.related) related += (related.empty() ? "" : ", ") + name.text;
      line(1, c.name.text + " relate with " + related);
      for (const Expression& protocol : c.safety_protocols)
        field(2, "safety_protocol", expression(protocol));
      for (const Event& event : c.events) {
        line(2, "event: when guard do action");
        field(2, "guard", expression(event.guard));
        field(2, "action", action(event.action));
        field(2, "probability", number(event.probability.value));
      }
    }
  }

  std::string out_;
};

}  // namespace

std::string print(const File& file) { return Printer().run(file); }

}  // namespace scenfuzz::chs
