#include "scenarios/scene/initial_scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace carom {

void read_initial(TableReader& root, Scene& scene) {
  if (auto i = root.table("initial")) {
    scene.seed = static_cast<std::uint64_t>(i->integer("seed", 1, 0, std::numeric_limits<std::int64_t>::max(), "random seed"));
    scene.temperature = i->number("temperature", 0.0, Range::non_negative("granular temperature T = m <v_x^2> of filled particles, J"));
    scene.rms_velocity = i->number("rms_velocity", 0.0, Range::non_negative("rms velocity of filled particles, m/s"));
    if (i->has("temperature") && i->has("rms_velocity"))
      i->fail("rms_velocity", "cannot be given together with initial.temperature; choose one");
    scene.settle_time = i->number("settle_time", 0.0, Range::non_negative("settling run before t = 0, s (0: none)"));
    scene.settle_where = i->where_key("settle_time");
    scene.settle_zero_velocity = i->boolean("settle_zero_velocity", false);
    if (i->has("settle_zero_velocity") && scene.settle_time == 0.0)
      i->fail("settle_zero_velocity", "is only used with initial.settle_time > 0");
    // "scene": the scene's own method settles (Monte Carlo, without excluded volume, settles
    // event-driven). "event_driven": exact events settle any scene, so that runs of the same
    // scene and seed by different methods start from the same bed (a chart's variants).
    scene.settle_by_events =
        i->string("settle_method", "scene", {"scene", "event_driven"}) == "event_driven";
    if (i->has("settle_method") && scene.settle_time == 0.0)
      i->fail("settle_method", "is only used with initial.settle_time > 0");
    if (auto f = i->table("from_file")) {
      InitialFile file;
      file.where = f->where_key("path");
      file.written = f->required_string("path");
      if (file.written.empty()) f->fail("path", "must not be empty (a carom run.h5 or checkpoint.h5)");
      std::filesystem::path path(file.written);
      if (path.is_relative()) path = std::filesystem::path(scene.file).parent_path() / path;
      file.path = path.string();
      file.snapshot_given = f->has("snapshot");
      file.snapshot = f->integer("snapshot", -1, std::numeric_limits<std::int64_t>::min() + 1,
                                 std::numeric_limits<std::int64_t>::max(),
                                 "snapshot index in a run file: 0 first, -1 last, -2 the one before");
      f->finish();
      scene.from_file = file;
    }
    i->finish();
  }
}

}  // namespace carom
