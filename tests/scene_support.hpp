#pragma once
/// Shared by the scene tests (test_scene.cpp, test_cone_scene.cpp, test_flow_scene.cpp,
/// test_input_errors.cpp, test_placement.cpp): a scene text edited in place, and the message a
/// user gets for a bad scene.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scenarios/scene/scene.hpp"

namespace carom::test {

/// `text` with the first `from` replaced by `to`; a test failure when `from` is not in it.
inline std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

/// Parses (as "bad.toml", with `overrides`) and places the particles; returns the SceneError
/// message ("" when the scene is fine).
inline std::string error_of(const std::string& text,
                            const std::vector<std::string>& overrides = {}) {
  try {
    Scene scene = parse_scene(text, "bad.toml", overrides);
    build_initial_state(scene);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

/// The scene is refused (by parsing or by placing the particles) with a message that contains
/// every fragment (file:line, key, value, allowed range ...).
inline void expect_error(const std::string& text, const std::vector<std::string>& fragments,
                         const std::vector<std::string>& overrides = {}) {
  const std::string message = error_of(text, overrides);
  ASSERT_FALSE(message.empty()) << "accepted:\n" << text;
  for (const auto& f : fragments)
    EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' not in: " << message;
}

/// parse_scene alone refuses `text` with a message that contains every fragment.
inline void expect_parse_error(const std::string& text, const std::vector<std::string>& fragments) {
  try {
    parse_scene(text, "bad.toml");
    ADD_FAILURE() << "accepted:\n" << text;
  } catch (const SceneError& e) {
    const std::string message = e.what();
    for (const auto& f : fragments)
      EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' not in: " << message;
  }
}

}  // namespace carom::test
