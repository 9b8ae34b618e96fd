"""PistonSlap driven by the EngineCycle FMU through the Python master (`pistonslap.coupled`), both packaged FMUs
in one process."""

import numpy as np
import pytest

from pistonslap.master import run
from pistonslap.validation import coupled_energy

RAMP_TIME = 8.4  # s: 100 → 200 rad/s, (100 + 200)/2 · 8.4 = 1260 rad > 100 cycles of 4π
STEP = 1e-3
RAMP = {"speed_start": 100.0, "speed_end": 200.0, "ramp_time": RAMP_TIME}


@pytest.fixture(scope="module")
def ramp_runs():
    return {d: run(RAMP_TIME, STEP, engine_values=RAMP, derivatives=d) for d in (True, False)}


def test_crank_angles_agree_over_100_cycles_of_a_speed_ramp(ramp_runs):
    rows = ramp_runs[True]
    assert rows["engine_crank_angle"][-1] > 100 * 4 * np.pi
    # With the speed's slope passed on, PistonSlap integrates the engine's linear ramp exactly.
    assert np.max(np.abs(rows["crank_angle"] - rows["engine_crank_angle"])) < 1e-3


def test_held_speed_lags_by_half_alpha_h_squared_per_step(ramp_runs):
    # Held over each step, the speed loses ½ α h² of crank angle per step against the ramp.
    rows = ramp_runs[False]
    alpha = (RAMP["speed_end"] - RAMP["speed_start"]) / RAMP_TIME
    steps = len(rows) - 1
    lag = rows["engine_crank_angle"][-1] - rows["crank_angle"][-1]
    assert lag == pytest.approx(steps * 0.5 * alpha * STEP**2, rel=1e-6)
    assert lag > 1e-3


@pytest.fixture(scope="module")
def energies():
    """Impact energy per cycle over cycles 2..5 at 1200 rpm, fired default engine: the runs of
    documentation/validation/coupling.md's table (`pistonslap.validation`, cached, so that its check reuses them)."""
    return {
        (h, d): coupled_energy(h, d)
        for h, d in [(2e-5, False), (1e-3, False), (1e-3, True), (2.5e-4, False), (2.5e-4, True)]
    }


def test_first_derivatives_at_1ms_give_the_fine_step_impact_energy(energies):
    reference = energies[(2e-5, False)]
    assert reference > 0
    first_order = abs(energies[(1e-3, True)] / reference - 1)
    held = abs(energies[(1e-3, False)] / reference - 1)
    assert first_order < 0.03
    # The held inputs miss it by several times more: the derivatives are what closes the gap.
    assert held > 2 * first_order


def test_libcosim_and_the_python_master_give_the_same_impacts_at_the_same_steps():
    from pistonslap.coupled import run_libcosim

    steps = 400  # 4 engine cycles of 1 ms steps (the OSP file's BaseStepSize), inputs held in both
    cosim = run_libcosim(steps)
    ours = run(steps * 1e-3, 1e-3, derivatives=False)[1:]
    assert cosim["impact_count"][-1] > 100
    np.testing.assert_array_equal(cosim["impacts_in_step"], ours["impacts_in_step"].astype(int))
    # libcosim places the communication points at whole nanoseconds, the Python master at k h: round-off apart.
    np.testing.assert_allclose(cosim["impact_energy_total"], ours["impact_energy_total"], rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(cosim["engine_crank_angle"], ours["engine_crank_angle"], rtol=1e-12)


def test_the_coupled_system_converges_with_the_step_held_or_interpolated(energies):
    reference = energies[(2e-5, False)]
    for derivatives in (False, True):
        coarse, fine = (abs(energies[(h, derivatives)] / reference - 1) for h in (1e-3, 2.5e-4))
        assert fine < 0.5 * coarse, f"derivatives={derivatives}: {coarse:.2e} at 1 ms, {fine:.2e} at 0.25 ms"
