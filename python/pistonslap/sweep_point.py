"""One point of a sweep: a run of the FMU and its row of the results (slap metrics, response class, status)."""

import numpy as np
from fmpy.fmi1 import FMICallException

from .fmu import CYCLE, simulate_with_logs
from .response import CLASSIFIABLE_CYCLES, classify, roller_run
from .settings import to_fmu
from .tables import (
    LANDING_METRICS,
    LANDING_RUN_ON,
    OVER_CYCLES,
    SAMPLE_DEG,
    cycle_metrics,
    over_cycles,
    side_changes,
)

#: The results' columns after the swept values, and their units: the impact log's, then (crank train only; NaN for
#: the roller) the landings, liner loads, skirt FMEP and film of the counted cycles (`tables.over_cycles`).
IMPACT_METRICS = {
    "impacts_per_cycle": "1/cycle",
    "max_impact_velocity": "m/s",
    "impact_energy_per_cycle": "J/cycle",
    "side_changes_per_cycle": "1/cycle",
}
METRICS = {**IMPACT_METRICS, **OVER_CYCLES}
#: What a crank-train run records for `tables.cycle_metrics`: of the FMU's firing-TDC cycle outputs only the FMEP
#: (`tables.over_cycles` reads no other; each output recorded at every 0.36° costs about 2 % more time).
RECORDED = [
    "crank_angle",
    "cycle_count",
    "min_film_thickness_thrust",
    "min_film_thickness_antithrust",
    "film_force",
    "asperity_force",
    "cycle_skirt_fmep",
    *LANDING_METRICS,
]
#: Then the response (variant 2, runs of at least CLASSIFIABLE_CYCLES crank cycles; else empty), its period and the
#: cycle it settled at (0 where none), and `ok` or the FMI error message.
RESPONSE_COLUMNS = ("response", "period", "settled", "status")

#: Crank angle of one cycle: an engine cycle (firing TDC to firing TDC) for the crank train, a crank turn for the
#: roller, whose forcing repeats every turn.
CYCLE_ANGLE = {1: CYCLE, 2: 2 * np.pi}
_FMI_ERROR = 3


def defaults(model_description):
    """The FMU's start values by name (numbers as numbers)."""
    kinds = {"Real": float, "Integer": int, "Enumeration": int, "Boolean": lambda s: s == "true", "String": str}
    return {v.name: kinds[v.type](v.start) for v in model_description.modelVariables if v.start is not None}


def run_point(fmu, model_description, values, cycles, skip_cycles):
    """Runs `cycles` cycles with the start values `values` from `fmu` (a file or extracted folder) and returns the
    row of metrics over the cycles after the first `skip_cycles`; an FMI error is the row's status."""
    values = to_fmu(values, defaults(model_description))
    every = dict(defaults(model_description), **values)
    speed, angle = every["crank_speed"], CYCLE_ANGLE[every["model_variant"]]
    crank_train = every["model_variant"] == 1
    # the crank train sampled as the demo does, past the cycle about the firing TDC ending the last counted cycle
    # until the FMU completed its landing figures (the next landing started); the roller (thousands of turns, no
    # film) once a turn
    interval = np.radians(SAMPLE_DEG) / speed if crank_train else angle / speed
    landed_by = (cycles * angle + np.pi * 2) / speed if crank_train else None
    stop_time = landed_by + LANDING_RUN_ON / speed + interval if crank_train else cycles * angle / speed
    errors = []

    def logger(_component, _instance, status, _category, message):
        if status >= _FMI_ERROR:
            errors.append(message.decode(errors="replace"))

    try:
        result, events, landings = simulate_with_logs(
            fmu=fmu,
            model_description=model_description,
            start_values=values,
            stop_time=stop_time,
            landed_by=landed_by,
            output_interval=interval,
            output=RECORDED if crank_train else ["impact_count"],
            logger=logger,
        )
    except FMICallException as e:
        return dict(
            dict.fromkeys(METRICS, np.nan), response=None, period=0, settled=0, status=errors[-1] if errors else str(e)
        )
    row = metrics(events, speed * events["time"] // angle, cycles, skip_cycles)
    if crank_train:
        table, _ = cycle_metrics(result, landings)
        row |= over_cycles(table[(table["cycle"] > skip_cycles) & (table["cycle"] <= cycles)])
    else:
        row |= dict.fromkeys(OVER_CYCLES, np.nan)
    kind, period, settled = None, 0, 0
    if every["model_variant"] == 2 and cycles >= CLASSIFIABLE_CYCLES:
        response = classify(roller_run(events, every, cycles))
        kind, period, settled = response.kind, response.period, response.settled
    return dict(row, response=kind, period=period, settled=settled, status="ok")


def metrics(events, cycle, cycles, skip_cycles):
    """`METRICS` of the impact log `events` whose rows fall in the cycles `cycle` (0 = the run's first), counted
    over cycles skip_cycles to cycles - 1 (side changes: `tables.side_changes`)."""
    counted = cycles - skip_cycles
    window = (cycle >= skip_cycles) & (cycle < cycles)
    impacts = window & (events["kind"] == "impact")
    change = side_changes(events)
    velocities = events["normal_velocity_before"][impacts]
    return {
        "impacts_per_cycle": impacts.sum() / counted,
        "max_impact_velocity": float(velocities.max()) if velocities.size else 0.0,
        "impact_energy_per_cycle": events["energy_lost"][impacts].sum() / counted,
        "side_changes_per_cycle": (change & window).sum() / counted,
    }


def all_zero(values):
    """Whether a metric's values (NaN for failed points) are zero at every point that has one, there being one."""
    values = np.asarray(values, dtype=float)
    finite = values[np.isfinite(values)]
    return finite.size > 0 and not finite.any()


def zero_note(names):
    """One line saying which metrics (`names`) read 0 at every point of a sweep, or None for none."""
    if not names:
        return None
    hint = (
        " (no impacts: the landing_ and film columns measure the slap of a skirt riding on its film)"
        if set(names) & set(IMPACT_METRICS)
        else ""
    )
    return f"0 at every point of the sweep: {', '.join(names)}{hint}"
