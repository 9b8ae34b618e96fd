"""`pistonslap sweep` on a 2-worker local Dask cluster: rows equal to direct runs, resume after the sweep's process
is killed, a worker killed mid-sweep, specs refused before anything runs."""

import os
import signal
import subprocess
import sys
import tempfile
import threading
import time

import fmpy
import numpy as np
import pytest
from distributed import Client, LocalCluster

from pistonslap.fmu import CYCLE, read_landing_log, simulate
from pistonslap.sweep import run, summary
from pistonslap.sweep_spec import SpecError, parse
from pistonslap.sweep_store import Store
from pistonslap.tables import SAMPLE_DEG

CYCLE_TIME = CYCLE / 125.66  # s, one engine cycle at the crank_speed start value (a hair over 0.1 s)


@pytest.fixture(scope="module")
def model_description(fmu_file):
    return fmpy.read_model_description(fmu_file)


@pytest.fixture(scope="module")
def client():
    with (
        LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster,
        Client(cluster) as client,
    ):
        yield client


def spec_of(model_description, **raw):
    return parse(dict(dict(name="test", cycles=6, skip_cycles=2), **raw), model_description)


def test_grid_rows_are_the_direct_runs(client, model_description, tmp_path):
    """Every metric of every point equals the FMU's own counters over the counted cycles of a direct run; a bore
    narrower than the piston is a failed point carrying the FMU's message, and the sweep goes on."""
    spec = spec_of(model_description, grid={"bore": [0.08008, 0.0801, 0.0799], "restitution": [0.0, 0.8]})
    path, ran = run(spec, tmp_path, client, batch_size=1, progress=False)
    rows = Store(tmp_path, spec).read().to_pylist()
    assert ran == 6 and [r["point"] for r in rows] == list(range(6)) and path.exists()
    # points 4 and 5 have the narrow bore; the summary counts them and quotes the FMU's refusal of the first
    assert summary(path, ran).startswith(f"wrote {path} (6 points, 6 run now, 2 failed; first failure: point 4: ")
    assert "bore" in summary(path, ran).split("point 4: ")[1]
    for row in rows:
        assert (row["bore"], row["restitution"]) == (
            spec.points[row["point"]]["bore"],
            spec.points[row["point"]]["restitution"],
        )
        if row["bore"] < 0.08:
            assert "bore" in row["status"] and np.isnan(row["impacts_per_cycle"]), row
            continue
        # at the sweep's communication step (the demo's), which restarts the integrator at its points
        step = np.radians(SAMPLE_DEG) / 125.66
        direct = simulate(
            stop_time=6 * CYCLE_TIME + step,
            output_interval=step,
            start_values={"bore": row["bore"], "restitution": row["restitution"]},
            output=["impact_count", "impact_energy_total", "max_impact_velocity_in_step"],
        )
        # the samples at the cycle ends, 720° / 0.36° apart
        ends = np.arange(7) * round(720 / SAMPLE_DEG)
        np.testing.assert_allclose(direct["time"][ends], np.arange(7) * CYCLE_TIME, rtol=1e-12)
        assert row["status"] == "ok" and row["response"] is None  # variant 1 is not classified
        impacts, energy = direct["impact_count"][ends], direct["impact_energy_total"][ends]
        assert row["impacts_per_cycle"] == (impacts[6] - impacts[2]) / 4
        assert row["impact_energy_per_cycle"] == pytest.approx((energy[6] - energy[2]) / 4, rel=1e-9)
        # the log's approach speed and the output's agree to round-off (2e-12 here), not bit for bit
        counted = (direct["time"] > 2 * CYCLE_TIME) & (direct["time"] <= 6 * CYCLE_TIME)
        assert row["max_impact_velocity"] == pytest.approx(
            direct["max_impact_velocity_in_step"][counted].max(), rel=1e-9
        )
        if (row["bore"], row["restitution"]) == (0.08008, 0.0):
            assert row["side_changes_per_cycle"] == 6, "A&K's six side changes per cycle (DESIGN.md §6.3)"
        _assert_landings_are_the_logs(row, step)


def _assert_landings_are_the_logs(row, step):
    """A dry point's landing columns are the FMU's landing log over the counted cycles: the landings about the firing
    TDCs ending cycles 3 to 6 (a landing counts in the cycle from −360° to 360° it starts in), per cycle, and the
    largest one's energy, loss and crank angle, from a direct run with the log on."""
    landed = {}
    with tempfile.TemporaryDirectory() as tmp:
        simulate(
            stop_time=6.75 * CYCLE_TIME,
            output_interval=step,
            start_values={"bore": row["bore"], "restitution": row["restitution"], "landing_log": f"{tmp}/l.csv"},
            output=["crank_angle"],
        )
        landed = read_landing_log(f"{tmp}/l.csv")
    cycle = np.floor((125.66 * landed["time"] + 2 * np.pi) / CYCLE)
    for wall in ("thrust", "antithrust"):
        mine = landed[(landed["wall"] == wall) & (cycle >= 3) & (cycle <= 6)]
        assert row[f"landings_per_cycle_{wall}"] == len(mine) / 4 and len(mine) >= 4, (row, wall)
        largest = mine[np.argmax(mine["kinetic_energy"])]
        assert row[f"landing_energy_{wall}"] == largest["kinetic_energy"] > 0
        assert row[f"landing_loss_{wall}"] == largest["energy_loss"]
        assert row[f"landing_crank_angle_{wall}"] == largest["crank_angle"]


SLOW_GRID = {"restitution": [0.2, 0.5, 0.8], "bore": [0.08004, 0.08012]}
#: Cycles of a slow sweep's points: about a second each, sampled every 0.36°.
SLOW_CYCLES = 20


def test_a_rerun_after_the_sweep_is_killed_runs_only_the_missing_points(client, model_description, tmp_path):
    """The sweep's process (and its cluster) killed after two batches: the rerun adds exactly the missing points and
    keeps the recorded ones as they were."""
    text = f"name = 'test'\ncycles = {SLOW_CYCLES}\nskip_cycles = 2\n[grid]\n" + "".join(
        f"{name} = {values}\n" for name, values in SLOW_GRID.items()
    )
    (tmp_path / "spec.toml").write_text(text)
    spec = spec_of(model_description, cycles=SLOW_CYCLES, grid=SLOW_GRID)
    parts = tmp_path / "test" / "parts"
    process = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "pistonslap.cli",
            "sweep",
            str(tmp_path / "spec.toml"),
            "--workers",
            "1",
            "--batch",
            "1",
            "--out",
            str(tmp_path),
        ],
        stderr=subprocess.DEVNULL,
        start_new_session=True,
    )
    deadline = time.monotonic() + 60
    while len(list(parts.glob("*.parquet"))) < 2 and process.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
    os.killpg(process.pid, signal.SIGKILL)
    process.wait()
    before = Store(tmp_path, spec).read().to_pylist()
    assert 2 <= len(before) < len(spec.points), "killed midway"

    _, ran = run(spec, tmp_path, client, progress=False)
    after = Store(tmp_path, spec).read().to_pylist()
    assert ran == len(spec.points) - len(before)
    assert [r["point"] for r in after] == list(range(len(spec.points)))
    assert all(r["status"] == "ok" for r in after)
    assert [r for r in after if r["point"] in {b["point"] for b in before}] == before


def test_a_worker_killed_mid_sweep_loses_nothing(client, model_description, tmp_path):
    """SIGKILL to one worker process of a cluster of its own after the first batch: Dask reruns its tasks on the
    other, every point is recorded once, equal to the undisturbed sweep's rows on the module's cluster. (Whether the
    nanny's replacement joins in time is Dask's affair, not the sweep's: the killed cluster is not used again.)"""
    spec = spec_of(model_description, cycles=SLOW_CYCLES, grid=SLOW_GRID)
    with (
        LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster,
        Client(cluster) as doomed,
    ):
        pids = doomed.run(os.getpid)
        sweep = threading.Thread(target=run, args=(spec, tmp_path, doomed), kwargs=dict(batch_size=1, progress=False))
        sweep.start()
        parts = tmp_path / "test" / "parts"
        while not list(parts.glob("*.parquet")) and sweep.is_alive():
            time.sleep(0.02)
        assert sweep.is_alive(), "the sweep ended before a worker could be killed"
        os.kill(next(iter(pids.values())), signal.SIGKILL)
        sweep.join()
    killed = Store(tmp_path, spec).read().to_pylist()

    _, ran = run(spec, tmp_path / "undisturbed", client, progress=False)
    assert ran == len(spec.points)
    assert killed == Store(tmp_path / "undisturbed", spec).read().to_pylist()


@pytest.mark.parametrize(
    "raw, message",
    [
        (dict(grid={"bore_width": [0.0801]}), "grid.bore_width: the FMU has no variable 'bore_width'"),
        (dict(start={"impact_count": 1}, grid={"bore": [0.0801]}), "start.impact_count: impact_count is an output"),
        (dict(grid={"restitution": [0.5, 1.5]}), r"grid.restitution\[1\] = 1.5 is outside restitution's range"),
        (dict(grid={"bore": {"start": 0.0801, "stop": 0.0802, "num": 0}}), "grid.bore.num = 0"),
        (dict(grid={"model_variant": [1, 1.5]}), r"grid.model_variant\[1\] = 1.5: model_variant is an Integer"),
        (dict(random={"n": 4, "seed": 1, "bore": [0.0802, 0.0801]}), "random.bore = .*: low must be below high"),
        (
            dict(grid={"bore": [0.0801]}, random={"n": 2, "seed": 1, "bore": [0.08, 0.081]}),
            "bore is given in more than one",
        ),
        (dict(cycles=5, skip_cycles=5, grid={"bore": [0.0801]}), "skip_cycles = 5 leaves no cycle"),
        (dict(grid={"impact_log": ["x.csv"]}), "grid.impact_log: impact_log is set by the sweep itself"),
        (dict(grids={"bore": [0.0801]}), r"unknown entries \['grids'\]"),
    ],
)
def test_bad_specs_are_refused_naming_the_entry(model_description, raw, message):
    with pytest.raises(SpecError, match=message):
        spec_of(model_description, **raw)


def test_the_command_refuses_a_bad_spec_before_starting_a_cluster(tmp_path):
    (tmp_path / "bad.toml").write_text("name = 'bad'\ncycles = 4\n[grid]\nrestitution = [2.0]\n")
    done = subprocess.run(
        [sys.executable, "-m", "pistonslap.cli", "sweep", str(tmp_path / "bad.toml"), "--out", str(tmp_path)],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 2 and "grid.restitution[0] = 2.0 is outside restitution's range" in done.stderr
    assert not (tmp_path / "bad").exists()
