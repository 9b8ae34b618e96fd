"""The impulse each liner wall receives per communication step (impacts and contact forces together), as a structural
model of block or liner would take it: the same per cycle at any step, and the contact forces' integral where no
impact falls in the step."""

import numpy as np
import pytest

from pistonslap.fmu import CYCLE, simulate

OMEGA = 125.66  # rad/s, the default crank speed
OUTPUTS = ["liner_impulse_thrust_in_step", "liner_impulse_antithrust_in_step", "impacts_in_step"] + [
    f"contact_force_{i}" for i in range(1, 5)
]


@pytest.fixture(scope="module")
def runs():
    """One engine cycle of the default case at three communication steps."""
    return {h: simulate(stop_time=CYCLE / OMEGA, output_interval=h, output=OUTPUTS) for h in (1e-3, 1e-4, 1e-5)}


def test_a_cycles_impulse_does_not_depend_on_the_step(runs):
    """Summed over the steps, each wall's impulse over the cycle is the same at 1 ms, 0.1 ms and 10 µs steps (to
    1e-5: the trajectories differ by the restarts at communication points), and no step's impulse is negative."""
    for side in ("thrust", "antithrust"):
        totals = [runs[h][f"liner_impulse_{side}_in_step"].sum() for h in runs]
        assert totals[0] > 1.0, "the piston presses on both walls for part of the cycle"
        np.testing.assert_allclose(totals, totals[-1], rtol=1e-5)
        for result in runs.values():
            assert result[f"liner_impulse_{side}_in_step"].min() >= -1e-12 * totals[0]


def test_without_impacts_the_impulse_is_the_contact_forces_integral(runs):
    """At 10 µs steps without an impact, each corner of the wall held at both ends or free at both, its impulse is
    the trapezoid of its corners' contact forces at the step's ends: to 1e-4 at the median step, to 1 % of the
    largest where a step's forces are not smooth (points within an integrator step take the impulse from the
    cubic Hermite of its integral)."""
    result = runs[1e-5]
    for side, corners in (("thrust", (3, 4)), ("antithrust", (1, 2))):
        force = sum(result[f"contact_force_{i}"] for i in corners)
        held = [result[f"contact_force_{i}"] > 0 for i in corners]
        quiet = (result["impacts_in_step"][1:] == 0) & (force[1:] > 0)
        for h in held:
            quiet &= h[1:] == h[:-1]
        trapezoid = 0.5 * (force[1:] + force[:-1]) * np.diff(result["time"])
        got = result[f"liner_impulse_{side}_in_step"][1:]
        assert quiet.sum() > 0.1 * len(quiet) and trapezoid[quiet].max() > 0
        error = np.abs(got[quiet] - trapezoid[quiet])
        assert np.median(error / trapezoid[quiet]) < 1e-4
        assert error.max() <= 1e-2 * trapezoid[quiet].max()
