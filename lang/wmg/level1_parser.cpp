// The top level of a level-1 file: the header, then the sentences in the grammar's order
// (environment, junctions, roads, road features, actors, locations, SSMS). A sentence with an
// error is skipped to its full stop and reading goes on, so independent mistakes are reported
// together; names are checked once every sentence has been read.
#include "lang/wmg/level1_parser.hpp"


#include "lang/wmg/level1_parse_parts.hpp"
#include "lang/wmg/lexer.hpp"

namespace scenfuzz::wmg {

namespace {

using detail::SentenceCursor;
using detail::SentenceError;

// VERSION ':' INT.INT [AUTHOR ':' STRING]
Level1Header parse_header(SentenceCursor& cursor) {
  Level1Header header;
  if (!cursor.at_word("VERSION"))
    cursor.fail_expected("'VERSION: 1.0' at the start of the file", "", {"VERSION"});
  SourceLocation first = cursor.expect_phrase("VERSION", "");
  cursor.expect(TokenKind::colon, "'VERSION'");
  const Token& token = cursor.peek();
  std::size_t dot = token.text.find('.');
  constexpr std::size_t kMostDigits = 9;
  if (token.kind != TokenKind::number || dot == std::string::npos || dot > kMostDigits ||
      token.text.size() - dot - 1 > kMostDigits)
    cursor.fail_expected("a version number such as 1.0", "'VERSION:'");
  header.version.major_part = digits_of(token, 0, dot);
  header.version.minor_part = digits_of(token, dot + 1, token.text.size() - dot - 1);
  header.version.location = token.location;
  cursor.take();
  if (cursor.at_word("AUTHOR")) {
    cursor.take();
    cursor.expect(TokenKind::colon, "'AUTHOR'");
    header.author = cursor.string("the author", "'AUTHOR:'");
  }
  header.location = cursor.span_from(first);
  return header;
}

class Reader {
 public:
  Reader(SentenceCursor& cursor, Level1File& file) : cursor_(cursor), file_(file) {}

  void read() {
    header();
    if (cursor_.at_phrase("During the"))
      sentence([&] { file_.environment = detail::parse_environment_sentence(cursor_); });
    else
      missing("the environment sentence 'During the day, there is a ... sky.'", "the header",
              {"During the"});
    junctions();
    roads();
    dynamics();
    if (!cursor_.at(TokenKind::end_of_file))
      missing("the end of the file or another 'When ...'", "the last SSMS", {"When"});
  }

 private:
  // A part of the file that is not there: reported once, without reading on, because when one
  // part is missing the parts after it usually are not where they should be either.
  void missing(const std::string& expected, const std::string& after,
               const std::vector<std::string>& candidates = {}) {
    if (!lost_ && !cursor_.too_many_errors() && !cursor_.at(TokenKind::invalid))
      cursor_.error(cursor_.peek().location, cursor_.expected_message(expected, after, candidates));
    lost_ = true;
  }

  // Reads one sentence; after an error, skips to its full stop.
  template <typename Read>
  void sentence(Read&& read) {
    if (cursor_.too_many_errors()) return;
    std::size_t start = cursor_.position();
    try {
      read();
    } catch (const SentenceError&) {
      if (cursor_.position() == start && cursor_.at(TokenKind::dot)) cursor_.take();
      cursor_.skip_sentence();
    }
  }

  void header() {
    try {
      file_.header = parse_header(cursor_);
    } catch (const SentenceError&) {
      while (!cursor_.at(TokenKind::end_of_file) && !cursor_.at_phrase("During the"))
        cursor_.take();
    }
  }

  void junctions() {
    if (cursor_.at_phrase("There is no junction present")) {
      sentence([&] {
        cursor_.take(5);
        cursor_.expect(TokenKind::dot, "'There is no junction present'");
      });
      return;
    }
    if (!detail::at_junction_sentence(cursor_)) {
      missing(
          "'There is no junction present.' or a junction such as 'There is a crossroad, J1, "
          "which has connections with R1, R2, R3 and R4.'",
          "the environment sentence", {"There"});
      return;
    }
    while (detail::at_junction_sentence(cursor_) && !cursor_.too_many_errors()) {
      sentence([&] { file_.junctions.push_back(detail::parse_junction_sentence(cursor_)); });
      while (detail::at_connection_sentence(cursor_) && !cursor_.too_many_errors())
        sentence([&] {
          ConnectionSentence connection = detail::parse_connection_sentence(cursor_);
          if (!file_.junctions.empty()) file_.junctions.back().connections.push_back(connection);
        });
    }
  }

  void roads() {
    if (!detail::at_road_sentence(cursor_))
      missing("a road sentence such as 'R1 is a straight, motorway.'", "the junctions");
    while (detail::at_road_sentence(cursor_) && !cursor_.too_many_errors())
      sentence([&] { file_.roads.push_back(detail::parse_road_sentence(cursor_)); });
    while (detail::at_road_feature_sentence(cursor_) && !cursor_.too_many_errors())
      sentence(
          [&] { file_.road_features.push_back(detail::parse_road_feature_sentence(cursor_)); });
  }

  void dynamics() {
    if (!detail::at_actor_sentence(cursor_))
      missing("an actor sentence such as 'There is 1 vehicle, Ego.'", "the road sentences",
              {"There", "Also"});
    while (detail::at_actor_sentence(cursor_) && !cursor_.too_many_errors())
      sentence([&] { file_.actors.push_back(detail::parse_actor_sentence(cursor_)); });
    if (!detail::at_location_sentence(cursor_))
      missing("the actors' locations, such as 'Ego is in R1.'", "the actor sentences");
    while (detail::at_location_sentence(cursor_) && !cursor_.too_many_errors())
      sentence([&] {
        for (ActorLocation& location : detail::parse_location_sentence(cursor_))
          file_.locations.push_back(std::move(location));
      });
    if (!cursor_.at_word("When"))
      missing("'When ...', what the actors do", "the actors' locations", {"When"});
    while (cursor_.at_word("When") && !cursor_.too_many_errors()) {
      std::size_t start = cursor_.position();
      try {
        file_.sequences.push_back(detail::parse_ssms(cursor_));
      } catch (const SentenceError&) {
        // An SSMS runs over several sentences: resume at the next one.
        if (cursor_.position() == start) cursor_.take();
        while (!cursor_.at(TokenKind::end_of_file) && !cursor_.at_word("When")) cursor_.take();
      }
    }
  }

  SentenceCursor& cursor_;
  Level1File& file_;
  bool lost_ = false;
};

}  // namespace

Level1ParseResult parse_level1(const SourceFile& file) {
  Level1ParseResult result;
  std::vector<Token> tokens = tokenize(file, result.diagnostics);
  if (tokens.size() == 1 && !result.diagnostics.has_errors()) {
    result.diagnostics.error(SourceLocation{1, 1, 0, 0},
                             "the file is empty: expected a level-1 scenario starting with "
                             "'VERSION: 1.0'");
    return result;
  }
  SentenceCursor cursor(file, tokens, result.diagnostics);
  Level1File parsed;
  Reader(cursor, parsed).read();
  if (!result.diagnostics.has_errors()) detail::check_references(parsed, result.diagnostics);
  if (!result.diagnostics.has_errors()) result.file = std::move(parsed);
  return result;
}

}  // namespace scenfuzz::wmg
