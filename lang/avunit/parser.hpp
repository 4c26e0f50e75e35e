// Recursive-descent parser from tokens to statements of untyped syntax.
//
// Operator precedence, loosest first (DESIGN.md): `->`, `|`, `&`, `U`, comparisons, `+ -`,
// `* /`, `^`, then prefix and postfix operators. `~ G F X` take a whole comparison as operand,
// as in the AVUnit grammar (`G dis1 >= 1` is `G (dis1 >= 1)`).
#pragma once

#include <optional>
#include <vector>

#include "lang/avunit/syntax.hpp"
#include "lang/diagnostic.hpp"

namespace scenfuzz::avunit {

// A statement with a syntax error is reported and skipped up to its `;`, so that one run
// reports several independent errors.
std::vector<Statement> parse_statements(const std::vector<Token>& tokens, Diagnostics& diagnostics);

// The tokens as one expression and nothing after it; nullopt after a syntax error.
std::optional<Syntax> parse_lone_expression(const std::vector<Token>& tokens,
                                            Diagnostics& diagnostics);

}  // namespace scenfuzz::avunit
