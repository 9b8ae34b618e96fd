"""slap.png and piston_motion.png as the demo draws them (issue 55): on oil no empty axes, a line saying the skirt
rode on its film, the landings' energies and each wall's load rise rate against crank angle in the walls' colours,
MAHLE's windows shaded; piston_motion.png shows film and wall loads instead of the corner contacts. Dry, the impact
panels stay below the landings. Checked on the figures' artists against the run's own files."""

import os
import pickle
import subprocess
import sys

import numpy as np
import pytest
from matplotlib.colors import to_rgba

from pistonslap.fmu import read_landing_log

RED, BLUE = to_rgba("tab:red"), to_rgba("tab:blue")
OIL = ["--set", "skirt_model=2", "--set", "skirt_grid_circumferential=6", "--set", "skirt_grid_axial=8"]


#: Runs the demo with its figures pickled beside their PNGs: in a process of its own, since the demo's checks
#: install an fmpy logger that the call-by-call tests' process-wide one (harness.py) must not lose.
DRIVER = """
import pickle, sys
from pistonslap import demo, plots
save = plots._save
def keep(fig, path, **kwargs):
    with open(f"{path}.pickle", "wb") as f:
        pickle.dump(fig, f)
    return save(fig, path, **kwargs)
plots._save = keep
demo.main(sys.argv[1:])
"""


def _draw(tmp_path, *args):
    """Runs the demo as a user does; returns its output folder and its figures by file name."""
    out = tmp_path / "out"
    command = [sys.executable, "-c", DRIVER, "--rpm", "1500", "--cycles", "1", "--out", str(out), *args]
    subprocess.run(command, check=True, capture_output=True, env=dict(os.environ, MPLBACKEND="Agg"))
    figures = {}
    for pickled in out.glob("*.png.pickle"):
        with open(pickled, "rb") as f:
            figures[pickled.name.removesuffix(".pickle")] = pickle.load(f)
    return out, figures


@pytest.fixture(scope="module")
def oil(tmp_path_factory):
    return _draw(tmp_path_factory.mktemp("oil"), *OIL)


@pytest.fixture(scope="module")
def dry(tmp_path_factory):
    return _draw(tmp_path_factory.mktemp("dry"))


def _has_data(ax):
    """Whether an axis draws data: a curve (more than the two points of a reference line) or a collection."""
    return any(len(line.get_xdata()) > 2 for line in ax.get_lines()) or any(len(c.get_paths()) for c in ax.collections)


def _colour(artist):
    return to_rgba(artist.get_color())


def _spans(ax):
    """The shaded x-ranges of an axis (axvspan rectangles), rounded to 0.1°."""
    return sorted({(round(p.get_x(), 1), round(p.get_x() + p.get_width(), 1)) for p in ax.patches})


def test_on_oil_slap_png_shows_the_landings_and_rise_rates_with_no_empty_axis(oil):
    out, figures = oil
    fig = figures["slap.png"]
    (landings, _), (rates, rates_zoom) = fig.axes[0:2], fig.axes[2:4]
    assert len(fig.axes) == 4 and all(_has_data(ax) for ax in fig.axes), "no empty axes, no impact panels"
    assert "kinetic energy" in landings.get_ylabel() and "rise" in rates.get_ylabel()
    assert landings.get_xlim() == (-360, 360) and rates_zoom.get_xlim() == (-30, 60)
    assert "no impact in this cycle: the skirt rode on its oil film" in fig.get_suptitle()
    log = read_landing_log(out / "landing_log.csv")
    # the cycle drawn: from −360° to 360° about the firing TDC at 720°, the run's second
    log = log[np.floor((1500 * np.pi / 30 * log["time"] + 2 * np.pi) / (4 * np.pi)) == 1]
    for wall, colour in (("thrust", RED), ("antithrust", BLUE)):
        mine = log[log["wall"] == wall]
        markers = [line for line in landings.get_lines() if line.get_marker() == "o" and _colour(line) == colour]
        drawn = markers[0]
        shown = (drawn.get_xdata() >= -360) & (drawn.get_xdata() <= 360)
        assert shown.sum() == len(mine) >= 1, f"the cycle's landings on the {wall} wall are drawn"
        # each drawn landing is one of the log's, at its crank angle and energy
        factor = {"[mJ]": 1e3, "[µJ]": 1e6, "[nJ]": 1e9}[landings.get_ylabel().split()[-1]]
        for x, y in zip(drawn.get_xdata(), drawn.get_ydata(), strict=True):
            k = np.argmin(np.abs(np.degrees(mine["crank_angle"]) - x))
            assert y == pytest.approx(mine["kinetic_energy"][k] * factor, rel=1e-12)
        assert any(_colour(line) == colour and len(line.get_xdata()) > 1000 for line in rates.get_lines())
    for ax in fig.axes:
        assert {(-2.0, 8.0), (8.0, 20.0)} <= set(_spans(ax)), "MAHLE's rattling and croaking windows"
    names = [t.get_text() for t in landings.get_legend().get_texts()]
    assert "rattling −2…8° (MAHLE)" in names and "croaking 8…20° (MAHLE)" in names


def test_the_rise_rate_drawn_peaks_at_the_fmus_cycle_figure(oil):
    """Both sample the wall load at the demo's communication points, 0.36° apart: the largest rise rate drawn over
    the cycle is the FMU's cycle_max_liner_force_rate_* of that cycle (summary's row, cycles.csv's last row)."""
    out, figures = oil
    rates = figures["slap.png"].axes[2]
    header = (out / "demo.csv").read_text().splitlines()[0].split(",")
    last = np.genfromtxt(out / "demo.csv", delimiter=",", skip_header=1)[-1]
    for wall, colour in (("thrust", RED), ("antithrust", BLUE)):
        line = next(line for line in rates.get_lines() if _colour(line) == colour)
        fmu = last[header.index(f"cycle_max_liner_force_rate_{wall} [N/s]")]
        assert fmu > 0
        assert np.nanmax(line.get_ydata()) == pytest.approx(fmu * 1e-6, rel=1e-6)


def test_on_oil_piston_motion_png_shows_the_film_and_wall_loads_not_corner_contacts(oil):
    _, figures = oil
    fig = figures["piston_motion.png"]
    labels = [ax.get_ylabel() for ax in fig.axes]
    assert not any("contact" in label for label in labels), labels
    assert "film" in labels[2] and "liner load" in labels[3]
    assert all(_has_data(ax) for ax in fig.axes)
    film, loads = fig.axes[2], fig.axes[3]
    assert [_colour(line) for line in film.get_lines()] == [RED, BLUE]
    assert any("asperit" in line.get_label() for line in loads.get_lines())


def test_dry_slap_png_keeps_the_impacts_below_the_landings(dry):
    _, figures = dry
    fig = figures["slap.png"]
    assert [ax.get_ylabel().split("\n")[0] for ax in fig.axes[0::2]] == [
        "lateral kinetic energy",
        "wall load rise",
        "energy dissipated",
        "impact speed [mm/s]",
    ]
    assert all(_has_data(ax) for ax in fig.axes)
    assert "no impact" not in fig.get_suptitle()
    labels = [ax.get_ylabel() for ax in figures["piston_motion.png"].axes]
    assert "contact force [kN]" in labels
