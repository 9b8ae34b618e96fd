"""Inputs given to fmpy as signals change the outputs as the physics says.

fmpy samples an input signal at the start of each communication step and the FMU holds it over the step."""

import numpy as np
import pytest

from pistonslap.fmu import input_signals, simulate

R, L, D = 0.04, 0.15, 0.08  # crank_radius, rod_length, piston_diameter
CROWN = np.pi * D**2 / 4


def test_crank_angle_follows_a_speed_ramp(fmu_file):
    """ω ramps from 600 to 1800 rpm over 0.2 s. With ω held over each step h, the crank angle at t_k is the left
    Riemann sum of the ramp (exact up to rounding); it differs from the exact integral by a·t·h/2."""
    h, t_end, w0, w1 = 1e-3, 0.2, 62.83, 188.5
    a = (w1 - w0) / t_end
    ramp = input_signals([0, t_end], crank_speed=[w0, w1])
    result = simulate(stop_time=t_end, output_interval=h, input=ramp, output=["crank_angle"])
    t, theta = result["time"], result["crank_angle"]
    held = np.concatenate([[0], np.cumsum((w0 + a * t[:-1]) * np.diff(t))])
    np.testing.assert_allclose(theta, held, rtol=1e-9, atol=1e-12)
    exact = w0 * t + a * t**2 / 2
    assert np.all(np.abs(theta - (exact - a * t * h / 2)) <= 1e-9 * exact + 1e-12)


@pytest.fixture(scope="module")
def slow_crank_under_rising_pressure(fmu_file):
    """ω = 10 rad/s, gas_pressure from the host rising linearly from 0 to 3 MPa over 150° of crank angle."""
    omega, h = 10.0, 1e-4
    t_end = np.radians(150) / omega
    trace = input_signals([0, t_end], gas_pressure=[0, 3e6], crank_speed=[omega, omega])
    result = simulate(stop_time=t_end, output_interval=h, input=trace, start_values={"pressure_source": 1})
    pressure = 3e6 * np.concatenate([[0], result["time"][:-1]]) / t_end  # as held over the step ending at t
    return result, pressure


def quasi_static(theta, pressure):
    """Ideal slider crank, force F = p·πd²/4 on the crown: side force F tan β, drive torque -F r sin(θ+β)/cos β."""
    force = pressure * CROWN
    beta = np.arcsin(R / L * np.sin(theta))
    return force * np.tan(beta), -force * R * np.sin(theta + beta) / np.cos(beta)


def test_pressure_trace_sets_side_force_and_crank_torque(slow_crank_under_rising_pressure):
    """At 10 rad/s inertia forces are below 2 N and the joint damping below 0.3 N·m, so between 30° and 150° the
    piston, pressed flat on one wall, carries the quasi-static load; gravity on piston and rod (≈ 12 N along the
    axis) shifts side force and torque by at most ≈ 4 N and 0.5 N·m."""
    result, pressure = slow_crank_under_rising_pressure
    theta = result["crank_angle"]
    loaded = theta >= np.radians(30)
    side, torque = quasi_static(theta[loaded], pressure[loaded])
    np.testing.assert_allclose(np.abs(result["side_force"][loaded]), np.abs(side), rtol=0.02, atol=10)
    np.testing.assert_allclose(result["crank_torque"][loaded], torque, rtol=0.02, atol=1)
    # the liner pushes the piston back toward the axis
    assert np.all(np.sign(result["side_force"][loaded]) == -np.sign(result["piston_lateral"][loaded]))


def test_pressure_presses_the_piston_flat_on_one_wall(slow_crank_under_rising_pressure):
    """Gas force along the axis and pin mid-skirt: no moment about the pin, so both corners of the loaded wall
    touch and carry half the side force each."""
    result, _ = slow_crank_under_rising_pressure
    loaded = result["crank_angle"] >= np.radians(30)
    states = np.array([result[f"contact_state_{i}"][loaded] for i in range(1, 5)])
    forces = np.array([result[f"contact_force_{i}"][loaded] for i in range(1, 5)])
    left = np.all(states == [[1], [1], [0], [0]], axis=0)
    right = np.all(states == [[0], [0], [1], [1]], axis=0)
    assert np.all(left) or np.all(right)
    pair = forces[:2] if np.all(left) else forces[2:]
    np.testing.assert_allclose(pair[0], pair[1], rtol=0.05, atol=5)
