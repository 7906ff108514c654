#include "scenarios/python/scene_source.hpp"

namespace carom::python {

SceneSource::SceneSource(std::string text, std::string file)
    : text_(std::move(text)), file_(std::move(file)), scene_(parse_scene(text_, file_)) {}

SceneSource SceneSource::from_file(const std::string& path) {
  // load_scene's checks (a directory, a missing file, a byte-order mark, the size limit), then
  // the text it read is kept for the assignments to come.
  const Scene scene = load_scene(path);
  SceneSource source(scene.text, path);
  return source;
}

SceneSource SceneSource::from_text(const std::string& text, const std::string& file) {
  return SceneSource(text, file);
}

void SceneSource::set(const std::string& assignment) {
  std::vector<std::string> assignments = assignments_;
  assignments.push_back(assignment);
  scene_ = parse_scene(text_, file_, assignments);
  assignments_ = std::move(assignments);
}

}  // namespace carom::python
