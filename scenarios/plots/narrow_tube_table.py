#!/usr/bin/python3
"""The narrow-tube sweep as a table (narrow_tube.md): one row per case (N beads, superficial
gas velocity U, method), with the plug measurement of each case's summary.json at the scene's
threshold and the spread of the plug length over the two thresholds beside it, the bed top's
mean height and its rising and falling speeds, the share of beads that change plugs between
samples, the mean distance a bead travels in 1 s, when a plug first reached the lid (the top of
the domain) and the share of beads held there at the end (centres within 3 diameters of the
lid: a plug pinned under the lid by the gas stays, and the bed-top numbers then describe it),
and the wall time.

    /usr/bin/python3 scenarios/plots/narrow_tube_table.py SWEEP_OUT [RUN_DIR ...]

SWEEP_OUT: a `carom sweep` output folder (cases/NNNN/{case.json,summary.json}); RUN_DIR: further
single runs (a folder with summary.json and run.h5) to add as rows, e.g. the event-driven
contrast.
"""
import json
import os
import sys
import tomllib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from carom_reader import OutputError, open_run  # noqa: E402


def pinned(run_h5, diameter):
    """(first time a bead's centre came within one diameter of the lid, share of beads within
    3 diameters of it at the last sample), from /timeseries/plug_height."""
    try:
        run = open_run(run_h5)
        plug_height = run.series("plug_height")
        heights, t = plug_height.values, plug_height.time
        lid = float(run.domain["upper"][2])
    except (OSError, OutputError):
        return None, None
    near = heights > lid - 0.5 * diameter - diameter
    first = next((t[k] for k in range(len(t)) if near[k].any()), None)
    held = float((heights[-1] > lid - 0.5 * diameter - 3 * diameter).mean())
    return first, held


def row_of(summary, overrides, scene_text, lid):
    scene = tomllib.loads(scene_text) if scene_text else {}
    count = sum(s.get("fill", {}).get("count", 0) for s in scene.get("species", []))
    velocity = scene.get("gas", {}).get("boundaries", {}).get("z_low", {}).get("velocity")
    method = scene.get("method", {}).get("kind", "event_driven")
    for o in overrides:
        key, _, value = o.partition("=")
        if key.endswith("fill.count"):
            count = int(value)
        elif key == "gas.boundaries.z_low.velocity":
            velocity = float(value)
        elif key == "method.kind":
            method = value.strip('"')
    plugs = summary.get("analysis", {}).get("plugs", {})
    levels = plugs.get("by_threshold", [])
    main = levels[0] if levels else {}
    lengths = [b["length_mean"] for b in levels if b.get("length_mean") is not None]
    def f(key, scale=1.0, digits=3):
        v = main.get(key)
        return "-" if v is None else f"{v * scale:.{digits}g}"
    spread = f"{min(lengths):.3g}-{max(lengths):.3g}" if lengths else "-"
    return (f"| {count} | {velocity:.2f} | {method} | {summary.get('status', '?')} | "
            f"{f('plugs_mean')} ± {f('plugs_std', digits=2)} | {f('length_mean')} ± "
            f"{f('length_std', digits=2)} | {spread} | {f('bed_top_mean', 1e3)} | "
            f"{f('rise_speed', 1e3)} / {f('fall_speed', 1e3)} | {f('exchange', digits=2)} | "
            f"{f('travel_1s', 1e3)} | {'-' if lid[0] is None else f'{lid[0]:.2f}'} | "
            f"{'-' if lid[1] is None else f'{lid[1]:.2f}'} | {summary.get('wall_seconds', float('nan')):.0f} |")


def scene_text(run_h5):
    try:
        return open_run(run_h5).scene
    except (OSError, OutputError):
        return ""


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    print("| N | U (m/s) | method | status | plugs | lambda/d | lambda/d at 0.2-0.4 | bed top (mm) "
          "| rise / fall (mm/s) | exchange | travel in 1 s (mm) | at the lid from (s) | held at the lid "
          "| wall (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    sweep = argv[1]
    cases = os.path.join(sweep, "cases")
    folders = [os.path.join(cases, c) for c in sorted(os.listdir(cases))] if os.path.isdir(cases) else [sweep]
    folders += argv[2:]
    for folder in folders:
        summary_path = os.path.join(folder, "summary.json")
        if not os.path.exists(summary_path):
            print(f"| {os.path.basename(folder)}: not finished |")
            continue
        with open(summary_path) as f:
            summary = json.load(f)
        overrides = []
        if os.path.exists(os.path.join(folder, "case.json")):
            with open(os.path.join(folder, "case.json")) as f:
                overrides = json.load(f).get("overrides", [])
        run_h5 = os.path.join(folder, "run.h5")
        diameter = summary.get("analysis", {}).get("plugs", {}).get("diameter", 0.0)
        print(row_of(summary, overrides, scene_text(run_h5), pinned(run_h5, diameter)))


if __name__ == "__main__":
    main(sys.argv)
