// Checkpoints: the whole dynamic state of a run (the method's, the gas's), written atomically,
// read back exactly.
#include <stdexcept>
#include <string>
#include <vector>

#include "core/hdf5.hpp"
#include "scenarios/run/output_support.hpp"
#include "scenarios/run/run_output.hpp"

namespace carom {

using namespace output_detail;

void write_checkpoint(const std::string& path, const CollisionMethod& sim, const RunInfo& info,
                      const GasCoupling* gas, const FlowBoundaries* flow) {
  const std::string temporary = path + ".tmp";
  bool created = false;
  try {
    h5::File file = h5::File::create(temporary);
    created = true;
    write_info(file, info, kCheckpointKind);
    sim.save_state(file.create_group("state"));
    if (gas != nullptr) gas->save(file.create_group("gas"));
    if (flow != nullptr) flow->save(file.create_group("flow"));
    file.close();
    replace_file(temporary, path);
  } catch (...) {
    if (created) std::remove(temporary.c_str());  // The previous checkpoint is untouched.
    throw;
  }
}

Checkpoint read_checkpoint(const std::string& path) {
  Checkpoint checkpoint;
  checkpoint.file = std::make_shared<h5::File>(h5::File::open(path, false));
  checkpoint.info = read_info(*checkpoint.file, kCheckpointKind);
  if (!checkpoint.file->contains("state")) checkpoint.file->fail("holds no /state: not a complete checkpoint");
  if (checkpoint.has_gas() && checkpoint.gas_state().contains("state"))
    checkpoint.file->fail(
        "holds the gas state as one positional array, as carom wrote it before the gas checkpoint "
        "had named datasets; this version cannot resume it: run the scene again (or resume it with "
        "the carom that wrote it)");
  return checkpoint;
}

}  // namespace carom
