"""The `pistonslap` console script: `pistonslap demo` at an operating point of its own writes CSVs whose headers
carry units, the per-cycle table, and the plots; `pistonslap fmu-path` names the FMU the package carries."""

import csv
import os
import subprocess
import sys
from pathlib import Path

import numpy as np

from pistonslap.fmu import fmu_path

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
    for name in (
        "slap.png",
        "forces.png",
        "piston_motion.png",
        "piston_positions.png",
        "piston_positions.gif",
        "impact_log.csv",
    ):
        assert (out / name).stat().st_size > 1000, name
    assert not (out / "film.png").exists(), "the film plot is the lubricated skirt's (skirt_model = 2)"
