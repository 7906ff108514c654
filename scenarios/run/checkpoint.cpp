// Checkpoints: the whole dynamic state of a run (the method's, the gas's), written atomically,
// read back exactly.
#include <stdexcept>
#include <string>
#include <vector>

#include "core/hdf5.hpp"
#include "scenarios/run/file_checksum.hpp"
#include "scenarios/run/output_support.hpp"
#include "scenarios/run/run_output.hpp"

namespace carom {

using namespace output_detail;

std::uint64_t RunInfo::scene_hash() const { return text_hash(scene_text); }

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
    seal_file(file);  // last: it covers everything above
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
  // The kind first (a run file given by mistake gets that message), then the checksum, before
  // any stored value is used.
  if (!checkpoint.file->has_attribute("kind") || checkpoint.file->attribute<std::string>("kind") != kCheckpointKind)
    checkpoint.file->fail(std::string("is not a ") + kCheckpointKind + " file (root attribute 'kind' differs)");
  // A state of another method than the run's is named as such (a more useful message than the
  // checksum's, which would refuse it too).
  const h5::File& file = *checkpoint.file;
  if (file.has_attribute("method") && file.contains("state")) {
    const h5::Group state = file.open_group("state");
    const std::string run_method = file.attribute<std::string>("method");
    if (!run_method.empty() && state.has_attribute("method") && state.attribute<std::string>("method") != run_method)
      state.fail("holds the state of method '" + state.attribute<std::string>("method") + "', but the run's method is '" +
                 run_method + "': the checkpoint is damaged or assembled from two runs");
  }
  verify_file_seal(file);
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
