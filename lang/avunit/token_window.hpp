// The tokens the parser can see: read on demand from a source of tokens and forgotten once the
// parser has moved past them, so that parsing a big file holds only the statement at hand.
#pragma once

#include <cstddef>
#include <deque>
#include <functional>
#include <utility>

#include "lang/avunit/token.hpp"
#include "lang/demand.hpp"

namespace scenfuzz::avunit {

class TokenWindow {
 public:
  // `next` gives the tokens in order and ends with end_of_file.
  explicit TokenWindow(std::function<Token()> next) : next_(std::move(next)) {}

  // The token at absolute index i, reading ahead as needed; past the end, the end_of_file token.
  // References stay valid until forget_before() drops them (a deque keeps its elements in place).
  const Token& at(std::size_t i) {
    SCENFUZZ_DEMAND(i >= first_ && "reading a token the parser already let go");
    while (!ended_ && i - first_ >= tokens_.size()) {
      tokens_.push_back(next_());
      ended_ = tokens_.back().kind == TokenKind::end_of_file;
    }
    std::size_t k = i - first_;
    return k < tokens_.size() ? tokens_[k] : tokens_.back();
  }

  // Drops the tokens before index i, keeping at least the last one read.
  void forget_before(std::size_t i) {
    while (first_ < i && tokens_.size() > 1) {
      tokens_.pop_front();
      ++first_;
    }
  }

 private:
  std::function<Token()> next_;
  std::deque<Token> tokens_;
  std::size_t first_ = 0;  // the absolute index of tokens_.front()
  bool ended_ = false;
};

}  // namespace scenfuzz::avunit
