// A scalar that counts the floating-point operations done with it. Technique
// evaluators are templated on the scalar; instantiated with CountingScalar they
// report exact operation counts per evaluated vertex (docs/MEASURES.md, instructions).
#pragma once

#include <cmath>
#include <cstdint>

namespace tb::techniques {

struct OperationCounts {
  uint64_t add = 0;  // additions and subtractions
  uint64_t mul = 0;
  uint64_t div = 0;
  uint64_t sqrt = 0;
  uint64_t compare = 0;  // <, <=, >, >=, ==, !=
  uint64_t total() const { return add + mul + div + sqrt + compare; }
};

// Counts into a thread-local tally, so parallel evaluations do not mix. Read and
// reset it with operationCounts() / resetOperationCounts().
inline thread_local OperationCounts g_operation_counts;
inline OperationCounts& operationCounts() { return g_operation_counts; }
inline void resetOperationCounts() { g_operation_counts = {}; }

template <class T>
class CountingScalar {
 public:
  CountingScalar() = default;
  CountingScalar(T value) : value_(value) {}  // NOLINT: implicit, as a scalar literal is
  explicit operator T() const { return value_; }
  T value() const { return value_; }

  friend CountingScalar operator+(CountingScalar a, CountingScalar b) {
    ++g_operation_counts.add;
    return a.value_ + b.value_;
  }
  friend CountingScalar operator-(CountingScalar a, CountingScalar b) {
    ++g_operation_counts.add;
    return a.value_ - b.value_;
  }
  friend CountingScalar operator*(CountingScalar a, CountingScalar b) {
    ++g_operation_counts.mul;
    return a.value_ * b.value_;
  }
  friend CountingScalar operator/(CountingScalar a, CountingScalar b) {
    ++g_operation_counts.div;
    return a.value_ / b.value_;
  }
  // Negation is a sign flip, free on every GPU (a source modifier): not counted.
  friend CountingScalar operator-(CountingScalar a) { return -a.value_; }
  CountingScalar& operator+=(CountingScalar b) { return *this = *this + b; }
  CountingScalar& operator-=(CountingScalar b) { return *this = *this - b; }
  CountingScalar& operator*=(CountingScalar b) { return *this = *this * b; }
  CountingScalar& operator/=(CountingScalar b) { return *this = *this / b; }

  friend bool operator<(CountingScalar a, CountingScalar b) {
    ++g_operation_counts.compare;
    return a.value_ < b.value_;
  }
  friend bool operator>(CountingScalar a, CountingScalar b) {
    ++g_operation_counts.compare;
    return a.value_ > b.value_;
  }
  friend bool operator<=(CountingScalar a, CountingScalar b) {
    ++g_operation_counts.compare;
    return a.value_ <= b.value_;
  }
  friend bool operator>=(CountingScalar a, CountingScalar b) {
    ++g_operation_counts.compare;
    return a.value_ >= b.value_;
  }
  friend bool operator==(CountingScalar a, CountingScalar b) {
    ++g_operation_counts.compare;
    return a.value_ == b.value_;
  }
  friend bool operator!=(CountingScalar a, CountingScalar b) {
    ++g_operation_counts.compare;
    return a.value_ != b.value_;
  }

  friend CountingScalar sqrt(CountingScalar a) {
    ++g_operation_counts.sqrt;
    return std::sqrt(a.value_);
  }

 private:
  T value_{};
};

}  // namespace tb::techniques
