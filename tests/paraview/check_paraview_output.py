"""What ParaView makes of a carom run's XDMF sidecars, and whether a rendered snapshot shows it.

    xvfb-run -a pvpython tests/paraview/check_paraview_output.py RUN_DIR [SNAPSHOT.png]

RUN_DIR holds run.h5, run.xmf and run_gas.xmf of a run with a gas. With each of ParaView's three
readers for .xmf (Xdmf3ReaderS, the one pvpython's OpenDataFile and the GUI's first choice
pick; Xdmf3ReaderT; the legacy XDMFReader), and at the first, a middle and the last snapshot:
  - run.xmf gives the particles as one unstructured grid: as many points as the snapshot has
    particles, one vertex cell per point (cell k holds point k alone), the points at the
    positions of run.h5 and radius, velocity, spin, species and id as point data equal to
    run.h5's (bit for bit: the reader copies the doubles), so the time step is the right one;
  - run_gas.xmf gives the gas as one uniform grid of the run's cells (origin and spacing of
    /gas, x y z), with porosity, pressure and velocity as cell data equal to run.h5's;
  - the time steps are the snapshot times of run.h5.
With SNAPSHOT.png (scenarios/plots/paraview_snapshot.py's image on a white background): the
image is not blank: enough coloured pixels left of the colour bar (the spheres).
Exit status 0 when all holds, 1 with the failures listed otherwise.
"""
import os
import sys

os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")
import h5py  # noqa: E402
import numpy as np  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview import simple as pv  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkDataSet, vtkImageData, vtkUnstructuredGrid  # noqa: E402

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
    return condition


def read_run(h5_path):
    """Snapshot times and datasets, and the gas grid, of run.h5."""
    with h5py.File(h5_path, "r") as f:
        names = sorted(f["snapshots"].keys())
        snapshots = []
        for name in names:
            g = f["snapshots"][name]
            s = {"name": name, "time": float(g.attrs["time"])}
            for key in ("position", "velocity", "spin", "radius", "species", "id"):
                s[key] = g[key][()]
            if "gas" in g:
                s["gas"] = {key: g["gas"][key][()] for key in ("porosity", "pressure", "velocity")}
            snapshots.append(s)
        gas = None
        if "gas" in f:
            gas = {key: f["gas"][key][()] for key in ("cells", "lower", "spacing")}
    return snapshots, gas


def readers_for(path):
    """The default reader (what OpenDataFile picks) and the three readers by name."""
    default = pv.OpenDataFile(path)
    name = default.GetXMLName()
    pv.Delete(default)
    return name, {
        "Xdmf3ReaderS": lambda: pv.Xdmf3ReaderS(FileName=[path]),
        "Xdmf3ReaderT": lambda: pv.Xdmf3ReaderT(FileName=[path]),
        "XDMFReader": lambda: pv.XDMFReader(FileNames=[path]),
    }


def point_array(data, name):
    array = data.GetPointData().GetArray(name)
    return None if array is None else vtk_to_numpy(array)


def check_particles(reader_name, data, snapshot):
    where = f"{reader_name}, run.xmf, t = {snapshot['time']}"
    if not check(isinstance(data, vtkUnstructuredGrid),
                 f"{where}: {type(data).__name__}, not one unstructured grid of the particles"):
        return
    n = len(snapshot["radius"])
    check(data.GetNumberOfPoints() == n, f"{where}: {data.GetNumberOfPoints()} points, {n} particles")
    check(data.GetNumberOfCells() == n, f"{where}: {data.GetNumberOfCells()} cells, {n} particles")
    cells = data.GetCells()
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    connectivity = vtk_to_numpy(cells.GetConnectivityArray())
    check(np.array_equal(np.diff(offsets), np.ones(n, dtype=offsets.dtype)),
          f"{where}: not one point per cell")
    check(np.array_equal(connectivity, np.arange(n)), f"{where}: cell k does not hold point k")
    types = {data.GetCellType(k) for k in range(data.GetNumberOfCells())}
    check(types <= {1, 2}, f"{where}: cell types {types}, not vertex (1) / poly-vertex (2)")
    points = vtk_to_numpy(data.GetPoints().GetData())
    check(np.array_equal(points, snapshot["position"]), f"{where}: points differ from the positions")
    for name, components in (("radius", 1), ("velocity", 3), ("spin", 3), ("species", 1), ("id", 1)):
        values = point_array(data, name)
        if not check(values is not None, f"{where}: no point array {name}"):
            continue
        check(data.GetPointData().GetArray(name).GetNumberOfComponents() == components,
              f"{where}: {name} has {data.GetPointData().GetArray(name).GetNumberOfComponents()} components")
        check(np.array_equal(values, snapshot[name]), f"{where}: {name} differs from run.h5")


def check_gas(reader_name, data, snapshot, gas):
    where = f"{reader_name}, run_gas.xmf, t = {snapshot['time']}"
    if not check(isinstance(data, vtkImageData), f"{where}: {type(data).__name__}, not one uniform grid"):
        return
    cells = [int(c) for c in gas["cells"]]
    check(data.GetNumberOfCells() == cells[0] * cells[1] * cells[2],
          f"{where}: {data.GetNumberOfCells()} cells, the gas has {cells}")
    check(list(data.GetDimensions()) == [c + 1 for c in cells],
          f"{where}: {list(data.GetDimensions())} nodes, expected {[c + 1 for c in cells]} (x y z)")
    # Exact: the sidecar lists them with 17 digits, as doubles.
    check(list(data.GetOrigin()) == list(gas["lower"]),
          f"{where}: origin {data.GetOrigin()}, gas lower corner {list(gas['lower'])}")
    check(list(data.GetSpacing()) == list(gas["spacing"]),
          f"{where}: spacing {data.GetSpacing()}, gas cells {list(gas['spacing'])}")
    for name in ("porosity", "pressure", "velocity"):
        array = data.GetCellData().GetArray(name)
        if not check(array is not None, f"{where}: no cell array {name}"):
            continue
        expected = snapshot["gas"][name].reshape(cells[0] * cells[1] * cells[2], -1).squeeze()
        check(np.array_equal(vtk_to_numpy(array), expected),
              f"{where}: {name} differs from run.h5 (cell order x fastest)")


def check_file(path, snapshots, check_data):
    default, readers = readers_for(path)
    check(default in readers, f"{os.path.basename(path)}: default reader {default}, not an XDMF reader")
    print(f"{os.path.basename(path)}: default reader {default}")
    times = [s["time"] for s in snapshots]
    picks = sorted({0, len(snapshots) // 2, len(snapshots) - 1})
    for reader_name, make in readers.items():
        reader = make()
        steps = list(reader.TimestepValues) if reader.TimestepValues else []
        check(steps == times, f"{reader_name}, {os.path.basename(path)}: time steps {steps}, snapshots at {times}")
        for k in picks:
            reader.UpdatePipeline(times[k])
            data = servermanager.Fetch(reader)
            check_data(reader_name, data, snapshots[k])
            kind = type(data).__name__
            count = data.GetNumberOfCells() if isinstance(data, vtkDataSet) else "?"
            print(f"  {reader_name:13s} t = {times[k]:<8.4g} {kind}: {count} cells")
        pv.Delete(reader)


def check_image(png):
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, -1)[:, :, :3].astype(int)
    # The colour bar sits right of 0.86 of the width; left of 0.84 the coloured (not grey)
    # pixels are the spheres'. A 1 mm bead in the 40 mm column of the test's run covers about
    # 100 pixels of an 800 x 600 image; 500 pixels is five beads' worth.
    left = pixels[:, : int(0.84 * width)]
    coloured = int(np.count_nonzero(left.max(axis=2) - left.min(axis=2) > 40))
    background = int(np.count_nonzero((pixels == 255).all(axis=2)))
    print(f"{png}: {width} x {height}, {coloured} coloured pixels left of the colour bar, "
          f"{background} white")
    check(coloured >= 500, f"{png}: {coloured} coloured pixels: no particles drawn")
    check(background >= 0.3 * width * height, f"{png}: {background} white pixels: not a white background")


def main(argv):
    if len(argv) not in (1, 2):
        sys.exit(__doc__)
    run_dir = os.path.abspath(argv[0])
    snapshots, gas = read_run(os.path.join(run_dir, "run.h5"))
    check(len(snapshots) >= 3, f"{len(snapshots)} snapshots: the test needs at least 3")
    check(gas is not None, "run.h5 has no gas: the test needs a run with a gas")
    check_file(os.path.join(run_dir, "run.xmf"), snapshots, check_particles)
    if gas is not None:
        check_file(os.path.join(run_dir, "run_gas.xmf"), snapshots,
                   lambda reader, data, snapshot: check_gas(reader, data, snapshot, gas))
    if len(argv) == 2:
        check_image(argv[1])
    for failure in failures:
        print("FAILED:", failure)
    print("all checks passed" if not failures else f"{len(failures)} checks failed")
    return 0 if not failures else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
