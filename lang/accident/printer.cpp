// Printing an accident tree, part by part.
#include "lang/accident/printer.hpp"

#include <string_view>

#include "lang/accident/vocabulary.hpp"
#include "lang/number_format.hpp"

namespace scenfuzz::accident {

namespace {

std::string point(const Point& p) {
  return "(" + format_number(p.x) + ", " + format_number(p.y) + ")";
}

std::string coord(const Point& p) { return "COORD = " + point(p) + ";"; }

template <typename Value>
std::string word(const Choices<Value>& choices, const Word<Value>& w) {
  return std::string(spelling(choices, w.value));
}

std::string sign(const SignReference& s) {
  return s.kind == SignReference::Kind::point ? point(s.point) : s.name.text;
}

std::string involvement(const Involvement& i) { return i.id.text + ", " + word(parts(), i.part); }

class Printer {
 public:
  std::string run(const File& file) {
    statics(file);
    dynamics(file);
    accident(file);
    return std::move(out_);
  }

 private:
  void line(int indent, std::string_view text) {
    out_.append(static_cast<std::size_t>(2 * indent), ' ');
    out_ += text;
    out_ += '\n';
  }

  void statics(const File& file) {
    line(0, "// Static objects");
    line(0, "STATIC [");
    line(1, "ROAD [ KIND = " + word(road_kinds(), file.road.kind) + "; ]");
    for (const Tree& t : file.trees)
      line(1, "TREE [ ID = " + t.id.text + "; " + coord(t.coords) + " ]");
    for (const Light& l : file.lights)
      line(1, "LIGHT [ ID = " + l.id.text + "; COLOR = " + word(colours(), l.colour) + "; " +
                  coord(l.coords) + " ]");
    for (const LevelCrossing& c : file.crossings) line(1, "CROSSING [ " + coord(c.coords) + " ]");
    for (const StopSign& s : file.stop_signs) line(1, "STOPSIGN [ " + coord(s.coords) + " ]");
    line(0, "]");
  }

  void dynamics(const File& file) {
    line(0, "// Dynamic objects");
    line(0, "DYNAMIC [");
    for (const Vehicle& v : file.vehicles) vehicle(v);
    line(0, "]");
  }

  void vehicle(const Vehicle& v) {
    line(1, "VEHICLE [");
    line(2, "ID = " + v.id.text + ";");
    line(2, "KIND = " + word(vehicle_kinds(), v.kind) + ";");
    if (v.init_direction) line(2, "INITDIRECTION = " + word(directions(), *v.init_direction) + ";");
    if (v.start_sign) line(2, "STARTSIGN = " + sign(*v.start_sign) + ";");
    if (v.end_sign) line(2, "ENDSIGN = " + sign(*v.end_sign) + ";");
    if (!v.chain.empty()) {
      line(2, "CHAIN [");
      for (const Event& e : v.chain)
        line(3, std::string(e.critical ? "CRITICAL_EVENT" : "EVENT") +
                    " [ KIND = " + word(event_kinds(), e.kind) + "; ]");
      line(2, "]");
    }
    line(1, "]");
  }

  void accident(const File& file) {
    line(0, "// Collisions");
    line(0, "ACCIDENT [");
    for (const Collision& c : file.collisions) {
      line(1, "COLLISION [");
      line(2, "ACTOR = " + involvement(c.actor) + ";");
      line(2, "VICTIM = " + involvement(c.victim) + ";");
      if (c.coords) line(2, coord(*c.coords));
      line(1, "]");
    }
    line(0, "]");
  }

  std::string out_;
};

}  // namespace

std::string print(const File& file) { return Printer().run(file); }

}  // namespace scenfuzz::accident
