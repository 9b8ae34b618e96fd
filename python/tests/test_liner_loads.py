"""`pistonslap demo --liner-loads FILE.csv`: the liner's load for a structural model, sampled uniformly in crank angle.
Its mean force per interval carries the impacts: the impulse it gives each interval is the FMU's own
`liner_impulse_*_in_step` of that interval, from an independent run at the same step, to round-off. Bad options are
one line and exit status 2."""

import csv
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from pistonslap import liner_load
from pistonslap.fmu import simulate

PISTONSLAP = Path(sys.executable).parent / "pistonslap"
OMEGA = 1500 * np.pi / 30  # rad/s
WALLS = ("thrust", "antithrust")


def _demo(tmp_path, *args, check=True):
    env = dict(os.environ, MPLBACKEND="Agg")
    command = [str(PISTONSLAP), "demo", "--rpm", "1500", "--cycles", "1", "--out", str(tmp_path / "out"), *args]
    return subprocess.run(command, cwd=tmp_path, env=env, check=check, capture_output=True, text=True)


def _read(path):
    with open(path, newline="") as f:
        header = next(csv.reader(f))
    data = np.genfromtxt(path, delimiter=",", skip_header=1)
    return header, {name.split(" [")[0]: data[:, k] for k, name in enumerate(header)}


@pytest.fixture(scope="module")
def dry(tmp_path_factory):
    """One cycle of the default engine at 1500 rpm (impacts on both walls), liner loads every 0.5°."""
    tmp = tmp_path_factory.mktemp("dry")
    done = _demo(tmp, "--liner-loads", "loads/liner.csv", "--liner-load-step", "0.5", "--liner-load-spectrum")
    return tmp, done.stdout


def test_the_header_names_every_column_with_its_unit(dry):
    tmp, printed = dry
    assert f"wrote {Path('loads/liner.csv')}" in printed
    header, _ = _read(tmp / "loads" / "liner.csv")
    expected = ["time [s]", "cycle [1]", "crank_angle [deg]"]
    for wall in WALLS:
        expected += [
            f"liner_force_{wall} [N]",
            f"liner_force_mean_{wall} [N]",
            f"liner_force_height_{wall} [m]",
            f"liner_moment_{wall} [N.m]",
        ]
    assert header == expected


def test_samples_are_uniform_in_crank_angle_over_the_cycle_drawn(dry):
    """1440 samples at 0.5° over the cycle from −360° to 360° about the first firing TDC after the start, each at the
    end of its interval; the time between them is 0.5° at 1500 rpm."""
    tmp, _ = dry
    _, table = _read(tmp / "loads" / "liner.csv")
    assert len(table["time"]) == 1440 and set(table["cycle"]) == {1}
    np.testing.assert_allclose(table["crank_angle"], np.arange(1, 1441) * 0.5 - 360, atol=1e-9)
    np.testing.assert_allclose(np.diff(table["time"]), np.radians(0.5) / OMEGA, rtol=1e-9)


def test_the_mean_force_gives_the_fmus_impulse_of_every_interval(dry):
    """The file's mean force times its interval is `liner_impulse_*_in_step` of a run of the FMU at the same
    communication step, sample for sample, to round-off; the impulses include the impacts (so their sum exceeds the
    integral of the instantaneous force, which holds the contact forces only)."""
    tmp, _ = dry
    _, table = _read(tmp / "loads" / "liner.csv")
    step = np.radians(0.5) / OMEGA
    run = simulate(
        stop_time=table["time"][-1] + step / 2,
        output_interval=step,
        start_values={"crank_speed": OMEGA},
        output=[f"liner_impulse_{wall}_in_step" for wall in WALLS] + [f"liner_force_{wall}" for wall in WALLS],
    )
    rows = np.searchsorted(run["time"], table["time"] - step / 4)
    np.testing.assert_allclose(run["time"][rows], table["time"], rtol=1e-12)
    width = np.diff(np.concatenate([[table["time"][0] - step], table["time"]]))
    for wall in WALLS:
        impulse = run[f"liner_impulse_{wall}_in_step"][rows]
        assert impulse.sum() > 0.1, f"the {wall} wall is loaded in the cycle"
        np.testing.assert_allclose(table[f"liner_force_mean_{wall}"] * width, impulse, rtol=1e-12, atol=1e-15)
        np.testing.assert_allclose(table[f"liner_force_{wall}"], run[f"liner_force_{wall}"][rows], rtol=1e-12)
    trapezoid = sum(np.sum(table[f"liner_force_{w}"]) * step for w in WALLS)
    total = sum(np.sum(table[f"liner_force_mean_{w}"]) * step for w in WALLS)
    assert total > trapezoid * 1.001, "the impacts' impulses are in the mean force, not in the instantaneous one"


def test_the_point_of_application_lies_on_the_skirt_and_is_the_moment_over_the_force(dry):
    """Where a wall is loaded its load acts between the skirt top and bottom (the default 80 mm skirt), and the height
    times the force is the moment; where it is not, the height is empty (nan)."""
    tmp, _ = dry
    _, table = _read(tmp / "loads" / "liner.csv")
    for wall in WALLS:
        force, height = table[f"liner_force_{wall}"], table[f"liner_force_height_{wall}"]
        loaded = force > 0
        assert loaded.any() and (~loaded).any()
        assert np.all(height[loaded] >= -1e-12) and np.all(height[loaded] <= 0.08 + 1e-12)
        np.testing.assert_allclose(height[loaded] * force[loaded], table[f"liner_moment_{wall}"][loaded], rtol=1e-12)
        assert np.all(np.isnan(height[~loaded]))


def test_the_spectrum_plot_is_written_beside_the_file(dry):
    tmp, printed = dry
    assert (tmp / "loads" / "liner_spectrum.png").stat().st_size > 10000
    assert f"wrote {Path('loads/liner_spectrum.png')}" in printed


def test_a_sine_load_has_one_order_line_and_fills_its_third_octave_band():
    """A force of 1 kN + 300 N sin(order 3) over two cycles at 1500 rpm (order 3 = 75 Hz): its order spectrum holds
    300/√2 = 212.1 N at order 3 alone (46.53 dB re 1 N), the mean left out; the 80 Hz band (70.8…89.1 Hz) holds it."""
    per_cycle = 1440
    crank = np.arange(1, 2 * per_cycle + 1) * np.radians(0.5)
    table = np.zeros(len(crank), dtype=[(name, "f8") for name in liner_load.columns()])
    table["cycle"] = np.repeat([1, 2], per_cycle)
    table["liner_force_mean_thrust"] = 1000 + 300 * np.sin(3 * crank)
    orders, frequencies, rms = liner_load.order_spectrum(table, OMEGA)
    assert orders[0] == 0.25 and frequencies[orders == 3] == pytest.approx(75.0)
    peak = int(np.argmax(rms["thrust"]))
    assert orders[peak] == 3 and rms["thrust"][peak] == pytest.approx(300 / np.sqrt(2), rel=1e-9)
    assert np.delete(rms["thrust"], peak).max() < 1e-9 and not rms["antithrust"].any()
    assert liner_load.decibels(rms["thrust"][peak]) == pytest.approx(46.53, abs=0.01)
    centres, bands = liner_load.third_octaves(frequencies, rms)
    assert bands["thrust"][list(centres).index(80)] == pytest.approx(300 / np.sqrt(2), rel=1e-9)
    assert np.delete(bands["thrust"], list(centres).index(80)).max() < 1e-9


@pytest.mark.parametrize(
    "args, message",
    [
        (["--liner-loads", "x.csv", "--liner-load-step", "0.7"], "--liner-load-step = 0.7°: give a step that divides"),
        (["--liner-loads", "x.csv", "--liner-load-step", "0"], "--liner-load-step = 0°: give a step > 0"),
        (["--liner-loads", "x.csv", "--liner-load-step", "nan"], "--liner-load-step = nan°"),
        (["--liner-load-step", "0.5"], "go with --liner-loads FILE.csv"),
        (["--liner-load-spectrum"], "go with --liner-loads FILE.csv"),
        (["--liner-loads", "x.txt"], "give a .csv file name"),
        (["--liner-loads", "x.csv", "--set", "crank_mode=2"], "needs the prescribed crank speed"),
    ],
)
def test_bad_liner_load_options_are_one_line_and_status_2(tmp_path, args, message):
    done = _demo(tmp_path, *args, check=False)
    assert done.returncode == 2 and message in done.stderr, done.stderr
    assert len(done.stderr.strip().splitlines()) == 1 and "Traceback" not in done.stderr
    assert not (tmp_path / "out").exists(), "refused before anything is written"
