// The AVUnit lexer: token kinds, values and positions.
#include "lang/avunit/lexer.hpp"

#include <gtest/gtest.h>

namespace scenfuzz::avunit {
namespace {

std::vector<Token> lex(const std::string& text, Diagnostics& diagnostics) {
  return tokenize(SourceFile("t.avu", text), diagnostics);
}

std::vector<Token> lex_ok(const std::string& text) {
  Diagnostics diagnostics;
  std::vector<Token> tokens = lex(text, diagnostics);
  EXPECT_FALSE(diagnostics.has_errors()) << text;
  return tokens;
}

TEST(Lexer, NumbersTimesAndIdentifiers) {
  auto tokens = lex_ok("x1 = 12.5 + 3e2 - 7 ; 12:30 9:05:30");
  ASSERT_EQ(tokens.size(), 11u);
  EXPECT_EQ(tokens[0].kind, TokenKind::identifier);
  EXPECT_EQ(tokens[0].text, "x1");
  EXPECT_EQ(tokens[2].number, 12.5);
  EXPECT_EQ(tokens[4].number, 300);
  EXPECT_EQ(tokens[6].number, 7);
  EXPECT_EQ(tokens[8].kind, TokenKind::time);
  EXPECT_EQ(tokens[8].number, 12 * 3600 + 30 * 60);
  EXPECT_EQ(tokens[9].number, 9 * 3600 + 5 * 60 + 30);
}

TEST(Lexer, AColonFollowedByOtherThanTwoDigitsIsNotATime) {
  auto tokens = lex_ok("[0:5] [10:100] {rain:0.5}");
  EXPECT_EQ(tokens[1].kind, TokenKind::number);
  EXPECT_EQ(tokens[2].kind, TokenKind::colon);
  EXPECT_EQ(tokens[6].kind, TokenKind::number);
  EXPECT_EQ(tokens[8].number, 100);
  EXPECT_EQ(tokens[12].kind, TokenKind::colon);
  EXPECT_EQ(tokens[13].number, 0.5);
}

TEST(Lexer, OperatorsIncludingDottedAndArrows) {
  auto tokens = lex_ok("-> |= <= >= == != .+ .- .* ./ a.b ~ & | ^");
  std::vector<TokenKind> kinds;
  for (const Token& token : tokens) kinds.push_back(token.kind);
  std::vector<TokenKind> expected = {
      TokenKind::arrow,      TokenKind::satisfies,  TokenKind::less_equal, TokenKind::greater_equal,
      TokenKind::equal,      TokenKind::not_equal,  TokenKind::dot_plus,   TokenKind::dot_minus,
      TokenKind::dot_star,   TokenKind::dot_slash,  TokenKind::identifier, TokenKind::dot,
      TokenKind::identifier, TokenKind::tilde,      TokenKind::ampersand,  TokenKind::bar,
      TokenKind::caret,      TokenKind::end_of_file};
  EXPECT_EQ(kinds, expected);
}

TEST(Lexer, StraightAndTypographicQuotes) {
  auto tokens = lex_ok("\"a b\" 'c' “lane_1” ‘ego’");
  ASSERT_EQ(tokens.size(), 5u);
  EXPECT_EQ(tokens[0].text, "a b");
  EXPECT_EQ(tokens[1].text, "c");
  EXPECT_EQ(tokens[2].text, "lane_1");
  EXPECT_EQ(tokens[3].text, "ego");
  // Columns count characters, not bytes: ‘ego’ starts at character 20.
  EXPECT_EQ(tokens[3].location.column, 20u);
}

TEST(Lexer, CommentsOfEveryKindAreSkipped) {
  auto tokens = lex_ok("a // one\n# two\n/* three\n four */ b");
  ASSERT_EQ(tokens.size(), 3u);
  EXPECT_EQ(tokens[1].text, "b");
  EXPECT_EQ(tokens[1].location.line, 4u);
  EXPECT_EQ(tokens[1].location.column, 10u);
}

TEST(Lexer, BadCharactersAreReportedOnceAndKeptAsInvalidTokens) {
  Diagnostics diagnostics;
  auto tokens = lex("a @ b", diagnostics);
  ASSERT_EQ(diagnostics.error_count(), 1u);
  EXPECT_EQ(diagnostics.all()[0].location.column, 3u);
  ASSERT_EQ(tokens.size(), 4u);
  EXPECT_EQ(tokens[1].kind, TokenKind::invalid);
}

TEST(Lexer, TimesOutsideADayAreTokensMarkedInvalid) {
  auto tokens = lex_ok("0:60 25:00 24:00");
  EXPECT_TRUE(tokens[0].invalid_time);
  EXPECT_TRUE(tokens[1].invalid_time);
  EXPECT_FALSE(tokens[2].invalid_time);
}

}  // namespace
}  // namespace scenfuzz::avunit
