"""docs/python.md's worked example, cell by cell as printed, with its first cell's numbers
made small: sample 5 at 2000 particles (the whole 24 h test in about a second), two seeds."""

import os
import re

import pytest

from conftest import ROOT

SMALL = {"COUNT = 100_000": "COUNT = 2_000", "SEEDS = 5": "SEEDS = 2"}


def test_the_worked_example_of_docs_python_md(tmp_path, monkeypatch):
    pytest.importorskip("pandas")
    pytest.importorskip("matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    text = (ROOT / "docs" / "python.md").read_text()
    example = text[text.index("## Worked example"):]
    cells = re.findall(r"```python\n(.*?)```", example, re.S)
    assert len(cells) >= 4, "docs/python.md's example is cut into python cells"
    code = "\n".join(cells)
    for big, small in SMALL.items():
        assert big in code, big
        code = code.replace(big, small)
    monkeypatch.chdir(tmp_path)
    os.symlink(ROOT / "scenes", tmp_path / "scenes")
    space = {}
    exec(compile(code, "docs/python.md", "exec"), space)
    assert space["sim"].status == "complete"
    assert space["sim"].folder.record["particle_count"] == 2000
    assert (tmp_path / "fig18.png").stat().st_size > 10000
    assert (tmp_path / "fig18_seeds.png").stat().st_size > 10000
    # Every test read, in every seed, over the whole 24 h.
    counts = space["errors"].groupby("test").error_pp.count()
    assert counts.to_dict() == {"buoyancy": 2, "hydrometer": 2, "pipette": 2}
    assert len(space["band"]) > 10 and (space["band"].sd > 0).any()
