"""The lubricated skirt's film plot: the thinnest film per side in µm, the skirt friction force and power, on the
crank-angle axis of the other plots (firing TDC at 0, -360...360°); the demo draws it for skirt_model = 2 only."""

import os
import subprocess
import sys
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
import pytest

from pistonslap import plots, skirt_map

PISTONSLAP = Path(sys.executable).parent / "pistonslap"
NAMES = ("min_film_thickness_thrust", "min_film_thickness_antithrust", "skirt_friction_force", "skirt_friction_power")


def test_film_plot_draws_the_outputs_in_their_units(tmp_path, monkeypatch):
    angle = np.radians(np.linspace(-360, 360, 721))
    result = np.zeros(angle.size, dtype=[(name, float) for name in NAMES])
    result["min_film_thickness_thrust"] = 20e-6 + 5e-6 * np.cos(angle)
    result["min_film_thickness_antithrust"] = 30e-6 - 4e-6 * np.sin(angle)
    result["skirt_friction_force"] = -10 * np.sin(angle / 2)
    result["skirt_friction_power"] = 50 * np.sin(angle / 2) ** 2
    drawn = {}

    def keep(fig, path):
        drawn["fig"] = fig
        return path

    monkeypatch.setattr(plots, "_save", keep)
    assert plots.film(angle, result, tmp_path / "film.png", "a case") == tmp_path / "film.png"
    thickness, friction, power = drawn["fig"].axes
    assert power.get_xlim() == (-360, 360) and "firing TDC" in power.get_xlabel()
    (thrust, anti), force, watts = thickness.get_lines(), friction.get_lines()[0], power.get_lines()[0]
    np.testing.assert_allclose(thrust.get_xdata(), np.linspace(-360, 360, 721))
    np.testing.assert_allclose(thrust.get_ydata(), result["min_film_thickness_thrust"] * 1e6)
    np.testing.assert_allclose(anti.get_ydata(), result["min_film_thickness_antithrust"] * 1e6)
    assert "µm" in thickness.get_ylabel() and "thrust" in thrust.get_label() and "anti" in anti.get_label()
    np.testing.assert_allclose(force.get_ydata(), result["skirt_friction_force"])
    np.testing.assert_allclose(watts.get_ydata(), result["skirt_friction_power"])
    assert "[N]" in friction.get_ylabel() and "[W]" in power.get_ylabel()
    plt.close(drawn["fig"])


def test_the_demo_of_a_lubricated_engine_writes_the_film_plot_and_the_skirt_map(tmp_path):
    """One cycle on a coarse film grid: film.png is written, and the film it draws lies within the clearance; the skirt
    map asked for at -340° (380° in the FMU's 0...720° cycle) is the film of that crank angle in the cycle drawn, whose
    pressures add up to the `film_force` output there."""
    out = tmp_path / "demo"
    grid = ("--set", "skirt_model=2", "--set", "skirt_grid_circumferential=6", "--set", "skirt_grid_axial=8")
    args = [str(PISTONSLAP), "demo", *grid, "--cycles", "1", "--out", str(out), "--skirt-map", "-340"]
    env = dict(os.environ, MPLBACKEND="Agg")
    printed = subprocess.run(args, cwd=tmp_path, env=env, check=True, capture_output=True, text=True).stdout
    assert f"wrote {out / 'film.png'}" in printed
    assert (out / "film.png").stat().st_size > 1000
    header = (out / "demo.csv").read_text().splitlines()[0].split(",")
    data = np.loadtxt(out / "demo.csv", delimiter=",", skiprows=1)
    for side in ("thrust", "antithrust"):
        film = data[:, header.index(f"min_film_thickness_{side} [m]")]
        assert np.all(film > 1e-6) and np.all(film < 80e-6)
    assert f"wrote {out / 'skirt_map.png'}" in printed and (out / "skirt_map.png").stat().st_size > 1000
    drawn = skirt_map.read(out / "skirt_map.csv")
    # The first communication point at or after -340°, 0.36° apart.
    assert -340 <= drawn["crank_angle_deg"] < -340 + 0.37
    row = np.argmin(np.abs(data[:, header.index("time [s]")] - drawn["time"]))
    bore = 0.08008
    force = sum(skirt_map.film_force(drawn[side], bore) for side in ("thrust", "antithrust"))
    assert force == pytest.approx(data[row, header.index("film_force [N]")], rel=1e-9)
