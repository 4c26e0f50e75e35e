// A value kept on the heap but copied like a plain member: for a rarely set, large member of a
// struct that exists in great numbers, so that the many instances without it stay small (an
// AVUnit item is a number far more often than an actor, which takes 2 KB).
#pragma once

#include <memory>
#include <utility>

#include "lang/demand.hpp"

namespace scenfuzz {

template <class T>
class Boxed {
 public:
  Boxed() = default;
  Boxed(T value) : held_(std::make_unique<T>(std::move(value))) {}  // NOLINT: implicit on purpose
  Boxed(const Boxed& other) : held_(other.held_ ? std::make_unique<T>(*other.held_) : nullptr) {}
  Boxed(Boxed&&) noexcept = default;
  Boxed& operator=(const Boxed& other) {
    if (this != &other) held_ = other.held_ ? std::make_unique<T>(*other.held_) : nullptr;
    return *this;
  }
  Boxed& operator=(Boxed&&) noexcept = default;
  ~Boxed() = default;

  bool has_value() const { return held_ != nullptr; }
  // Reading an empty box is a programmer bug, as reading the wrong alternative of a variant is.
  T& operator*() {
    SCENFUZZ_DEMAND(held_ && "reading an empty Boxed");
    return *held_;
  }
  const T& operator*() const {
    SCENFUZZ_DEMAND(held_ && "reading an empty Boxed");
    return *held_;
  }

 private:
  std::unique_ptr<T> held_;
};

}  // namespace scenfuzz
