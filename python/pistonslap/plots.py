"""Plots of one engine cycle against crank angle, in the style of Awrejcewicz & Kudra (2005) Figs 5-10.

Every function takes the samples of one cycle (`phase` = crank angle within the cycle, rad) and writes a PNG.
"""

import matplotlib.pyplot as plt
import numpy as np

CORNERS = (1, 2, 3, 4)


def _axes(rows, title):
    fig, axes = plt.subplots(rows, 1, sharex=True, figsize=(9, 2.2 * rows + 0.8), squeeze=False)
    axes = axes[:, 0]
    fig.suptitle(title)
    axes[-1].set_xlabel("crank angle [deg]  (0 = firing TDC)")
    axes[-1].set_xlim(0, 720)
    axes[-1].set_xticks(np.arange(0, 721, 90))
    for ax in axes:
        ax.grid(True, alpha=0.3)
    return fig, axes


def _legend(ax):
    ax.legend(loc="lower right", bbox_to_anchor=(1, 1), ncol=4, fontsize="small", frameon=False)


def _save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def piston_motion(phase, result, path, title="Piston secondary motion over one engine cycle"):
    """Lateral pin position, tilt, contact states (a bar per corner while in contact) and contact forces."""
    deg = np.degrees(phase)
    fig, (lateral, tilt, states, forces) = _axes(4, title)
    lateral.plot(deg, result["piston_lateral"] * 1e6)
    lateral.set_ylabel("lateral x [µm]")
    tilt.plot(deg, result["piston_tilt"] * 1e3)
    tilt.set_ylabel("tilt [mrad]")
    for corner in CORNERS:
        in_contact = result[f"contact_state_{corner}"] > 0
        states.fill_between(deg, corner - 0.35, corner + 0.35, where=in_contact, step="post", label=f"K{corner}")
        forces.plot(deg, result[f"contact_force_{corner}"] * 1e-3, label=f"K{corner}")
    states.set_yticks(CORNERS, [f"K{c}" for c in CORNERS])
    states.set_ylim(0.4, 4.6)
    states.set_ylabel("sliding contact")
    forces.set_ylabel("contact force [kN]")
    _legend(forces)
    return _save(fig, path)


def impacts(phase, result, events, path, title="Impacts over one engine cycle"):
    """Largest impact velocity in each communication step, and every logged impact by corner
    (the log's crank angle is the phase within the cycle). Log rows of closed corners taking part in a
    neighbour's impact have a zero approach speed: only impacts faster than 1 µm/s are drawn."""
    fig, (per_step, per_impact) = _axes(2, title)
    deg = np.degrees(phase)
    hit = result["impacts_in_step"] > 0
    per_step.vlines(deg[hit], 0, result["max_impact_velocity_in_step"][hit] * 1e3)
    per_step.set_ylabel("max impact velocity\nin step [mm/s]")
    is_impact = (events["kind"] == "impact") & (events["normal_velocity_before"] > 1e-6)
    for corner in CORNERS:
        mine = is_impact & (events["corner"] == corner)
        per_impact.plot(np.degrees(events["crank_angle"][mine]), events["normal_velocity_before"][mine] * 1e3,
                        "o", ms=3, label=f"K{corner}")
    per_impact.set_ylabel("impact velocity [mm/s]")
    if np.any(is_impact):  # bounce sequences span decades
        per_impact.set_yscale("log")
    _legend(per_impact)
    return _save(fig, path)


def crank_torque(phase, result, path, title="Drive torque holding the crank speed"):
    """The torque the drive applies to hold the prescribed crank speed."""
    fig, (ax,) = _axes(1, title)
    ax.plot(np.degrees(phase), result["crank_torque"])
    ax.set_ylabel("crank torque [N·m]")
    return _save(fig, path)
