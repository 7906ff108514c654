#pragma once
/// RunStatistics in HDF5 (checkpoints of every method): written and read back exactly.
#include "core/hdf5.hpp"
#include "events/statistics.hpp"

namespace carom {

/// Writes every counter of `st` into `stats` (attributes and datasets).
void write_statistics(const h5::Group& stats, const RunStatistics& st);
/// Reads what write_statistics wrote; throws std::runtime_error naming the object if incomplete.
RunStatistics read_statistics(const h5::Group& stats);
/// Writes the tagged bodies' ids and impulses into stats/tagged (nothing when none is tagged).
void write_tagged(const h5::Group& stats, const TaggedImpulses& tagged);
/// Reads what write_tagged wrote (none tagged when stats has no "tagged"); slot_of stays empty
/// until the method tags the same ids again (TaggedImpulses::tag).
TaggedImpulses read_tagged(const h5::Group& stats);

}  // namespace carom
