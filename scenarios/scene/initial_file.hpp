#pragma once
/// `[initial] from_file`: particles read from a carom run file's snapshot or from a checkpoint,
/// so that a bed settled once can be reused by other scenes.
///
/// The file's kind (root attribute `kind`) says which it is. From a run file, the chosen
/// snapshot's rows are taken as written (id order). From a checkpoint, each particle's stored
/// (delayed) state is brought to the checkpoint's time by the flight of the scene stored in it,
/// exactly as the run would report it, and the particles are put in id order. Species are
/// matched by name against the scene's; radii must equal the scene species' diameter / 2.
#include <cstdint>
#include <vector>

#include "scenarios/scene/scene.hpp"

namespace carom {

/// One particle read from the file, its species already mapped to the scene's.
struct FileParticle {
  std::uint32_t species = 0;     ///< Index into the scene's species.
  Vec3 position = Vec3::Zero();  ///< m.
  Vec3 velocity = Vec3::Zero();  ///< m/s.
  Vec3 spin = Vec3::Zero();      ///< rad/s.
};

/// Reads scene.from_file (which must be set). Throws SceneError naming the scene file, the line
/// and the key initial.from_file, and the HDF5 file: a missing or unreadable file, a file that is
/// not a carom run or checkpoint, a snapshot index out of range, a species the scene does not
/// define, a radius that is not the scene species' diameter / 2.
std::vector<FileParticle> read_initial_file(const Scene& scene);

}  // namespace carom
