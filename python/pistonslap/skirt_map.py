"""The lubricated skirt's film at one crank angle (the FMU's `skirt_map` CSV): reading it and drawing its pressure map.

The map holds both skirt sides unwrapped, each on its closed grid: the angle around the bore from the major-thrust
axis (+x) and the distance below the skirt's top edge. The plot draws each side as an engineer looks at the skirt
from outside, top edge up: film pressure in colour (MPa), film thickness in contour lines (µm).
"""

import csv

import numpy as np

#: Sides in the order of the plot, with their titles.
SIDES = (("thrust", "major-thrust side (+x)"), ("antithrust", "anti-thrust side (−x)"))


def read(path):
    """The map as {side: fields}, each field a 2-D array (axial rows from the top, circumferential columns), with the
    communication point's `time` (s) and `crank_angle_deg` (from firing TDC)."""
    with open(path, newline="") as file:
        rows = list(csv.DictReader(line for line in file if not line.startswith("#")))
    if not rows:
        raise ValueError(f"{path}: no map was written (the run did not pass skirt_map_crank_angle)")
    out = {"time": float(rows[0]["time"]), "crank_angle_deg": float(rows[0]["crank_angle_deg"])}
    for side, _ in SIDES:
        mine = [r for r in rows if r["side"] == side]
        angles = sorted({float(r["angle_deg"]) for r in mine})
        shape = (len(mine) // len(angles), len(angles))
        out[side] = {
            name: np.array([float(r[name]) for r in mine]).reshape(shape)
            for name in ("angle_deg", "position", "film_pressure", "asperity_pressure", "film_thickness")
        }
    return out


def film_force(side_map, bore):
    """The film's lateral force on the piston (N, + toward +x) from one side's pressures: Σ p (−cos θ) ΔA over the
    grid, whose edge pressures are zero, as the FMU's `film_force` sums it."""
    theta = np.radians(side_map["angle_deg"][0])
    position = side_map["position"][:, 0]
    area = (theta[1] - theta[0]) * bore / 2 * (position[1] - position[0])
    return float(np.sum(side_map["film_pressure"] * -np.cos(theta)[None, :]) * area)


def plot(skirt_map, path, case):
    """Both sides' film pressure (colour, MPa, one scale) and film thickness (contours, µm) against the angle around
    the bore and the distance below the skirt's top edge; writes `path`."""
    import matplotlib.pyplot as plt

    top = max(float(skirt_map[side]["film_pressure"].max()) for side, _ in SIDES) * 1e-6 or 1.0
    fig, axes = plt.subplots(1, 2, figsize=(11, 5), sharey=True, layout="constrained")
    fig.suptitle(
        f"Skirt film at crank angle {skirt_map['crank_angle_deg']:.1f}° (0 = firing TDC), "
        f"t = {skirt_map['time']:.6g} s\n{case}",
        fontsize="medium",
    )
    for ax, (side, title) in zip(axes, SIDES, strict=True):
        m = skirt_map[side]
        angle, depth = m["angle_deg"], m["position"] * 1e3
        mesh = ax.pcolormesh(
            angle, depth, m["film_pressure"] * 1e-6, shading="gouraud", cmap="viridis", vmin=0, vmax=top
        )
        lines = ax.contour(angle, depth, m["film_thickness"] * 1e6, colors="w", linewidths=0.7)
        ax.clabel(lines, fmt="%.0f µm", fontsize="x-small")
        ax.set_title(title, fontsize="medium")
        ax.set_xlabel("angle around the bore from +x [deg]")
    axes[0].set_ylabel("distance below the skirt's top edge [mm]")
    axes[0].invert_yaxis()
    fig.colorbar(mesh, ax=axes, label="film pressure [MPa]")
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path
