#pragma once
/// A scene as the Python module holds it: the text it was read from and the `--set`
/// assignments made since, parsed again after each one, so that every change is validated at
/// once with the messages of `carom run --set`.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scenarios/scene/scene.hpp"

namespace carom::python {

class SceneSource {
 public:
  /// Reads and validates a scene file (load_scene). Throws SceneError.
  static SceneSource from_file(const std::string& path);
  /// Validates a scene text; `file` names it in messages, and relative paths in the scene are
  /// taken from its folder. Throws SceneError.
  static SceneSource from_text(const std::string& text, const std::string& file);

  /// Applies "key=value" as `--set key=value` does, on top of the earlier ones. A change the
  /// scene refuses throws SceneError and is forgotten.
  void set(const std::string& assignment);
  /// The scene parsed with every assignment (no particles placed yet).
  const Scene& scene() const { return scene_; }
  /// The assignments made so far, in order.
  const std::vector<std::string>& assignments() const { return assignments_; }

 private:
  SceneSource(std::string text, std::string file);
  std::string text_;  ///< As read.
  std::string file_;
  std::vector<std::string> assignments_;
  Scene scene_;
};

}  // namespace carom::python
