"""The default experiment through fmpy.simulate_fmu: it runs, its outputs are finite, agree with the impact log,
and stay inside the bounds the geometry sets (A&K section 8 defaults: d = 0.08 m, D = 0.08008 m, s = 0.08 m)."""

import numpy as np
import pytest

from pistonslap.fmu import CYCLE, simulate_with_events

OMEGA = 125.66  # rad/s, the crank_speed start value
R, L = 0.04, 0.15  # crank_radius, rod_length
HALF_CLEARANCE = (0.08008 - 0.08) / 2
SKIRT = 0.08
RESTITUTION = 0.5


@pytest.fixture(scope="module")
def run(fmu_file):
    return simulate_with_events()


def test_runs_to_the_default_stop_time_with_finite_outputs(run, unpacked_fmu):
    result, _ = run
    _, md = unpacked_fmu
    assert result["time"][-1] == pytest.approx(float(md.defaultExperiment.stopTime), abs=1e-12)
    for name in result.dtype.names:
        assert np.all(np.isfinite(result[name])), name


def test_crank_angle_is_the_integral_of_the_prescribed_speed(run):
    result, _ = run
    np.testing.assert_allclose(result["crank_angle"], OMEGA * result["time"], rtol=1e-9, atol=1e-12)


def test_piston_stays_inside_the_bore(run):
    """The pin sits mid-skirt (h = s/2), so its lateral position is the mean of two corners' and cannot pass the
    half clearance by more than d(1 - cos tilt)/2 ≈ 2e-8 m; tilt cannot pass clearance/skirt (diagonal contact).
    1 µm and 1e-5 rad leave room for gap tolerances while still catching any real penetration."""
    result, _ = run
    assert np.max(np.abs(result["piston_lateral"])) <= HALF_CLEARANCE + 1e-6
    assert np.max(np.abs(result["piston_tilt"])) <= 2 * HALF_CLEARANCE / SKIRT + 1e-5


def test_pin_follows_the_slider_crank_kinematics(run):
    """Axial pin position r cos θ + sqrt(l² - (r sin θ - x)²): a lateral offset |x| ≤ 40 µm moves it by at most
    r|x|/sqrt(l² - r²) ≈ 1.1e-5 m from the zero-clearance value."""
    result, _ = run
    theta = result["crank_angle"]
    nominal = R * np.cos(theta) + np.sqrt(L**2 - (R * np.sin(theta)) ** 2)
    assert np.max(np.abs(result["piston_axial"] - nominal)) <= 1.5e-5


def test_contact_forces_push_and_vanish_when_free(run):
    result, _ = run
    for corner in range(1, 5):
        force, state = result[f"contact_force_{corner}"], result[f"contact_state_{corner}"]
        assert set(np.unique(state)) <= {0, 1}
        assert np.all(force >= 0), corner
        assert np.all(force[state == 0] == 0), corner


def test_impact_statistics_agree_with_the_impact_log(run):
    result, events = run
    impacts = events[events["kind"] == "impact"]
    assert len(impacts) > 0, "the default engine cycle has impacts (A&K Fig 6)"
    assert set(events["kind"]) <= {"impact", "slide", "release"}
    assert set(events["corner"]) <= {1, 2, 3, 4}
    counts = result["impact_count"]
    assert counts[0] == 0 and counts[-1] == len(impacts)
    np.testing.assert_array_equal(np.diff(counts), result["impacts_in_step"][1:])
    # the impacts of step k are log rows counts[k-1] .. counts[k]-1
    for k in np.flatnonzero(result["impacts_in_step"]):
        in_step = impacts[counts[k - 1] : counts[k]]
        assert result["max_impact_velocity_in_step"][k] == pytest.approx(
            in_step["normal_velocity_before"].max(), rel=1e-12
        )
        assert result["impact_energy_in_step"][k] == pytest.approx(in_step["energy_lost"].sum(), rel=1e-9)
        assert result["impact_velocity"][k] == pytest.approx(in_step["normal_velocity_before"][-1], rel=1e-12)
        assert result["last_impact_corner"][k] == in_step["corner"][-1]
    np.testing.assert_allclose(result["impact_energy_total"], np.cumsum(result["impact_energy_in_step"]), rtol=1e-9)
    assert result["last_impact_crank_angle"].min() >= 0 and result["last_impact_crank_angle"].max() < CYCLE


def test_impacts_obey_newtons_law(run):
    """Approach speed ≥ 0, and the generalized Newton law ġ⁺ ≥ -e ġ⁻ (equality for a single impact; a corner
    released by a neighbour's impulse separates faster, DESIGN.md §6.4). Floors of 1e-12 m/s allow for rounding."""
    _, events = run
    impacts = events[events["kind"] == "impact"]
    before, after = impacts["normal_velocity_before"], impacts["normal_velocity_after"]
    assert np.all(before >= -1e-12)
    assert np.all(after >= RESTITUTION * before - 1e-12)


def test_corners_held_in_contact_are_not_counted_as_impacts(run):
    """A corner sliding on the wall when its neighbour strikes takes a reaction impulse but keeps ġ = 0: no
    approach, no dissipation, so no impact row and no count (it once made a fifth of the rows, all at 0 m/s)."""
    result, events = run
    impacts = events[events["kind"] == "impact"]
    assert np.all(impacts["normal_velocity_before"] > 0), impacts[impacts["normal_velocity_before"] <= 0]
    assert result["impact_count"][-1] == len(impacts)


def test_impact_energy_is_what_the_restitution_dissipates(run):
    """A single impact at speed v dissipates ½(1 - e²) m v², m the corner's effective mass. With the crank held at
    its prescribed speed only the piston and the rod move; locking the tilt can only raise m, to at most the
    piston's 0.4 kg plus the rod's (J2 + m2 l²)/(l² cos²β) ≤ 1.43 kg. So 0 ≤ energy ≤ ½(1 - e²)·1.83 kg·v²
    (the floor -1e-9 J allows for rounding; a 1 mm/s impact dissipates 1e-7 J)."""
    _, events = run
    impacts = events[events["kind"] == "impact"]
    times, count = np.unique(impacts["time"], return_counts=True)
    single = impacts[np.isin(impacts["time"], times[count == 1])]
    assert len(single) > 0
    v, energy = single["normal_velocity_before"], single["energy_lost"]
    assert np.all(energy >= -1e-9), single[energy < -1e-9]
    too_much = energy > 0.5 * (1 - RESTITUTION**2) * 1.83 * v**2
    assert not np.any(too_much), single[too_much]
    assert np.all(events["energy_lost"] >= -1e-9), events[events["energy_lost"] < -1e-9]
