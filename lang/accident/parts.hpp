// The readers of the three parts of a `.acc` file, shared by parser.cpp (the top level) and
// static_part.cpp, dynamic_part.cpp and accident_part.cpp (one file per part): each reads its
// bracket into the File being built.
#pragma once

#include "lang/accident/blocks.hpp"
#include "lang/accident/syntax.hpp"
#include "lang/accident/token_cursor.hpp"

namespace scenfuzz::accident {

struct PartReader {
  TokenCursor& cursor;
  BlockReader& blocks;
  File& file;
  SourceLocation first_road;  // where the first ROAD was written (unknown before it)

  // Each after its keyword was taken.
  void read_static(const Token& keyword);
  void read_dynamic(const Token& keyword);
  void read_accident(const Token& keyword);

 private:
  void read_road(const Token& keyword);
  void read_tree(const Token& keyword);
  void read_light(const Token& keyword);
  void read_marker(const Token& keyword, Context context);  // CROSSING, STOPSIGN
  void read_vehicle(const Token& keyword);
  void read_chain(const Token& keyword, Vehicle& vehicle);
  void read_event(const Token& keyword, bool critical, Vehicle& vehicle);
  void read_collision(const Token& keyword);
};

}  // namespace scenfuzz::accident
