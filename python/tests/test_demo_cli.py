"""The `pistonslap` console script: `pistonslap demo` at an operating point of its own writes CSVs whose headers
carry units, the per-cycle table, and the plots `--plots` names (all but the animation by default); its summary opens
with the engine and the operating point; a long run shows its progress; `pistonslap fmu-path` names the FMU the
package carries."""

import csv
import io
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from pistonslap.fmu import fmu_path
from pistonslap.progress import Progress

PISTONSLAP = Path(sys.executable).parent / "pistonslap"


def _run(*args, cwd):
    env = dict(os.environ, MPLBACKEND="Agg")
    return subprocess.run([str(PISTONSLAP), *args], cwd=cwd, env=env, check=True, capture_output=True, text=True).stdout


def test_fmu_path_is_the_packaged_fmu(tmp_path):
    assert Path(_run("fmu-path", cwd=tmp_path).strip()) == fmu_path()


def test_demo_at_an_operating_point(tmp_path):
    out = tmp_path / "demo"
    printed = _run(
        "demo",
        "--rpm",
        "1500",
        "--peak-pressure",
        "60",
        "--clearance",
        "40",
        "--restitution",
        "0.3",
        "--pin-offset",
        "0.5",
        "--cycles",
        "1",
        "--out",
        str(out),
        cwd=tmp_path,
    )
    assert "1500 rpm, peak pressure 60 bar, clearance 40 µm, e = 0.3, pin offset 0.5 mm" in printed
    with open(out / "demo.csv", newline="") as f:
        header = next(csv.reader(f))
    for column in ("time [s]", "crank_angle [rad]", "side_force [N]", "gas_pressure_acting [Pa]", "impact_count [1]"):
        assert column in header, header
    data = np.loadtxt(out / "demo.csv", delimiter=",", skiprows=1)
    speed = np.diff(data[:, header.index("crank_angle [rad]")]) / np.diff(data[:, header.index("time [s]")])
    np.testing.assert_allclose(speed, 1500 * np.pi / 30, rtol=1e-9)
    assert np.degrees(speed[0] * np.diff(data[:, 0])).max() <= 0.5, "samples at most 0.5° apart"
    pressure = data[:, header.index("gas_pressure_acting [Pa]")]
    assert 0.999 * 60e5 < pressure.max() <= 60e5
    with open(out / "cycles.csv", newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0][:3] == ["time [s]", "cycle [1]", "cycle_slap_events [1]"] and len(rows) == 2 and rows[1][1] == "1"
    assert "cycle_slap_energy_thrust [J]" in rows[0] and "cycle_impacts [1]" in rows[0]
    for name in ("slap.png", "forces.png", "piston_motion.png", "piston_positions.png", "impact_log.csv"):
        assert (out / name).stat().st_size > 1000, name
    assert not (out / "film.png").exists(), "the film plot is the lubricated skirt's (skirt_model = 2)"
    assert not (out / "piston_positions.gif").exists(), "the animation is drawn when asked for"


def test_the_summary_opens_with_the_engine_and_the_operating_point(tmp_path):
    lines = _run("demo", "--engine", "flores", "--plots", "none", "--out", "o", cwd=tmp_path)
    first = lines.splitlines()[0]
    assert first.startswith("engine flores; ") and " rpm, " in first and "PistonSlap.fmu" not in first, first


@pytest.mark.parametrize(
    "plots, drawn",
    [
        (["--plots", "gif,slap"], {"piston_positions.gif", "slap.png"}),
        (["--plots", "all", "--no-gif"], {"slap.png", "forces.png", "piston_motion.png", "piston_positions.png"}),
        (["--plots", "none"], set()),
    ],
)
def test_plots_draws_what_it_names(tmp_path, plots, drawn):
    _run("demo", "--cycles", "1", *plots, "--out", "o", cwd=tmp_path)
    assert {p.name for p in (tmp_path / "o").iterdir() if p.suffix in (".png", ".gif")} == drawn


def test_an_unknown_plot_is_refused(tmp_path):
    env = dict(os.environ, MPLBACKEND="Agg")
    done = subprocess.run(
        [str(PISTONSLAP), "demo", "--plots", "slap,gifs", "--out", "o"], cwd=tmp_path, env=env, capture_output=True
    )
    assert done.returncode == 2 and b"gifs" in done.stderr and not (tmp_path / "o").exists(), done.stderr


def test_progress_is_printed_once_a_run_has_taken_its_quiet_time():
    """Every 10 % of the simulated time on its own line (not a terminal); nothing while the run is quick."""
    stream = io.StringIO()
    progress = Progress("run", stop_time=1.0, quiet_for=0.0, stream=stream)
    for k in range(1, 101):
        progress(k / 100)
    assert stream.getvalue().split("\n")[:-1] == [f"run: {p:3d} % of the run, 0 s" for p in range(10, 101, 10)]
    quiet = io.StringIO()
    progress = Progress("run", stop_time=1.0, stream=quiet)
    for k in range(1, 101):
        progress(k / 100)
    assert quiet.getvalue() == ""


@pytest.mark.parametrize(
    "command, label",
    [
        (["demo", "--plots", "none"], "pistonslap demo: simulating"),
        (["coupled", "--cycles", "3"], "pistonslap coupled: simulating"),
    ],
)
def test_the_commands_show_their_progress_once_the_run_is_long(tmp_path, command, label):
    """With no quiet time (`PISTONSLAP_PROGRESS_AFTER=0`) every tenth of the run is a line on stderr, and its end
    (the demo stops once the landing figures are complete, before its stop time); a short run in the default quiet
    time of 3 s prints none."""
    runs = {
        after: subprocess.run(
            [str(PISTONSLAP), *command, "--out", f"o{after}"],
            cwd=tmp_path,
            env=dict(os.environ, MPLBACKEND="Agg", **({"PISTONSLAP_PROGRESS_AFTER": after} if after else {})),
            capture_output=True,
            text=True,
        )
        for after in ("0", None)
    }
    lines = runs["0"].stderr.splitlines()
    assert runs["0"].returncode == 0 and lines[0] == f"{label}:  10 % of the run, 0 s", lines
    assert len(lines) >= 6 and lines[-1].startswith(f"{label}: done in "), lines
    assert runs[None].stderr == "", runs[None].stderr
