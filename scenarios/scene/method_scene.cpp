#include "scenarios/scene/method_scene.hpp"

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

}  // namespace carom
