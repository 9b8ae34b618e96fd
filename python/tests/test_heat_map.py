"""`pistonslap map`: a full grid fills its cells, failed points grey, an ambiguous (x, y) pair refused."""

import matplotlib.image
import numpy as np
import pyarrow as pa
import pytest

from pistonslap.heat_map import heat_map
from pistonslap.refusal import Refusal

LIGHTGREY = np.array([211, 211, 211]) / 255


def table(statuses, x=(1.0, 2.0, 1.0, 2.0), y=(0.1, 0.1, 0.2, 0.2)):
    return pa.table(
        dict(
            x=list(x),
            y=list(y),
            impacts_per_cycle=[1.0, 2.0, 3.0, 4.0],
            response=["periodic", "chaos", "periodic", None],
            status=statuses,
        )
    )


def grey_pixels(path):
    return np.all(np.abs(matplotlib.image.imread(path)[..., :3] - LIGHTGREY) < 0.01, axis=-1).sum()


def test_failed_and_unclassified_points_are_grey(tmp_path):
    """A quarter of the axes (thousands of pixels) turns grey for the failed point of a metric map, and for the
    unclassified point of a response map."""
    ok, failed = ["ok"] * 4, ["ok", "ok", "ok", "fmi2ExitInitializationMode: bore ..."]
    metric = [
        grey_pixels(heat_map(table(s), "x", "y", "impacts_per_cycle", tmp_path / "m.png", "t")) for s in (ok, failed)
    ]
    assert metric[1] > metric[0] + 10000
    response = grey_pixels(heat_map(table(ok), "x", "y", "response", tmp_path / "r.png", "t"))
    assert response > metric[0] + 10000


def test_points_sharing_a_cell_are_refused(tmp_path):
    with pytest.raises(Refusal, match="--where"):
        heat_map(table(["ok"] * 4, y=(0.1, 0.1, 0.1, 0.2)), "x", "y", "impacts_per_cycle", tmp_path / "m.png", "t")


def test_a_metric_zero_at_every_point_is_said_on_the_map(tmp_path, monkeypatch):
    """A map of zeros (a failed point aside) carries the words; a metric that varies carries none."""
    from pistonslap import heat_map as module

    drawn = []
    monkeypatch.setattr(module.plt, "close", drawn.append)
    zeros = table(["ok", "ok", "ok", "fmi2ExitInitializationMode: bore ..."]).set_column(
        2, "impacts_per_cycle", pa.array([0.0, 0.0, 0.0, np.nan])
    )
    heat_map(zeros, "x", "y", "impacts_per_cycle", tmp_path / "z.png", "t")
    heat_map(table(["ok"] * 4), "x", "y", "impacts_per_cycle", tmp_path / "v.png", "t")
    assert [t.get_text() for t in drawn[0].axes[0].texts] == ["impacts_per_cycle is 0 at every point"]
    assert len(drawn[1].axes[0].texts) == 0
