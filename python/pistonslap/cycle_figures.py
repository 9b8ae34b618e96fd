"""The figures of the cycle a demo draws, from the same impact log the slap plot draws (so that the summary and the
plots describe one cycle), and their change from the cycle before: whether the run has settled.

The FMU's per-cycle slap and impact outputs count from firing TDC to firing TDC; the demo draws the cycle from −360°
to 360° about the last firing TDC (or 0…720° with `--crank-0-720`), over which its landing outputs are taken.
`figures` counts the slaps and impacts of the logged events within the drawn window with the FMU's rules (a slap: a
landing on the other wall faster than `slap_threshold`, `tables.slap_rows`), under the FMU's column names.
"""

import numpy as np

from .fmu import last_cycle
from .tables import WALLS, slap_rows

#: A figure that moved by more than this share from the cycle before has not settled.
SETTLED = 0.10
#: Energies below this share of the cycle's impact energy are left out of the settling check (noise, not a figure).
NEGLIGIBLE = 0.02


def walls(events):
    """Per event, `thrust` (corners 3, 4 at +D/2) or `antithrust` (corners 1, 2)."""
    return np.where(events["corner"] <= 2, "antithrust", "thrust")


def figures(events, in_window, slap_threshold):
    """The slap and impact figures (`tables.CYCLE_METRICS`' names) of the logged `events` selected by `in_window`."""
    slaps = slap_rows(events, slap_threshold) & in_window
    impacts = (events["kind"] == "impact") & in_window
    wall, lost = walls(events), events["energy_lost"]
    row = {"cycle_slap_events": int(slaps.sum()), "cycle_impacts": int(impacts.sum())}
    row["cycle_impact_energy"] = float(lost[impacts].sum())
    for side in WALLS:
        on = wall == side
        row[f"cycle_slaps_{side}"] = int((slaps & on).sum())
        row[f"cycle_slap_energy_{side}"] = float(lost[slaps & on].sum())
        row[f"cycle_max_slap_energy_{side}"] = float(lost[slaps & on].max(initial=0.0))
        row[f"cycle_max_impact_energy_{side}"] = float(lost[impacts & on].max(initial=0.0))
    return row


def cycle_before(crank_angle, drawn, origin):
    """The samples of the cycle before the drawn one (`drawn`, a mask of `crank_angle`'s samples), or None when the
    record does not hold it whole."""
    first = int(np.argmax(drawn))
    if first == 0:
        return None
    before, angle = last_cycle(crank_angle[: first + 1], origin=origin)
    if not angle[before][0] <= origin + WHOLE:
        return None
    mask = np.zeros(len(crank_angle), dtype=bool)
    mask[: first + 1] = before
    return mask


#: How far past its start a cycle's first sample may lie and the cycle count as whole, rad (a few samples).
WHOLE = np.radians(1.0)
#: The figures compared from cycle to cycle, in words.
MAIN = {
    "cycle_slap_events": "slaps",
    "cycle_max_slap_energy_thrust": "largest major-thrust slap",
    "cycle_max_slap_energy_antithrust": "largest anti-thrust slap",
    "cycle_impact_energy": "impact energy",
}


def change(now, before):
    """(one line of the main figures' change from the cycle before, the figures that moved by more than `SETTLED`)."""
    parts, moved = [], []
    floor = NEGLIGIBLE * max(now["cycle_impact_energy"], before["cycle_impact_energy"])
    for name, words in MAIN.items():
        a, b = before[name], now[name]
        if name == "cycle_slap_events":
            parts.append(f"{words} {a} → {b}")
            if a != b:
                moved.append(words)
            continue
        largest = max(abs(a), abs(b))
        share = (b - a) / largest if largest > 0 else 0.0
        parts.append(f"{words} {a * 1e3:.3g} → {b * 1e3:.3g} mJ ({round(100 * share, 1) + 0.0:+.1f} %)")
        if abs(share) > SETTLED and largest > floor:
            moved.append(words)
    return "From the cycle before to the cycle drawn: " + ", ".join(parts) + ".", moved
