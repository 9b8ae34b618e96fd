"""Python side of PistonSlap: run the packaged FMU with fmpy, read its impact log, plot the results."""

from .fmu import (
    CYCLE,
    fmu_path,
    input_signals,
    last_cycle,
    read_impact_log,
    read_landing_log,
    simulate,
    simulate_with_events,
    simulate_with_logs,
)
from .liner_load import liner_loads

__all__ = [
    "CYCLE",
    "fmu_path",
    "input_signals",
    "last_cycle",
    "liner_loads",
    "read_impact_log",
    "read_landing_log",
    "simulate",
    "simulate_with_events",
    "simulate_with_logs",
]
