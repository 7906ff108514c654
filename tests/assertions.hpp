#pragma once
/// Assertion helpers shared by the tests.
#include <gtest/gtest.h>

#include <cmath>

namespace carom::test {

/// Relative closeness |a - b| <= tol |b|, with both numbers and their relative difference in
/// the failure message.
inline ::testing::AssertionResult close(double a, double b, double tol) {
  if (std::abs(a - b) <= tol * std::abs(b)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a << " vs " << b << " (relative " << (a - b) / b << ")";
}

}  // namespace carom::test
