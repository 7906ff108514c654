#pragma once
/// Numbers in text meant for a person: messages, errors, `carom check`, `carom info`.
///
/// A value as short as it was typed (0.1, 1.00001, 2e-05) stays as typed; anything longer, such
/// as a derived 2.4000000000000003e-06 or 1.3089969389957471e-06, is shown to 4 significant
/// digits (2.4e-06, 1.309e-06). Data written for programs (summary.json, CSV tables, scene keys
/// passed on) use the exact shortest round-trip text of scene_reader.hpp's format_number instead.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

namespace carom {

/// Significant digits a shown number keeps when its exact text would be longer.
inline constexpr int kDisplayDigits = 4;
/// Exact texts with at most this many significant digits are shown as they are.
inline constexpr int kDisplayExactDigits = 6;

/// `x` for a person to read (see the header comment). "nan", "inf" and "-inf" as such.
inline std::string display_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char exact[64];
  const auto end = std::to_chars(exact, exact + sizeof(exact), x).ptr;
  int digits = 0;
  bool leading = true;
  for (const char* c = exact; c != end && *c != 'e'; ++c) {
    if (*c < '0' || *c > '9') continue;
    if (leading && *c == '0') continue;
    leading = false;
    ++digits;
  }
  if (digits <= kDisplayExactDigits) return std::string(exact, end);
  char rounded[64];
  std::snprintf(rounded, sizeof(rounded), "%.*g", kDisplayDigits, x);
  return rounded;
}

}  // namespace carom
