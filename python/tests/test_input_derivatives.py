"""Interpolated inputs (`canInterpolateInputs`): fmi2SetRealInputDerivatives of order 1 and 2 makes the inputs follow
polynomials inside the step, the crank angle integrates the interpolated speed exactly, a new fmi2SetReal of an input
ends its derivatives, bad calls are refused; and a host-supplied pressure converges with the step size, far faster with
first derivatives than held."""

import pytest
from fmpy.fmi1 import FMICallException

from pistonslap.validation import FED_REFERENCE_STEP, FED_STEPS, fed_cycles

from harness import FMI_ERROR, Instance

W0 = 125.66  # rad/s


def derivatives(s, name, *values):
    """fmi2SetRealInputDerivatives of `name`, orders 1, 2, … for `values`."""
    s.slave.setRealInputDerivatives([s.vr[name]] * len(values), list(range(1, len(values) + 1)), list(values))


@pytest.mark.parametrize("order", [1, 2])
def test_the_crank_angle_integrates_the_interpolated_speed_exactly(unpacked_fmu, order):
    """ω(t) = ω0 + a t + b t²/2 given at each 1 ms step by its value and derivatives: φ = ω0 t + a t²/2 + b t³/6
    at every communication point, to rounding (held inputs are off by a·t·h/2, 1e-3 rad here)."""
    a, b, h = 2000.0, (0.0 if order == 1 else -4e4), 1e-3
    with Instance(unpacked_fmu) as s:
        s.initialize()
        for k in range(100):
            t = k * h
            s.set(crank_speed=W0 + a * t + b * t * t / 2)
            derivatives(s, "crank_speed", *([a + b * t, b][:order]))
            s.step(h)
            t += h
            exact = W0 * t + a * t * t / 2 + b * t**3 / 6
            angle, speed = s.get("crank_angle", "crank_speed_actual")
            assert angle == pytest.approx(exact, rel=1e-12, abs=1e-12)
            assert speed == pytest.approx(W0 + a * t + b * t * t / 2, rel=1e-12)


def test_gas_pressure_follows_its_polynomial_and_a_new_value_ends_it(unpacked_fmu):
    h = 1e-3
    with Instance(unpacked_fmu) as s:
        s.initialize(pressure_source=1, gas_pressure=1e6)
        derivatives(s, "gas_pressure", 2e8, 4e10)
        s.step(h)
        assert s.get("gas_pressure_acting")[0] == pytest.approx(1e6 + 2e8 * h + 4e10 * h * h / 2, rel=1e-14)
        # the derivatives stay until the input is set again, about each step's start and the value last set
        s.step(h)
        assert s.get("gas_pressure_acting")[0] == pytest.approx(1e6 + 2e8 * h + 4e10 * h * h / 2, rel=1e-14)
        s.set(gas_pressure=3e6)
        s.step(h)
        assert s.get("gas_pressure_acting")[0] == 3e6


def test_a_new_crank_speed_ends_its_derivatives(unpacked_fmu):
    h = 1e-3
    with Instance(unpacked_fmu) as s:
        s.initialize()
        derivatives(s, "crank_speed", 1000.0)
        s.step(h)
        before = s.get("crank_angle")[0]
        assert before == pytest.approx(W0 * h + 1000 * h * h / 2, rel=1e-13)
        s.set(crank_speed=100.0)
        s.step(h)
        assert s.get("crank_angle")[0] - before == pytest.approx(100.0 * h, rel=1e-12)


@pytest.mark.parametrize(
    "name, order, value, expected",
    [
        ("crank_speed", 0, 1.0, "derivative order 0 of crank_speed refused"),
        ("crank_speed", 3, 1.0, "derivative order 3 of crank_speed refused"),
        ("gas_pressure", 1, float("nan"), "derivative 1 of gas_pressure = NaN refused"),
        ("crank_angle", 1, 1.0, "crank_angle (value reference"),
        ("restitution", 1, 1.0, "restitution (value reference"),
    ],
)
def test_bad_input_derivatives_are_refused_naming_the_cause(unpacked_fmu, name, order, value, expected):
    with Instance(unpacked_fmu) as s:
        s.initialize()
        with pytest.raises(FMICallException):
            s.slave.setRealInputDerivatives([s.vr[name]], [order], [value])
        assert any(expected in m for m in s.messages(FMI_ERROR)), s.messages(FMI_ERROR)
        s.step(1e-3)  # still usable


# --- a host-supplied Wiebe pressure cycle: step-size convergence, held against first-order inputs ---------------------


@pytest.fixture(scope="module")
def convergence():
    """{(h, first_order): (energy per cycle, max impact velocity)} and the 1e-5 s first-order reference: the runs of
    documentation/validation/coupling.md's table (`pistonslap.validation`, cached, so that its check reuses them)."""
    runs = {(h, first): fed_cycles(h, first) for h in FED_STEPS for first in (False, True)}
    return runs, fed_cycles(FED_REFERENCE_STEP, True)


def test_first_derivatives_at_1_ms_are_within_3_percent_of_the_fine_step_reference(convergence):
    """Measured: first-order +0.7 % (energy) and +0.8 % (max impact velocity) at 1 ms, held −8.9 % and −7.8 %."""
    runs, (energy, fastest) = convergence
    first, held = runs[1e-3, True], runs[1e-3, False]
    assert first[0] == pytest.approx(energy, rel=0.03) and first[1] == pytest.approx(fastest, rel=0.03)
    assert held[0] < 0.95 * energy and held[1] < 0.95 * fastest  # the lag of a held pressure, which derivatives remove


def test_both_converge_with_the_step_and_first_order_is_closer_at_every_step(convergence):
    runs, (energy, _) = convergence
    error = {key: abs(value[0] / energy - 1) for key, value in runs.items()}
    for first in (False, True):
        assert error[1e-4, first] < error[1e-3, first] / 5
    for h in FED_STEPS:
        assert error[h, True] < error[h, False]
