// The untyped syntax tree of an AVUnit / scenest file. The parser only knows the shapes of
// expressions; the elaborator decides what they mean (a tuple may be a coordinate, a state, a
// vehicle type or a colour depending on where it is used).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lang/avunit/token.hpp"

namespace scenfuzz::avunit {

enum class SyntaxKind {
  error,             // what a statement that did not parse is bound to: already reported
  number,            // `number`, `text` as written
  string,            // `text`
  time,              // `number` seconds since midnight
  identifier,        // `text`
  empty,             // a left-out element: `Vehicle(s, , t)`
  star,              // `*`
  tuple,             // ( children ) — also a parenthesised expression, see `parenthesised`
  set,               // { children }
  keyed,             // `text`: children[0], inside a set
  call,              // text( children )
  scenario,          // CreateScenario{ children; ... }
  binary,            // children[0] op children[1]
  unary,             // op children[0]  (- + ~)
  temporal,          // text (G, F, X) [interval] children[0]
  until,             // children[0] U [interval] children[1]
  index,             // children[0][children[1]]
  member,            // children[0].text
  angle,             // children[0] text (deg, rad) [related to children[1]]
  pi,                // children[0] pi
  coordinate_range,  // children[0] range children[1] & children[2]
};

struct IntervalSyntax {
  double lower = 0.0;
  double upper = 0.0;
  SourceLocation location;
};

struct Syntax {
  SyntaxKind kind = SyntaxKind::empty;
  std::string text;
  double number = 0.0;
  TokenKind op = TokenKind::end_of_file;
  bool parenthesised = false;  // tuple: `(x)` with one element and no comma
  std::vector<Syntax> children;
  std::optional<IntervalSyntax> interval;
  int depth = 1;            // height of this subtree: the parser bounds it
  SourceLocation location;  // spans the whole construct
};

enum class StatementKind {
  assignment,         // name = value;
  trace_declaration,  // Trace name = value;   (value is EXE(scenario))
  assertion,          // name |= value;
};

struct Statement {
  StatementKind kind = StatementKind::assignment;
  std::string name;
  SourceLocation name_location;
  Syntax value;
  SourceLocation location;
};

}  // namespace scenfuzz::avunit
