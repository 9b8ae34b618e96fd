"""Impacts are located inside the communication step, so the event record does not depend on the step size:
two engine cycles of the default engine with communication steps of 1e-3 s and 1e-4 s.

Measured (1e-3 vs 1e-4 vs 1e-5 s): the 172 impacts faster than 1 mm/s pair one to one, same corner, times within
1.3e-10 s, approach speeds within 2e-5 relative. The assertions leave a factor of about 100 on the times and 50 on
the speeds, and are still 1e5 times finer than the coarse step, on whose grid an FMU that detected impacts only at
the end of the step would put them.

A host may also take one long step: 10 s in one `fmi2DoStep` holds ≈ 9600 events, which the core must not mistake
for an accumulation of impacts."""

import numpy as np
import pytest

from pistonslap.fmu import simulate_with_events

COARSE, FINE = 1e-3, 1e-4
STOP = 0.2  # s, two cycles at 1200 rpm
TIME_TOLERANCE = 1e-8  # s, 4e-5° of crank angle at 1200 rpm
SPEED_TOLERANCE = 1e-3  # relative
#: Slower impacts end bounce sequences that converge to sliding (their length depends on where the integrator's
#: steps fall) or are closed corners taking part in a neighbour's impact: counted, not paired.
SLOW = 1e-3  # m/s
LONG = 10.0  # s, a hundred cycles in one communication step


@pytest.fixture(scope="module")
def runs(fmu_file):
    return {h: simulate_with_events(stop_time=STOP, output_interval=h, output=["impact_count"]) for h in (COARSE, FINE)}


def impacts(run, slower_than=-np.inf):
    _, events = run
    fast = (events["kind"] == "impact") & (events["normal_velocity_before"] > slower_than)
    return events[fast]


def test_impact_counts_agree(runs):
    coarse, fine = (len(impacts(runs[h])) for h in (COARSE, FINE))
    assert coarse > 0 and abs(coarse - fine) <= 2
    for h in (COARSE, FINE):
        assert runs[h][0]["impact_count"][-1] == len(impacts(runs[h]))


def test_impacts_pair_one_to_one(runs):
    coarse, fine = (impacts(runs[h], SLOW) for h in (COARSE, FINE))
    assert len(coarse) == len(fine) > 100
    np.testing.assert_array_equal(coarse["corner"], fine["corner"])
    np.testing.assert_allclose(coarse["time"], fine["time"], rtol=0, atol=TIME_TOLERANCE)
    np.testing.assert_allclose(coarse["normal_velocity_before"], fine["normal_velocity_before"], rtol=SPEED_TOLERANCE)


def test_impacts_are_not_on_the_communication_grid(runs):
    times = impacts(runs[COARSE])["time"]
    on_grid = np.abs(times / COARSE - np.round(times / COARSE)) < 1e-6
    assert on_grid.mean() < 0.05


def test_one_long_step_gives_the_impacts_of_short_ones(fmu_file):
    long, short = (simulate_with_events(stop_time=LONG, output_interval=h)[1] for h in (LONG, 1e-2))
    fast = [impacts((None, events), SLOW) for events in (long, short)]
    assert len(fast[0]) == len(fast[1]) > 5000
    np.testing.assert_array_equal(fast[0]["corner"], fast[1]["corner"])
    np.testing.assert_allclose(fast[0]["time"], fast[1]["time"], rtol=0, atol=TIME_TOLERANCE)


#: The default engine at 8000 rpm, and one at 3482 rpm with a 3.6 um clearance and e = 0: fast and tight designs,
#: where the prescribed crank's steps must stay bounded in crank angle (not only by the error control, which sees
#: nothing while two corners hold the piston) for the impacts not to depend on the communication step.
FAST_AND_TIGHT = [
    ({"crank_speed": 8000 * np.pi / 30}, 400),
    ({"crank_speed": 3482 * np.pi / 30, "bore": 0.08 + 7.2e-6, "restitution": 0.0}, 20),
]


@pytest.mark.parametrize("start_values, at_least", FAST_AND_TIGHT)
def test_impacts_at_high_speed_and_tight_clearance_pair_one_to_one(fmu_file, start_values, at_least):
    coarse, fine = (
        simulate_with_events(
            start_values=start_values, stop_time=0.06, output_interval=h, output=["impact_energy_total"]
        )
        for h in (2e-3, 1e-5)
    )
    assert coarse[0]["impact_energy_total"][-1] == pytest.approx(fine[0]["impact_energy_total"][-1], rel=1e-6)
    coarse, fine = impacts(coarse), impacts(fine)
    assert len(coarse) == len(fine) >= at_least
    np.testing.assert_array_equal(coarse["corner"], fine["corner"])
    np.testing.assert_allclose(coarse["time"], fine["time"], rtol=0, atol=TIME_TOLERANCE)
    np.testing.assert_allclose(coarse["normal_velocity_before"], fine["normal_velocity_before"], rtol=SPEED_TOLERANCE)
