"""A published finding through the FMU: with e = 0 and D = 0.08008 m at 1200 rpm and 8 MPa peak (gauge) pressure,
the piston changes sides six times per four-stroke cycle (Awrejcewicz & Kudra 2005, Fig 5 and its text;
DESIGN.md §6.3)."""

import numpy as np

from pistonslap.fmu import last_cycle, simulate

HALF_CLEARANCE = (0.08008 - 0.08) / 2
CYCLES = 4  # the first cycles carry the start-up transient; the last one is steady


def side_changes(lateral):
    """How often the pin crosses from beyond +c/4 to beyond -c/4 or back (hysteresis ignores rebounds)."""
    side = np.sign(lateral[np.abs(lateral) > HALF_CLEARANCE / 2])
    return int(np.count_nonzero(np.diff(side)))


def test_six_side_changes_per_cycle(fmu_file):
    result = simulate(
        stop_time=CYCLES * 0.1,
        output_interval=1e-4,
        start_values={"restitution": 0.0},
        output=["crank_angle", "piston_lateral"],
    )
    cycle, _ = last_cycle(result["crank_angle"])
    assert side_changes(result["piston_lateral"][cycle]) == 6
