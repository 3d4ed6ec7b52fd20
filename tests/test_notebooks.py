"""Every notebook in notebooks/ runs top to bottom.

The code cells are executed in order in one namespace, in this process, with
matplotlib's non-interactive backend: no Jupyter kernel is needed.  The
notebooks are stored without outputs.
"""
import glob
import json
import os

import pytest

from conftest import ROOT

pytestmark = pytest.mark.slow     # runs every notebook in a kernel

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

NOTEBOOKS = sorted(glob.glob(os.path.join(ROOT, "notebooks", "*.ipynb")))


def test_there_are_notebooks():
    assert NOTEBOOKS, "notebooks/ holds no notebook"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=os.path.basename)
def test_notebook_runs(path):
    import matplotlib.pyplot as plt

    with open(path) as f:
        nb = json.load(f)
    namespace = {"__name__": "__notebook__"}
    for i, cell in enumerate(nb["cells"]):
        if cell["cell_type"] != "code":
            continue
        assert not cell.get("outputs"), f"{path}: cell {i} is stored with outputs"
        source = "".join(cell["source"])
        exec(compile(source, f"{os.path.basename(path)}[{i}]", "exec"), namespace)
    plt.close("all")
