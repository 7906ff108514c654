"""The example notebook (scenarios/guides/python_example.ipynb) runs headless from its first cell
to its last without an error and draws its two figures (the bed's pressure drop and snapshot;
the three inlet velocities), as a reader running it would see them. About 15 s."""
import os
import pathlib

import pytest

nbformat = pytest.importorskip("nbformat", reason="Debian: python3-nbformat (with python3-nbconvert)")
nbclient = pytest.importorskip("nbclient", reason="Debian: python3-nbclient python3-ipykernel")

NOTEBOOK = pathlib.Path(__file__).resolve().parents[2] / "scenarios" / "guides" / "python_example.ipynb"


def test_the_example_notebook_runs_and_draws_its_figures(monkeypatch):
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    # The notebook's own folder as its working directory, as Jupyter runs it; the kernel
    # inherits this process's environment, where PYTHONPATH names the module (made absolute,
    # since the kernel starts in another folder).
    paths = [os.path.abspath(p) for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join(paths))
    client = nbclient.NotebookClient(notebook, timeout=120, kernel_name="python3",
                                     resources={"metadata": {"path": str(NOTEBOOK.parent)}})
    client.execute()  # raises CellExecutionError, naming the cell, on any error
    figures = [output for cell in notebook.cells if cell.cell_type == "code" for output in cell.outputs
               if "image/png" in output.get("data", {})]
    assert len(figures) == 2
