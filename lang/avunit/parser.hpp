// Recursive-descent parser from tokens to statements of untyped syntax.
//
// Operator precedence, loosest first (DESIGN.md): `->`, `|`, `&`, `U`, comparisons, `+ -`,
// `* /`, `^`, then prefix and postfix operators. `~ G F X` take a whole comparison as operand,
// as in the AVUnit grammar (`G dis1 >= 1` is `G (dis1 >= 1)`).
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "lang/avunit/lexer.hpp"
#include "lang/avunit/syntax.hpp"
#include "lang/diagnostic.hpp"

namespace scenfuzz::avunit {

// Gives each statement to `each` as soon as it is parsed, so that a big file's syntax trees need
// not all be held at once. A statement with a syntax error is reported and skipped up to its `;`,
// so that one run reports several independent errors; its name is still given, bound to an
// error, so that its uses stay silent.
void parse_statements(TokenReader& reader, Diagnostics& diagnostics,
                      const std::function<void(Statement)>& each);

// The tokens as one expression and nothing after it; nullopt after a syntax error.
std::optional<Syntax> parse_lone_expression(const std::vector<Token>& tokens,
                                            Diagnostics& diagnostics);

}  // namespace scenfuzz::avunit
