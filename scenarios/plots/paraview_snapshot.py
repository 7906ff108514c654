#!/usr/bin/env pvpython
"""One snapshot of a carom run rendered by ParaView: the particles as spheres of their radius,
coloured by speed, inside the outline of the domain.

    xvfb-run -a pvpython scenarios/plots/paraview_snapshot.py RUN_DIR/run.xmf [--time T]
        [--out PNG] [--size W H] [--view iso|x|y|z] [--max-speed V]

    --time T       simulated time, s: the last snapshot at or before T (default: the last one)
    --out PNG      the image (default: run_snapshot_3d.png beside run.xmf; `carom run
                   --overwrite` removes it with the run's other figures)
    --size W H     image size in pixels (default 1600 1200)
    --view         camera: iso (default, from the front, right and above), x, y or z (looking
                   along that axis; z looks down)
    --max-speed V  top of the colour scale, m/s (default: the snapshot's largest speed)

Reads run.xmf with ParaView's default reader for .xmf (Xdmf3ReaderS), as the ParaView GUI
would; the domain box and the scene's name come from run.h5, read by carom.open
(carom_reader.py), when numpy and h5py are importable (Debian: python3-h5py). Needs ParaView's
Python (Debian: paraview python3-paraview); without a display run it under xvfb-run (Debian:
xvfb xauth): `pvpython --force-offscreen-rendering` crashes on machines without a GPU.
Prints the file written, the snapshot time and the particle count.
"""
import argparse
import math
import os
import sys


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        description="Render a carom snapshot (run.xmf) with ParaView: spheres of their radius, coloured by speed.")
    parser.add_argument("xmf", help="the run's XDMF sidecar (RUN_DIR/run.xmf)")
    parser.add_argument("--time", type=float, default=None,
                        help="simulated time, s: the last snapshot at or before it (default: the last)")
    parser.add_argument("--out", default=None, help="PNG to write (default: beside run.xmf)")
    parser.add_argument("--size", type=int, nargs=2, default=[1600, 1200], metavar=("W", "H"),
                        help="image size in pixels (default 1600 1200)")
    parser.add_argument("--view", choices=["iso", "x", "y", "z"], default="iso",
                        help="camera direction (default iso)")
    parser.add_argument("--max-speed", type=float, default=None,
                        help="top of the colour scale, m/s (default: the snapshot's largest speed)")
    return parser.parse_args(argv)


def snapshot_time(times, requested):
    """The last snapshot time at or before `requested` (the first one when it is earlier)."""
    if not times:
        return None
    if requested is None:
        return times[-1]
    at_or_before = [t for t in times if t <= requested + 1e-12 * abs(requested)]
    return at_or_before[-1] if at_or_before else times[0]


def run_metadata(xmf):
    """The domain's (lower, upper) corners and the scene's name from run.h5 beside the sidecar,
    read through carom.open (carom_reader.py); None when it cannot be read (no numpy or h5py in
    ParaView's Python, or no run file)."""
    h5_path = os.path.splitext(xmf)[0] + ".h5"
    try:
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        from carom_reader import open_run

        run = open_run(h5_path)
        domain = run.domain
        return list(domain["lower"]), list(domain["upper"]), run.scene_name
    except Exception:  # the figure goes on with the particles' bounding box and the folder name
        return None


def main(argv):
    args = parse_arguments(argv)
    # ParaView's Xdmf3 readers resolve run.h5 against the sidecar's directory, and fail on a
    # path without one: always hand them an absolute path.
    xmf = os.path.abspath(args.xmf)
    if not os.path.isfile(xmf):
        sys.exit(f"paraview_snapshot.py: {args.xmf}: no such file")

    from paraview import simple as pv

    reader = pv.OpenDataFile(xmf)
    if reader is None:
        sys.exit(f"paraview_snapshot.py: {xmf}: ParaView has no reader for it")
    times = list(reader.TimestepValues) if reader.TimestepValues else []
    time = snapshot_time(times, args.time)
    if time is None:
        sys.exit(f"paraview_snapshot.py: {xmf}: no snapshots yet")

    # Speed |v| as a point array; spheres of diameter 2 r at every particle (the glyph source is
    # a sphere of radius 0.5, so the scale is 2 r).
    speed = pv.Calculator(Input=reader, ResultArrayName="speed", Function="mag(velocity)")
    diameter = pv.Calculator(Input=speed, ResultArrayName="diameter", Function="2*radius")
    glyph = pv.Glyph(Input=diameter, GlyphType="Sphere")
    glyph.OrientationArray = ["POINTS", "No orientation array"]
    glyph.ScaleArray = ["POINTS", "diameter"]
    glyph.ScaleFactor = 1.0
    glyph.GlyphMode = "All Points"
    glyph.GlyphType.ThetaResolution = 24
    glyph.GlyphType.PhiResolution = 16

    view = pv.GetActiveViewOrCreate("RenderView")
    view.ViewSize = list(args.size)
    view.ViewTime = time
    view.Background = [1.0, 1.0, 1.0]
    # ParaView 5.11 uses the colour palette's background unless this is off.
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.OrientationAxesVisibility = 1
    view.OrientationAxesLabelColor = [0.0, 0.0, 0.0]
    view.EnableRenderOnInteraction = 0

    spheres = pv.Show(glyph, view)
    speed.UpdatePipeline(time)
    count = speed.GetDataInformation().GetNumberOfPoints()
    speed_range = speed.PointData["speed"].GetRange() if count else (0.0, 0.0)
    top = args.max_speed if args.max_speed is not None else max(speed_range[1], 1e-12)

    pv.ColorBy(spheres, ("POINTS", "speed"))
    lut = pv.GetColorTransferFunction("speed")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    lut.RescaleTransferFunction(0.0, top)
    lut.AutomaticRescaleRangeMode = "Never"
    spheres.Specular = 0.3
    bar = pv.GetScalarBar(lut, view)
    bar.Title = "speed (m/s)"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    # Font sizes in points, scaled with the image so that labels keep their share of it.
    font = max(14, round(args.size[1] / 50))
    bar.TitleFontSize = bar.LabelFontSize = font
    bar.TitleBold = 0
    bar.RangeLabelFormat = "%-#.3g"
    bar.AutomaticLabelFormat = 1
    bar.ScalarBarLength = 0.4
    bar.WindowLocation = "Any Location"
    bar.Position = [0.86, 0.3]
    bar.Visibility = 1

    # The domain: its box from run.h5, or the particles' bounding box.
    metadata = run_metadata(xmf)
    if metadata is not None:
        lower, upper, _ = metadata
        outline = pv.Box(XLength=upper[0] - lower[0], YLength=upper[1] - lower[1],
                         ZLength=upper[2] - lower[2],
                         Center=[(a + b) / 2 for a, b in zip(lower, upper)])
    else:
        outline = pv.Outline(Input=reader)
    frame = pv.Show(outline, view)
    frame.SetRepresentationType("Outline")
    frame.AmbientColor = frame.DiffuseColor = [0.25, 0.25, 0.25]
    frame.LineWidth = 2.0
    frame.ColorArrayName = ["POINTS", ""]

    name = (metadata[2] if metadata is not None else "") or os.path.basename(os.path.dirname(xmf))
    label = pv.Text(Text=f"{name}   t = {time:.4g} s   {count} particles")
    text = pv.Show(label, view)
    text.WindowLocation = "Upper Left Corner"
    text.Color = [0.0, 0.0, 0.0]
    text.FontSize = font + 2

    # Camera: the whole domain in view, z up.
    view.CameraViewUp = [0.0, 0.0, 1.0] if args.view != "z" else [0.0, 1.0, 0.0]
    direction = {"iso": [1.0, -1.6, 0.9], "x": [1.0, 0.0, 0.0], "y": [0.0, -1.0, 0.0],
                 "z": [0.0, 0.0, 1.0]}[args.view]
    norm = math.sqrt(sum(d * d for d in direction))
    bounds = outline.GetDataInformation().GetBounds() if metadata is None else \
        [lower[0], upper[0], lower[1], upper[1], lower[2], upper[2]]
    center = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (bounds[4] + bounds[5]) / 2]
    view.CameraFocalPoint = center
    view.CameraPosition = [c + d / norm for c, d in zip(center, direction)]
    view.CameraParallelProjection = 0
    view.ResetCamera(False)
    view.GetActiveCamera().Dolly(0.92)  # a margin around the domain

    out = args.out or os.path.join(os.path.dirname(xmf),
                                   os.path.splitext(os.path.basename(xmf))[0] + "_snapshot_3d.png")
    pv.SaveScreenshot(out, view, ImageResolution=list(args.size), TransparentBackground=0)
    print(f"{out}: t = {time:.6g} s, {count} particles")
    # Without this, pvpython 5.11 under Xvfb ends with "GLXBadContext" and exit status 1 while
    # tearing down the render window.
    pv.Delete(view)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
