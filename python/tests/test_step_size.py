"""Impacts are located inside the communication step, so the event record does not depend on the step size:
two engine cycles of the default engine with communication steps of 1e-3 s and 1e-4 s."""

import numpy as np
import pytest

from pistonslap.fmu import simulate_with_events

COARSE, FINE = 1e-3, 1e-4
STOP = 0.2  # s, two cycles at 1200 rpm
#: An impact of one run is matched by an impact of the same corner in the other within this time (0.007° of
#: crank angle at 1200 rpm): a tenth of the fine step, a hundredth of the coarse one.
TIME_TOLERANCE = 1e-5
#: Impacts slower than this are the tail of a bounce sequence converging to sliding, whose length depends on where
#: the integrator's steps fall; they are counted but not matched one by one.
SLOW = 1e-3  # m/s


@pytest.fixture(scope="module")
def runs(fmu_file):
    return {h: simulate_with_events(stop_time=STOP, output_interval=h, output=["impact_count"]) for h in (COARSE, FINE)}


def impacts(events):
    return events[events["kind"] == "impact"]


def test_impact_counts_agree(runs):
    coarse, fine = (len(impacts(runs[h][1])) for h in (COARSE, FINE))
    assert coarse > 0
    assert abs(coarse - fine) <= max(2, 0.02 * fine)


def test_impact_times_agree(runs):
    coarse, fine = (impacts(runs[h][1]) for h in (COARSE, FINE))
    for this, other in ((coarse, fine), (fine, coarse)):
        for event in this[this["normal_velocity_before"] > SLOW]:
            same_corner = other[other["corner"] == event["corner"]]
            assert np.min(np.abs(same_corner["time"] - event["time"])) <= TIME_TOLERANCE, event


def test_impacts_are_not_on_the_communication_grid(runs):
    """An FMU that detected impacts only at the end of the step would put every impact on the coarse grid."""
    times = impacts(runs[COARSE][1])["time"]
    on_grid = np.abs(times / COARSE - np.round(times / COARSE)) < 1e-6
    assert on_grid.mean() < 0.05
