"""Plots of one engine cycle against crank angle, in the style of Awrejcewicz & Kudra (2005) Figs 5-10, and the
successive piston positions in the bore of their Fig. 7.

Every function takes the samples of one cycle (`angle` = crank angle from firing TDC, rad, over one cycle from
`origin`: -2π for the -360...360° axis engine people read, 0 for 0...720°), a `case` title naming the operating
point, and writes a PNG (the piston positions also an animated GIF). Sides follow the FMU's
conventions: +x (corners K3, K4) is the major-thrust wall, the one the piston presses on in the power stroke;
-x (K1, K2) the anti-thrust wall.
"""

import textwrap

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.animation import FuncAnimation, PillowWriter
from matplotlib.patches import Polygon

from .fmu import CENTRED, from_firing_tdc
from .liner_load import decibels, order_spectrum, third_octaves
from .tables import WALLS, energy_unit

CORNERS = (1, 2, 3, 4)
#: (label, corners, colour) of the two walls.
SIDES = (("major thrust (+x: K3, K4)", (3, 4), "tab:red"), ("anti-thrust (−x: K1, K2)", (1, 2), "tab:blue"))


def _axes(rows, title, case, origin):
    fig, axes = plt.subplots(rows, 1, sharex=True, figsize=(9, 2.2 * rows + 1.0), squeeze=False)
    axes = axes[:, 0]
    fig.suptitle(f"{title}\n{case}", fontsize="medium")
    start = np.degrees(origin)
    axes[-1].set_xlabel("crank angle [deg]  (0 = firing TDC)")
    axes[-1].set_xlim(start, start + 720)
    axes[-1].set_xticks(np.arange(start, start + 721, 90))
    for ax in axes:
        ax.grid(True, alpha=0.3)
    return fig, axes


#: The crank-angle window of the zoom beside the slap plot's panels, deg from firing TDC: MAHLE's windows and the
#: power stroke's landing.
ZOOM = (-30.0, 60.0)


def _axes_with_zoom(rows, title, case, origin):
    """`rows` panels over the cycle, each with a zoom on `ZOOM` beside it sharing its scale: `(fig, [(cycle axis,
    zoom axis), ...])`; the zooms' axis runs from −360° to 360° whatever `origin`."""
    height = 2.6 * rows + 1.9
    # laid out by hand: room above each panel for its legend, above the first for the title's three lines too
    fig, axes = plt.subplots(
        rows,
        2,
        sharex="col",
        sharey="row",
        figsize=(12, height),
        squeeze=False,
        gridspec_kw=dict(
            width_ratios=(3, 1), left=0.08, right=0.985, top=1 - 1.45 / height, bottom=0.55 / height, hspace=0.42
        ),
    )
    fig.suptitle(f"{title}\n{case}", fontsize="medium")
    start = np.degrees(origin)
    axes[-1, 0].set_xlabel("crank angle [deg]  (0 = firing TDC)")
    axes[-1, 0].set_xlim(start, start + 720)
    axes[-1, 0].set_xticks(np.arange(start, start + 721, 90))
    axes[-1, 1].set_xlabel(f"zoom {ZOOM[0]:g}…{ZOOM[1]:g} [deg]".replace("-", "−"))
    axes[-1, 1].set_xlim(*ZOOM)
    axes[-1, 1].set_xticks(np.arange(ZOOM[0], ZOOM[1] + 1, 15))
    for ax in axes.flat:
        ax.grid(True, alpha=0.3)
    return fig, [tuple(pair) for pair in axes]


def _broken_at_wraps(deg, values):
    """`deg` and `values` with a NaN where the crank angle wraps, so that a line does not cross the axis there."""
    wraps = np.flatnonzero(np.diff(deg) < 0) + 1
    return np.insert(deg.astype(float), wraps, np.nan), np.insert(values.astype(float), wraps, np.nan)


def _legend(ax, ncol=4, **kwargs):
    ax.legend(loc="lower right", bbox_to_anchor=(1, 1), ncol=ncol, fontsize="small", frameon=False, **kwargs)


def _count(n, word):
    """`n` and the word, plural unless one."""
    return f"{n} {word}{'' if n == 1 else 's'}"


def _save(fig, path, tight=True):
    """Writes the figure (laid out tight unless laid out by hand) and closes it."""
    if tight:
        fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def piston_motion(angle, result, half_clearance, path, case, origin=CENTRED, lubricated=False):
    """Eccentricity of the skirt top and bottom and of the pin, tilt, then for the dry skirt the contact states (a bar
    per corner while in sliding contact) and contact force per corner, for the lubricated one (`lubricated`) the
    thinnest film per side and each wall's load (film, asperities and any corner in contact) with the asperity load."""
    deg = np.degrees(angle)
    fig, (lateral, tilt, states, forces) = _axes(4, "Piston secondary motion over one engine cycle", case, origin)
    for name, label, style in (
        ("skirt_top_lateral", "skirt top (K1/K3 level)", "-"),
        ("skirt_bottom_lateral", "skirt bottom (K2/K4 level)", "-"),
        ("piston_lateral", "pin", ":"),
    ):
        lateral.plot(deg, result[name] * 1e6, style, label=label)
    # the walls' names beyond the walls, where no curve can run
    wall = half_clearance * 1e6
    lateral.set_ylim(-1.4 * wall, 1.4 * wall)
    for sign, (label, _, colour) in zip((1, -1), SIDES, strict=True):
        lateral.axhline(sign * wall, color=colour, lw=0.8, ls="--")
        lateral.annotate(
            label.split(" (")[0] + " wall",
            (np.degrees(origin) + 5, sign * wall),
            xytext=(0, 2 * sign),
            textcoords="offset points",
            color=colour,
            fontsize="x-small",
            va="bottom" if sign > 0 else "top",
        )
    lateral.set_ylabel("eccentricity x [µm]\n(+ toward major thrust)")
    _legend(lateral, ncol=3)
    tilt.plot(deg, result["piston_tilt"] * 1e3)
    tilt.set_ylabel("tilt [mrad]\n(+ counterclockwise)")
    if lubricated:
        _film_and_wall_loads(states, forces, deg, result)
    else:
        _corner_contacts(states, forces, deg, result)
    return _save(fig, path)


def _corner_contacts(states, forces, deg, result):
    """A bar per corner while in sliding contact, and each corner's contact force."""
    for corner in CORNERS:
        in_contact = result[f"contact_state_{corner}"] > 0
        states.fill_between(deg, corner - 0.35, corner + 0.35, where=in_contact, step="post", label=f"K{corner}")
        forces.plot(deg, result[f"contact_force_{corner}"] * 1e-3, ls="-" if corner % 2 else "--", label=f"K{corner}")
    states.set_yticks(CORNERS, [f"K{c}" for c in CORNERS])
    states.set_ylim(0.4, 4.6)
    states.set_ylabel("sliding contact")
    forces.set_ylabel("contact force [kN]")
    _legend(forces)


def _film_and_wall_loads(film, loads, deg, result):
    """The thinnest film on each side, and each wall's normal load (film, asperities and corners) with the asperity
    load (per side where the FMU gives it, else both sides together)."""
    for side, (label, _, colour) in zip(WALLS, SIDES, strict=True):
        name = label.split(" (")[0]
        film.plot(deg, result[f"min_film_thickness_{side}"] * 1e6, color=colour, label=name)
        loads.plot(deg, result[f"liner_force_{side}"] * 1e-3, color=colour, label=f"{name} wall load")
        if f"asperity_force_{side}" in result.dtype.names:
            loads.plot(deg, result[f"asperity_force_{side}"] * 1e-3, color=colour, ls="--", label=f"{name} asperities")
    if "asperity_force_thrust" not in result.dtype.names:
        loads.plot(deg, result["asperity_force"] * 1e-3, color="k", ls="--", lw=0.8, label="asperities (both sides)")
    film.set_ylim(bottom=0)
    film.set_ylabel("minimum film\nthickness [µm]")
    _legend(film, ncol=2)
    loads.set_ylabel("liner load [kN]")
    _legend(loads, ncol=3)


#: MAHLE's crank-angle windows of the liner's acceleration (deg from firing TDC): (name, start, end).
MAHLE_WINDOWS = (("rattling", -2.0, 8.0), ("croaking", 8.0, 20.0))
_WINDOW_COLOURS = ("0.75", "0.88")


def slap(
    events,
    is_slap,
    slap_threshold,
    path,
    case,
    origin=CENTRED,
    landings=None,
    loads=None,
    lubricated=False,
):
    """One cycle's landings and impacts against the crank angle, by wall, on linear scales.

    With `landings` (rows of the landing log in the cycle): the piston's lateral kinetic energy at each landing's
    start (filled, on stems) and the energy the landing took from it (hollow). With `loads` (`(angle, result)`, the
    cycle's samples): each wall's load rise rate between samples. Then, when the cycle had impacts: the energy each
    impact's normal (restitution) part dissipated, and its normal approach speed with the slap threshold drawn; slaps
    (`is_slap`: the landings on the other wall, `slap_rows`) filled on stems, the other impacts hollow. Without
    impacts a line says so (on oil, `lubricated`: that the skirt rode on its film). MAHLE's rattling and croaking
    windows are shaded."""
    impacts = events["kind"] == "impact"
    panels = (["landings"] if landings is not None else []) + (["rate"] if loads is not None else [])
    panels += ["impact energy", "impact speed"] if impacts.any() or not panels else []
    title = "Piston slap: landings and impacts over one engine cycle"
    if not impacts.any():
        case += "\nno impact in this cycle: " + (
            "the skirt rode on its oil film" if lubricated else "the piston slid along the liner"
        )
    fig, pairs = _axes_with_zoom(len(panels), title, case, origin)
    draw = {
        "landings": lambda ax, frame: _landings(ax, landings, frame),
        "rate": lambda ax, frame: _force_rates(ax, *loads, frame),
        "impact energy": lambda ax, frame: _impacts(ax, "energy", events, is_slap, slap_threshold, frame),
        "impact speed": lambda ax, frame: _impacts(ax, "speed", events, is_slap, slap_threshold, frame),
    }
    for panel, (cycle_ax, zoom) in zip(panels, pairs, strict=True):
        for ax, frame in ((cycle_ax, origin), (zoom, CENTRED)):
            _mahle_windows(ax, frame, legend=ax is pairs[0][0])
            draw[panel](ax, frame)
            _zero_near_bottom(ax)
        if zoom.get_legend():
            zoom.get_legend().remove()
        zoom.set_ylabel("")
    if "impact energy" in panels:
        # one legend for both impact panels, above the first
        energy, speed = (pairs[panels.index(name)][0] for name in ("impact energy", "impact speed"))
        speed.get_legend().remove()
        handles, labels = energy.get_legend_handles_labels()
        threshold = next(line for line in speed.get_lines() if line.get_label().startswith("slap threshold"))
        _legend(energy, ncol=3, handles=[*handles, threshold], labels=[*labels, threshold.get_label()])
    # the legend above the first panel names the windows; the zoom shows them wide enough to name them there too
    for name, low, high in MAHLE_WINDOWS:
        pairs[0][1].annotate(
            name,
            ((low + high) / 2, 1),
            xycoords=("data", "axes fraction"),
            xytext=(0, 2),
            textcoords="offset points",
            rotation=90,
            ha="center",
            va="bottom",
            fontsize="x-small",
        )
    return _save(fig, path, tight=False)


def _zero_near_bottom(ax):
    """The zero line a little above the bottom, so that values next to nothing stay visible."""
    top = max(ax.get_ylim()[1], 1e-9)
    ax.set_ylim(-0.04 * top, top)
    ax.axhline(0, color="0.6", lw=0.5, zorder=1)


def _landings(ax, landings, origin):
    """Per wall, each landing's lateral kinetic energy at its start (filled, on a stem) and the energy it took."""
    deg = np.degrees(from_firing_tdc(landings["crank_angle"], origin))
    factor, unit = energy_unit(max(landings["kinetic_energy"].max(initial=0), landings["energy_loss"].max(initial=0)))
    for side, (label, _, colour) in zip(WALLS, SIDES, strict=True):
        mine = landings["wall"] == side
        name = label.split(" (")[0]
        energy, loss = landings["kinetic_energy"][mine] * factor, landings["energy_loss"][mine] * factor
        ax.vlines(deg[mine], 0, energy, color=colour, lw=1)
        ax.plot(
            deg[mine],
            energy,
            "o",
            color=colour,
            ms=5,
            zorder=4,
            label=f"{name}: {_count(mine.sum(), 'landing')}, energy",
        )
        ax.plot(deg[mine], loss, "D", mfc="none", color=colour, ms=5, mew=1, zorder=4, label=f"{name}: energy taken")
    if not len(landings):
        ax.text(0.5, 0.5, "no landing in this cycle", transform=ax.transAxes, ha="center", va="center")
    ax.set_ylabel(f"lateral kinetic energy\nat landing [{unit}]")
    _legend(ax, ncol=3)


def _force_rates(ax, angle, result, origin):
    """Per wall, the rise rate of its load between consecutive samples (falls not drawn), at the later sample."""
    deg = np.degrees(from_firing_tdc(angle, origin))
    time = result["time"]
    for side, (label, _, colour) in zip(WALLS, SIDES, strict=True):
        rate = np.maximum(np.diff(result[f"liner_force_{side}"]) / np.diff(time), 0) * 1e-6
        ax.plot(*_broken_at_wraps(deg[1:], rate), color=colour, lw=0.9, label=label.split(" (")[0])
    ax.set_ylabel("wall load rise\nrate [kN/ms]")
    _legend(ax, ncol=2)


def _impacts(ax, what, events, is_slap, slap_threshold, origin):
    """Every impact's dissipated `energy` or approach `speed` by wall, slaps filled on stems; with the speeds, the
    slap threshold."""
    impacts = events["kind"] == "impact"
    deg = np.degrees(from_firing_tdc(events["crank_angle"], origin))
    values = events["energy_lost"] * 1e3 if what == "energy" else events["normal_velocity_before"] * 1e3
    for label, corners, colour in SIDES:
        mine = impacts & np.isin(events["corner"], corners)
        slaps, others, name = mine & is_slap, mine & ~is_slap, label.split(" (")[0]
        ax.vlines(deg[slaps], 0, values[slaps], color=colour, lw=1)
        ax.plot(
            deg[slaps], values[slaps], "o", color=colour, ms=5, zorder=4, label=f"{name}: {_count(slaps.sum(), 'slap')}"
        )
        ax.plot(
            deg[others],
            values[others],
            "o",
            mfc="none",
            color=colour,
            ms=3,
            mew=0.8,
            zorder=3,
            clip_on=False,
            label=f"{name}: {_count(others.sum(), 'other impact')}",
        )
    if what == "energy":
        ax.set_ylabel("energy dissipated\nper impact [mJ]")
        return
    # named in the legend: a label on the line would sit among the bounces that follow each slap
    ax.axhline(slap_threshold * 1e3, color="k", lw=0.8, ls="--", label=f"slap threshold {slap_threshold * 1e3:g} mm/s")
    ax.set_ylabel("impact speed [mm/s]")
    _legend(ax, ncol=2)


def _mahle_windows(ax, origin, legend=False):
    """MAHLE's windows shaded (on a 0…720° axis the part before firing TDC at its end), named in the legend when
    `legend`."""
    start = np.degrees(origin)
    for (name, low, high), colour in zip(MAHLE_WINDOWS, _WINDOW_COLOURS, strict=True):
        label = f"{name} {low:g}…{high:g}° (MAHLE)".replace("-", "−") if legend else "_window"
        for shift in (0.0, 720.0):
            lo, hi = max(low + shift, start), min(high + shift, start + 720)
            if lo < hi:
                ax.axvspan(lo, hi, color=colour, lw=0, zorder=0, label=label)
                label = "_window"


def _zero_at_same_height(*axes):
    """Lowers the bottoms of twin y-axes so that their zeros lie at the same height, each still showing its data."""
    limits = [(min(lo, 0.0), max(hi, 0.0)) for lo, hi in (ax.get_ylim() for ax in axes)]
    # the largest fraction of the height below zero, given to every axis
    below = max(-lo / (hi - lo) for lo, hi in limits)
    if below < 1:
        for ax, (lo, hi) in zip(axes, limits, strict=True):
            ax.set_ylim(min(lo, -below * hi / (1 - below)), hi)


def forces(angle, result, path, case, origin=CENTRED):
    """The gas pressure that acted with the net side force of the liner on the piston (zeros level), and the engine
    torque."""
    deg = np.degrees(angle)
    fig, (side, torque) = _axes(2, "Side force, gas pressure and engine torque over one engine cycle", case, origin)
    side.plot(deg, result["side_force"] * 1e-3, color="tab:purple", label="net side force (liner on piston)")
    side.set_ylabel("side force [kN]\n(− from major thrust)")
    pressure = side.twinx()
    pressure.plot(deg, result["gas_pressure_acting"] * 1e-5, color="tab:gray", lw=0.8, label="gas pressure (gauge)")
    pressure.set_ylabel("gas pressure [bar]")
    _zero_at_same_height(side, pressure)
    side.axhline(0, color="k", lw=0.5, label="_zero")
    lines = [line for line in side.get_lines() + pressure.get_lines() if not line.get_label().startswith("_")]
    side.legend(
        lines,
        [line.get_label() for line in lines],
        loc="lower right",
        bbox_to_anchor=(1, 1),
        ncol=2,
        fontsize="small",
        frameon=False,
    )
    torque.plot(deg, result["engine_torque"])
    torque.set_ylabel("engine torque [N·m]\n(+ along rotation)")
    return _save(fig, path)


def film(angle, result, path, case, origin=CENTRED):
    """The lubricated skirt (skirt_model = 2): the thinnest oil film on each side (µm), the skirt's axial friction
    force (N, + away from the crank) and the power it takes from the piston's motion (W)."""
    deg = np.degrees(angle)
    fig, (thickness, friction, power) = _axes(3, "Oil film and skirt friction over one engine cycle", case, origin)
    for side, (label, _, colour) in zip(("thrust", "antithrust"), SIDES, strict=True):
        thickness.plot(deg, result[f"min_film_thickness_{side}"] * 1e6, color=colour, label=label.split(" (")[0])
    thickness.set_ylabel("minimum film\nthickness [µm]")
    thickness.set_ylim(bottom=0)
    _legend(thickness, ncol=2)
    friction.plot(deg, result["skirt_friction_force"], color="tab:green")
    friction.axhline(0, color="k", lw=0.5)
    friction.set_ylabel("skirt friction force [N]\n(+ away from the crank)")
    power.plot(deg, result["skirt_friction_power"], color="tab:olive")
    power.set_ylabel("skirt friction\npower [W]")
    return _save(fig, path)


def _outline(top, bottom, pin_height, skirt, diameter, magnification):
    """Corners K1, K3, K4, K2 of the drawn piston in mm: the axis at the top and bottom corner levels displaced by
    `magnification` times the skirt's lateral positions (m), heights from the pin."""
    x_top, x_bottom = magnification * top * 1e3, magnification * bottom * 1e3
    r, z_top, z_bottom = diameter * 500, pin_height * 1e3, (pin_height - skirt) * 1e3
    return np.array([(x_top - r, z_top), (x_top + r, z_top), (x_bottom + r, z_bottom), (x_bottom - r, z_bottom)])


#: Index in `_outline`'s corners of each corner K1..K4.
_OUTLINE_INDEX = {1: 0, 3: 1, 4: 2, 2: 3}


def _draw_piston(ax, frame, geometry, magnification):
    """One piston position: liner walls, the piston outline, and the corners in sliding contact (filled) or
    hitting in this interval (ring)."""
    bore, diameter, skirt, pin_height = geometry
    wall = diameter * 500 + magnification * (bore - diameter) * 500
    corners = _outline(frame["top"], frame["bottom"], pin_height, skirt, diameter, magnification)
    ax.add_patch(Polygon(corners, closed=True, fc="0.85", ec="k", lw=0.8))
    for x, colour in ((wall, SIDES[0][2]), (-wall, SIDES[1][2])):
        ax.axvline(x, color=colour, lw=1.5)
    for corner in frame["sliding"]:
        ax.plot(*corners[_OUTLINE_INDEX[corner]], "o", color="k", ms=5)
    for corner in frame["hit"]:
        ax.plot(*corners[_OUTLINE_INDEX[corner]], "o", mfc="none", mec="tab:orange", ms=9, mew=1.5)
    ax.plot(0, 0, "+", color="0.4", ms=4)
    ax.set_xlim(-1.15 * wall, 1.15 * wall)
    ax.set_ylim((pin_height - skirt) * 1e3 - 8, pin_height * 1e3 + 8)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    ax.set_title(f"{frame['deg']:.0f}°", fontsize="small", pad=2)


def position_frames(angle, result, events, every_deg, origin=CENTRED):
    """The piston at every `every_deg` of crank angle in the cycle: skirt positions, corners in sliding contact,
    and corners that hit since the previous frame."""
    deg = np.degrees(angle)
    impacts = events[events["kind"] == "impact"]
    hit = np.degrees(from_firing_tdc(impacts["crank_angle"], origin))
    frames = []
    for target in np.arange(np.degrees(origin), np.degrees(origin) + 720, every_deg):
        k = int(np.argmin(np.abs(deg - target)))
        recent = (hit > target - every_deg) & (hit <= target)
        frames.append(
            {
                "deg": target,
                "top": result["skirt_top_lateral"][k],
                "bottom": result["skirt_bottom_lateral"][k],
                "sliding": [c for c in CORNERS if result[f"contact_state_{c}"][k] > 0],
                "hit": sorted(set(impacts["corner"][recent].tolist())),
            }
        )
    return frames


def _positions_caption(magnification):
    return (
        f"clearance and tilt magnified {magnification:g}×; red: major-thrust wall (+x), blue: anti-thrust wall; "
        "● corner sliding on the liner, ○ corner hit since the previous frame; + piston pin"
    )


def piston_positions(angle, result, events, geometry, magnification, path, case, every_deg=30, origin=CENTRED):
    """Awrejcewicz & Kudra Fig. 7: successive positions of the piston in the bore over one cycle, one small panel
    every `every_deg` degrees. `geometry` = (bore, piston_diameter, skirt_length, pin_height), m."""
    frames = position_frames(angle, result, events, every_deg, origin)
    columns = 8
    rows = -(-len(frames) // columns)
    fig, axes = plt.subplots(rows, columns, figsize=(1.5 * columns, 1.45 * rows + 1.1), squeeze=False)
    for ax, frame in zip(axes.flat, frames, strict=False):
        _draw_piston(ax, frame, geometry, magnification)
    for ax in axes.flat[len(frames) :]:
        ax.set_visible(False)
    fig.suptitle(
        f"Successive piston positions in the bore over one engine cycle (0° = firing TDC)\n{case}", fontsize="medium"
    )
    fig.text(0.5, 0.01, _positions_caption(magnification), ha="center", fontsize="small")
    # laid out by hand: a tight layout of the many small panels costs a drawing of its own
    fig.subplots_adjust(left=0.01, right=0.99, bottom=0.05, top=1 - 0.9 / fig.get_figheight(), wspace=0.05, hspace=0.2)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def piston_animation(angle, result, events, geometry, magnification, path, case, every_deg=5, origin=CENTRED):
    """The positions of `piston_positions` as an animated GIF, one frame every `every_deg` degrees: the first frame
    drawn as a panel, the later ones moving its outline and corner marks."""
    frames = position_frames(angle, result, events, every_deg, origin)
    _, diameter, skirt, pin_height = geometry
    fig, ax = plt.subplots(figsize=(4, 5))
    _draw_piston(ax, frames[0], geometry, magnification)
    outline = ax.patches[0]
    sliding = ax.plot([], [], "o", color="k", ms=5)[0]
    hit = ax.plot([], [], "o", mfc="none", mec="tab:orange", ms=9, mew=1.5)[0]

    def draw(frame):
        corners = _outline(frame["top"], frame["bottom"], pin_height, skirt, diameter, magnification)
        outline.set_xy(corners)
        for marks, which in ((sliding, frame["sliding"]), (hit, frame["hit"])):
            at = corners[[_OUTLINE_INDEX[c] for c in which]] if which else np.empty((0, 2))
            marks.set_data(at[:, 0], at[:, 1])
        ax.set_title(f"crank angle {frame['deg']:.0f}° (0° = firing TDC)", fontsize="small")

    for line in ax.lines[:]:
        # the first frame's own corner marks give way to the marks each frame moves
        if line not in (sliding, hit) and line.get_marker() == "o":
            line.remove()
    title = fig.suptitle(textwrap.fill(case, 70), fontsize="x-small")
    caption = fig.text(
        0.5, 0.01, _positions_caption(magnification).replace("; ", "\n"), ha="center", fontsize="x-small"
    )
    fig.subplots_adjust(bottom=0.18)
    # the title and caption, the same in every frame, drawn once into a background image: text is most of a frame
    ax.set_title("")
    fig.canvas.draw()
    fig.figimage(np.asarray(fig.canvas.buffer_rgba()).copy(), zorder=-1, origin="upper")
    title.set_visible(False)
    caption.set_visible(False)
    FuncAnimation(fig, draw, frames=frames).save(path, writer=PillowWriter(fps=12))
    plt.close(fig)
    return path


def liner_load_spectrum(table, speed, path, case):
    """The spectrum of each wall's mean load (rows of `liner_load.liner_loads`, whole cycles at the prescribed crank
    speed `speed`, rad/s) as NVH tools draw it, a column per wall on common scales: the order spectrum (RMS per
    harmonic, dB re 1 N, on a logarithmic order axis) above the third-octave band levels (bars at the nominal band
    centres)."""
    orders, frequencies, rms = order_spectrum(table, speed)
    centres, bands = third_octaves(frequencies, rms)
    fig, axes = plt.subplots(2, 2, figsize=(12, 7.5), sharey="row")
    cycles = round(table["cycle"].max() - table["cycle"].min() + 1)
    fig.suptitle(
        f"Liner load spectrum: each wall's mean normal force over {720 * cycles / len(table):g}° intervals, "
        f"{cycles} cycle{'s' if cycles > 1 else ''} (order 1 = {speed / (2 * np.pi):.4g} Hz)\n{case}",
        fontsize="medium",
    )
    levels = {wall: decibels(rms[wall]) for wall in WALLS}
    top = max(np.max(levels[wall][np.isfinite(levels[wall])]) for wall in WALLS)
    floor = top - 100
    for column, (side, (label, _, colour)) in enumerate(zip(WALLS, SIDES, strict=True)):
        order_ax, band_ax = axes[0, column], axes[1, column]
        order_ax.vlines(orders, floor, np.maximum(levels[side], floor), color=colour, lw=0.6)
        order_ax.set_xscale("log")
        order_ax.set_xlim(orders[0] / 1.2, orders[-1] * 1.2)
        order_ax.set_ylim(floor, top + 5)
        order_ax.set_xlabel("engine order (multiple of the crank speed; 0.5 = once a cycle)")
        order_ax.set_title(f"{label.split(' (')[0]} wall", fontsize="medium", color=colour)
        order_ax.grid(True, which="both", alpha=0.3)
        band_levels = decibels(bands[side])
        positions = np.arange(len(centres))
        band_ax.bar(positions, np.maximum(band_levels, floor) - floor, bottom=floor, width=0.8, color=colour)
        band_ax.set_xticks(positions, [f"{c / 1000:g}k" if c >= 1000 else f"{c:g}" for c in centres], rotation=90)
        band_ax.set_xlabel("third-octave band, nominal centre frequency [Hz]")
        band_ax.set_ylim(floor, top + 10)
        band_ax.grid(True, axis="y", alpha=0.3)
    axes[0, 0].set_ylabel("order RMS [dB re 1 N]")
    axes[1, 0].set_ylabel("band RMS [dB re 1 N]")
    return _save(fig, path)
