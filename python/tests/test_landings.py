"""Where the user looks for the landings (issue 55): the demo's summary, cycles.csv and the sweep's results carry per
wall the largest landing's energy, loss and crank angle, the landings per cycle, the peak wall load and its rise
rate, and the skirt FMEP, thinnest film per side with its crank angle, peak film force and asperity load; on a dry
and on a lubricated run, checked against the FMU's landing log and time series, not against this package's code. A
sweep on oil, which has no impacts, says in one line (and on the map) that its impact metrics are 0 everywhere."""

import csv
import os
import re
import subprocess
import sys
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
import pyarrow.parquet as pq
import pytest

from pistonslap import heat_map
from pistonslap.fmu import CYCLE, read_landing_log
from pistonslap.tables import LANDING_METRICS

PISTONSLAP = Path(sys.executable).parent / "pistonslap"
WALLS = ("thrust", "antithrust")
#: The lubricated skirt on a coarse film grid, as a user sets it.
OIL = ("--set", "skirt_model=2", "--set", "skirt_grid_circumferential=6", "--set", "skirt_grid_axial=8")
LANDING_COLUMNS = [f"{name} [{unit}]" for name, unit in LANDING_METRICS.items()]
FILM_COLUMNS = [f"cycle_min_film_thickness_{wall} [m]" for wall in WALLS] + [
    f"cycle_min_film_crank_angle_{wall} [rad]" for wall in WALLS
]
FILM_COLUMNS += ["cycle_max_film_force [N]", "cycle_max_asperity_force [N]", "cycle_skirt_fmep [Pa]"]


def _run(*args, cwd, check=True):
    env = dict(os.environ, MPLBACKEND="Agg")
    return subprocess.run([str(PISTONSLAP), *args], cwd=cwd, env=env, check=check, capture_output=True, text=True)


def _table(path):
    with open(path, newline="") as f:
        header = next(csv.reader(f))
    data = np.atleast_2d(np.genfromtxt(path, delimiter=",", skip_header=1))
    return header, {name.split(" [")[0]: data[:, k] for k, name in enumerate(header)}


def _demo(tmp_path_factory, name, *args):
    out = tmp_path_factory.mktemp(name) / "out"
    printed = _run("demo", "--rpm", "1500", "--cycles", "2", "--out", str(out), *args, cwd=out.parent).stdout
    return out, printed


@pytest.fixture(scope="module", params=["dry", "oil"])
def demo(request, tmp_path_factory):
    return (request.param, *_demo(tmp_path_factory, request.param, *(OIL if request.param == "oil" else ())))


def _centred_cycle(time, omega=1500 * np.pi / 30):
    """Index of the cycle from −360° to 360° about a firing TDC that holds each instant (0: the one about the start)."""
    return np.floor((omega * np.asarray(time) + CYCLE / 2) / CYCLE).astype(int)


def test_cycles_csv_carries_the_landings_of_the_landing_log(demo):
    """Each row's landing columns are those of the landing log's rows of the cycle about the firing TDC that ends
    the row's engine cycle (a landing counts in the cycle it starts in): the count per wall, and the largest
    landing's energy, loss and crank angle; the run goes on until the FMU completed the last one."""
    kind, out, _ = demo
    header, table = _table(out / "cycles.csv")
    assert set(LANDING_COLUMNS + FILM_COLUMNS) <= set(header), header
    log = read_landing_log(out / "landing_log.csv")
    assert len(log) > 0, f"{kind}: the piston lands"
    cycle_of = _centred_cycle(log["time"])
    for row, engine_cycle in enumerate(table["cycle"].astype(int)):
        for wall in WALLS:
            mine = log[(log["wall"] == wall) & (cycle_of == engine_cycle)]
            assert table[f"cycle_landings_{wall}"][row] == len(mine), (kind, row, wall)
            if len(mine):
                largest = mine[np.argmax(mine["kinetic_energy"])]
                assert table[f"cycle_landing_energy_{wall}"][row] == pytest.approx(largest["kinetic_energy"], rel=1e-9)
                assert table[f"cycle_landing_loss_{wall}"][row] == pytest.approx(largest["energy_loss"], rel=1e-9)
                assert table[f"cycle_landing_crank_angle_{wall}"][row] == pytest.approx(
                    largest["crank_angle"], abs=1e-9
                )


def test_cycles_csv_carries_the_film_figures_of_the_time_series(demo):
    """The thinnest film per side with its crank angle, the largest film force and asperity load over the same cycle,
    from demo.csv; on oil the film is thinner than the clearance and loads the walls, dry there is none."""
    kind, out, _ = demo
    _, table = _table(out / "cycles.csv")
    _, series = _table(out / "demo.csv")
    cycle_of = np.floor((series["crank_angle"] + CYCLE / 2) / CYCLE)
    for row, engine_cycle in enumerate(table["cycle"].astype(int)):
        window = cycle_of == engine_cycle
        for wall in WALLS:
            film = series[f"min_film_thickness_{wall}"]
            assert table[f"cycle_min_film_thickness_{wall}"][row] == film[window].min()
            at = np.flatnonzero(window)[np.argmin(film[window])]
            angle = np.mod(series["crank_angle"][at] + CYCLE / 2, CYCLE) - CYCLE / 2
            assert table[f"cycle_min_film_crank_angle_{wall}"][row] == pytest.approx(angle, abs=1e-9)
        assert table["cycle_max_film_force"][row] == np.abs(series["film_force"][window]).max()
        assert table["cycle_max_asperity_force"][row] == series["asperity_force"][window].max()
    if kind == "oil":
        assert 0 < table["cycle_min_film_thickness_thrust"].min() < 40e-6 and table["cycle_max_film_force"].max() > 100
        assert table["cycle_skirt_fmep"][-1] > 0
    else:
        assert not table["cycle_max_film_force"].any() and not table["cycle_max_asperity_force"].any()


def test_the_summary_names_the_landings_per_wall_and_on_oil_the_film(demo):
    """The printed summary gives each wall's landings of the cycle drawn with the largest one's energy and crank
    angle (as the landing log has them), the peak load and its rise rate, the FMEP; on oil the thinnest film."""
    kind, out, printed = demo
    log = read_landing_log(out / "landing_log.csv")
    last = _centred_cycle(log["time"]) == 2  # the run's third, the second whole one: the demo draws it
    line = next(
        line
        for line in printed.splitlines()
        if line.startswith("Landings in the cycle from −360° to 360° about the last firing TDC")
    )
    for wall, name in zip(WALLS, ("major-thrust", "anti-thrust"), strict=True):
        mine = log[last & (log["wall"] == wall)]
        if len(mine):
            largest = mine[np.argmax(mine["kinetic_energy"])]
            said = re.search(
                f"{len(mine)} on the {name} wall, the largest at {np.degrees(largest['crank_angle']):.1f}° with "
                r"(\S+) (mJ|µJ|nJ) of lateral kinetic energy",
                line,
            )
            assert said, line
            factor = {"mJ": 1e3, "µJ": 1e6, "nJ": 1e9}[said[2]]
            assert float(said[1]) == pytest.approx(largest["kinetic_energy"] * factor, rel=1e-2)
    assert "kN/ms" in line and "Skirt friction: FMEP" in printed
    assert ("thinnest film" in printed) == (kind == "oil")


SPEC = """name = "oil_offset"
cycles = 2
skip_cycles = 1
[start]
skirt_model = 2
skirt_grid_circumferential = 6
skirt_grid_axial = 8
[grid]
pin_offset = ["0 mm", "1 mm"]
crank_speed = ["1500 rpm"]
"""


@pytest.fixture(scope="module")
def oil_sweep(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("sweep")
    (tmp / "spec.toml").write_text(SPEC)
    done = _run("sweep", "spec.toml", "--workers", "1", "--out", "sweeps", cwd=tmp)
    return tmp, done.stdout


def test_an_oil_sweep_carries_the_landings_and_says_its_impact_metrics_are_zero(oil_sweep):
    """On oil there is no impact: the sweep says in one line that its impact metrics read 0 at every point; its
    landing and film columns hold the landings (each wall's largest landing and peak load, the film)."""
    tmp, printed = oil_sweep
    lines = printed.strip().splitlines()
    assert lines[0].startswith("wrote sweeps/oil_offset/results.parquet (2 points, 2 run now, 0 failed)")
    assert lines[1].startswith("0 at every point of the sweep: impacts_per_cycle, max_impact_velocity"), lines
    assert "landing_energy_thrust" not in lines[1] and len(lines) == 2
    rows = pq.read_table(tmp / "sweeps" / "oil_offset" / "results.parquet").to_pylist()
    for row in rows:
        assert row["status"] == "ok" and row["impacts_per_cycle"] == 0
        for wall in WALLS:
            assert row[f"landing_energy_{wall}"] > 0 and row[f"max_liner_force_{wall}"] > 100, row
            assert row[f"landings_per_cycle_{wall}"] >= 1
            assert 0 < row[f"min_film_thickness_{wall}"] < 40e-6
            assert -np.pi * 2 <= row[f"landing_crank_angle_{wall}"] < 2 * np.pi
        assert row["skirt_fmep"] > 0 and row["max_film_force"] > 100


def test_the_map_of_a_metric_zero_everywhere_says_so(oil_sweep, monkeypatch):
    """`pistonslap map` of impacts_per_cycle on the oil sweep prints one line saying it is 0 at every point, and the
    map carries the same words; a metric that varies gets no such line."""
    tmp, _ = oil_sweep
    folder = tmp / "sweeps" / "oil_offset"
    args = ("map", str(folder), "--x", "pin_offset", "--y", "crank_speed")
    zero = _run(*args, "--metric", "impacts_per_cycle", cwd=tmp).stdout.strip().splitlines()
    assert zero[1] == "impacts_per_cycle is 0 at every point drawn: the map is one colour", zero
    varying = _run(*args, "--metric", "landing_energy_thrust", cwd=tmp).stdout.strip().splitlines()
    assert len(varying) == 1 and varying[0].startswith("wrote ")
    drawn = []
    monkeypatch.setattr(heat_map.plt, "close", drawn.append)
    heat_map.heat_map(
        pq.read_table(folder / "results.parquet"), "pin_offset", "crank_speed", "impacts_per_cycle", tmp / "m.png", "t"
    )
    texts = [t.get_text() for t in drawn[0].axes[0].texts]
    assert texts == ["impacts_per_cycle is 0 at every point"]
    plt.close(drawn[0])
