#include "scenarios/scene/time_scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace carom {

void read_time_and_output(TableReader& root, Scene& scene) {
  auto t = root.table("time");
  if (!t) root.fail_table("the [time] section is missing (key end, s)");
  scene.end_time = t->number("end", Range::positive("simulated end time, s"));
  t->finish();
  OutputSchedule& out = scene.output;
  out.max_bytes_where = root.file();
  out.snapshot_every = scene.end_time / 100.0;
  out.sample_every = 0.0;
  if (auto o = root.table("output")) {
    out.snapshot_every = o->number("snapshot_every", out.snapshot_every, Range::non_negative("time between snapshots, s (0: only first and last)"));
    out.sample_every = o->number("sample_every", out.sample_every, Range::non_negative("time between time-series rows, s"));
    out.checkpoint_every = o->number("checkpoint_every", 0.0, Range::non_negative("time between checkpoints, s (0: only at the end or on interruption)"));
    out.max_bytes_given = o->has("max_bytes");
    out.max_bytes = o->number("max_bytes", out.max_bytes, Range::positive("largest estimated output of the run, bytes"));
    out.max_bytes_where = o->where_key("max_bytes");
    out.warn_bytes = o->number("warn_bytes", out.warn_bytes,
                               Range::positive("estimated output above which a run warns before it starts, bytes"));
    o->finish();
  }
  if (out.sample_every == 0.0) out.sample_every = out.snapshot_every > 0 ? out.snapshot_every / 10.0 : scene.end_time / 1000.0;
}

}  // namespace carom
