// The top level of a level-2 file: the header, then the sections in their order, each parsed by
// its own file; a section with an error is skipped up to the next section keyword.
#include "lang/wmg/parser.hpp"

#include <functional>

#include "lang/wmg/lexer.hpp"
#include "lang/wmg/parse_sections.hpp"

namespace scenfuzz::wmg {

namespace {

using detail::Cursor;
using detail::SyntaxError;

// VERSION ':' INT.INT — the lexer reads `1.0` as one number; its two parts are the version.
Version parse_version(Cursor& cursor) {
  cursor.expect_phrase("VERSION", "at the start of the file");
  cursor.expect(TokenKind::colon, "after 'VERSION'");
  const Token& token = cursor.peek();
  std::size_t dot = token.text.find('.');
  constexpr std::size_t kMostDigits = 9;
  if (token.kind != TokenKind::number || dot == std::string::npos || dot > kMostDigits ||
      token.text.size() - dot - 1 > kMostDigits)
    cursor.fail(token.location,
                "expected a version number such as 1.0 after 'VERSION:', found " + describe(token));
  Version version;
  version.major_part = digits_of(token, 0, dot);
  version.minor_part = digits_of(token, dot + 1, token.text.size() - dot - 1);
  version.location = token.location;
  cursor.take();
  return version;
}

Label parse_extension(Cursor& cursor) {
  cursor.expect_phrase("EXTENSION", "in the header");
  cursor.expect(TokenKind::colon, "after 'EXTENSION'");
  return cursor.label(vocabulary::extension());
}

// scenfuzz's `NPC BEHAVIOUR: Reactive | Scripted` lines, at most one, anywhere after VERSION.
void parse_npc_behaviour(Cursor& cursor, Header& header) {
  while (cursor.at_phrase("NPC BEHAVIOUR")) {
    if (header.npc_behaviour)
      cursor.fail(cursor.peek().location, "the header has two NPC BEHAVIOUR lines; keep one");
    cursor.expect_phrase("NPC BEHAVIOUR", "in the header");
    cursor.expect(TokenKind::colon, "after 'NPC BEHAVIOUR'");
    header.npc_behaviour = cursor.enumerated<NpcBehaviourWord>(vocabulary::npc_behaviour());
  }
}

// HEADER: VERSION, then the authors with the extension line before or after them; scenfuzz's
// NPC BEHAVIOUR line anywhere among them.
Header parse_header(Cursor& cursor) {
  Header header;
  SourceLocation first = cursor.peek().location;
  header.version = parse_version(cursor);
  parse_npc_behaviour(cursor, header);
  if (cursor.at_phrase("EXTENSION")) header.extension = parse_extension(cursor);
  parse_npc_behaviour(cursor, header);
  while (cursor.at_phrase("AUTHOR")) {
    cursor.take();
    cursor.expect(TokenKind::colon, "after 'AUTHOR'");
    header.authors.push_back(cursor.string("the author"));
    parse_npc_behaviour(cursor, header);
  }
  if (header.authors.empty())
    cursor.fail(cursor.peek().location,
                "expected 'AUTHOR: 'name'' after the version, found " + describe(cursor.peek()));
  if (cursor.at_phrase("EXTENSION")) {
    if (header.extension)
      cursor.fail(cursor.peek().location, "the header has two EXTENSION lines; keep one");
    header.extension = parse_extension(cursor);
  }
  parse_npc_behaviour(cursor, header);
  header.location = cursor.span_from(first);
  return header;
}

Text parse_internal_elements(Cursor& cursor) {
  cursor.expect_phrase("INTERNAL ELEMENTS", "");
  cursor.expect(TokenKind::colon, "after 'INTERNAL ELEMENTS'");
  return cursor.string("the internal elements");
}

}  // namespace

Level2ParseResult parse_level2(const SourceFile& file) {
  Level2ParseResult result;
  std::vector<Token> tokens = tokenize(file, result.diagnostics);
  if (tokens.size() == 1 && !result.diagnostics.has_errors()) {
    // A file of nothing but comments and blanks is empty too: point at its start.
    result.diagnostics.error(SourceLocation{1, 1, 0, 0},
                             "the file is empty: expected a level-2 scenario starting with "
                             "'VERSION: 1.0'");
    return result;
  }
  Cursor cursor(file, tokens, result.diagnostics);
  Level2File parsed;
  // Each section is parsed once, in order; after an error the cursor moves on to the next
  // section keyword, so every later section is still checked.
  auto section = [&](const std::function<void()>& parse) {
    if (cursor.too_many_errors()) return;
    try {
      parse();
    } catch (const SyntaxError&) {
      cursor.skip_to_section();
    }
  };
  section([&] { parsed.header = parse_header(cursor); });
  section([&] { parsed.scenery = detail::parse_scenery(cursor); });
  section([&] { parsed.dynamics = detail::parse_dynamics(cursor); });
  if (cursor.at_phrase("INTERNAL ELEMENTS"))
    section([&] { parsed.internal_elements = parse_internal_elements(cursor); });
  section([&] { parsed.environment = detail::parse_environment(cursor); });
  if (cursor.at_phrase("TRAFFIC ELEMENTS"))
    section([&] { parsed.traffic = detail::parse_traffic_model(cursor); });
  if (!cursor.too_many_errors() && !cursor.at(TokenKind::end_of_file)) {
    std::string message = "expected the end of the file, found " + describe(cursor.peek());
    if (cursor.at_section_start())
      message +=
          ": the sections come in the order SCENERY ELEMENTS, DYNAMIC ELEMENTS, "
          "[INTERNAL ELEMENTS], ENVIRONMENT ELEMENTS, [TRAFFIC ELEMENTS], each once";
    cursor.error(cursor.peek().location, message);
  }
  if (!result.diagnostics.has_errors()) result.file = std::move(parsed);
  return result;
}

}  // namespace scenfuzz::wmg
