#include "scenarios/scene/method_scene.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace carom {

void read_method(TableReader& root, Scene& scene) {
  auto m = root.table("method");
  if (!m) return;
  const std::vector<std::string> names(kMethodNames.begin(), kMethodNames.end());
  const std::string kind = m->string("kind", std::string(method_name(scene.method.kind)), names);
  for (std::size_t k = 0; k < kMethodNames.size(); ++k)
    if (kMethodNames[k] == kind) scene.method.kind = static_cast<MethodKind>(k);
  m->finish();
}

void read_engine(TableReader& root, Scene& scene) {
  if (auto e = root.table("engine")) {
    scene.method.event_driven.grid_level_ratio = e->number("grid_level_ratio", scene.method.event_driven.grid_level_ratio,
                                               Range{0.0, 1.0, false, true, "size ratio that starts a new grid level (0: one grid)"});
    scene.method.event_driven.check_invariants = e->boolean("check_invariants", scene.method.event_driven.check_invariants);
    scene.method.event_driven.threads =
        static_cast<int>(e->integer("threads", 0, 0, 1024,
                                    "threads of one run (0: CAROM_THREADS, else the hardware "
                                    "threads this process may run on)"));
    scene.method.event_driven.prefetch_from = static_cast<std::size_t>(
        e->integer("prefetch_from", static_cast<std::int64_t>(scene.method.event_driven.prefetch_from), 0,
                   1000000000000, "particles from which the engine's loading hints are on (hints change no result)"));
    e->finish();
  }
}

}  // namespace carom
