"""Liner friction through fmpy: the published Flores–Leine–Glocker slider crank against Siconos, and the friction
outputs of an engine against the Coulomb law they report (cone, sign, power, accumulated energy)."""

import numpy as np
import pytest
from fmpy.fmi1 import FMICallException

from pistonslap import demo
from pistonslap.fmu import simulate, simulate_with_events
from pistonslap.presets import PRESETS

from harness import FMI_ERROR, Instance

# The benchmark's links, slider and guide mapped onto the crank train (tests/crank_train/flores_benchmark.rs),
# as published: mu = 0.01, gravity 9.81 m/s^2 across the guide, a start tilt rate of -0.01 rad/s.
FLORES = PRESETS["flores"].values


def test_flores_as_published_matches_siconos():
    """0.2 s at 1 ms steps: Siconos Moreau-Jean, its SliderCrank example run as published and extrapolated to
    h -> 0, turns the crank 2.87801 times; friction slows it against the frictionless 2.89271 with gravity alone."""
    result = simulate(
        stop_time=0.2,
        output_interval=1e-3,
        start_values=FLORES,
        output=["crank_angle", "friction_energy_total", "friction_power"],
    )
    revolutions = result["crank_angle"][-1] / (2 * np.pi)
    assert revolutions == pytest.approx(2.87801, rel=1e-4)
    assert revolutions < 2.8927 - 1e-3
    assert result["friction_energy_total"][-1] > 0 and np.all(np.diff(result["friction_energy_total"]) >= 0)


@pytest.fixture(scope="module")
def rubbing_engine():
    """One engine cycle of the default case with mu = 0.1 on a horizontal cylinder, at 0.1 ms steps."""
    corners = [f"{name}_{i}" for name in ("friction_force", "contact_force", "contact_state") for i in range(1, 5)]
    return simulate_with_events(
        start_values={"friction": 0.1, "gravity_lateral": 9.81},
        stop_time=0.1,
        output_interval=1e-4,
        output=[*corners, "friction_power", "friction_energy_total", "crank_angle"],
    )


def test_friction_forces_obey_the_coulomb_law(rubbing_engine):
    """A free corner carries no friction; a held one at most mu times its normal force; the force dissipates
    (power >= 0), and some corner slides on the liner through most of the cycle."""
    result, _ = rubbing_engine
    loaded = 0
    for i in range(1, 5):
        force, normal, held = (result[f"{n}_{i}"] for n in ("friction_force", "contact_force", "contact_state"))
        assert np.all(force[held == 0] == 0)
        assert np.all(np.abs(force) <= 0.1 * normal * (1 + 1e-9) + 1e-12)
        loaded += np.count_nonzero(np.abs(force) > 0)
    assert loaded > 0.5 * len(result)
    assert np.all(result["friction_power"] >= -1e-9 * np.abs(result["friction_power"]).max())


def test_friction_energy_accumulates_its_power(rubbing_engine):
    """friction_energy_total starts at 0, never decreases, and holds at least the sliding friction's work (the
    trapezoid of friction_power, to 2 % for the trapezoid's error at 0.1 ms): impacts add their share."""
    result, _ = rubbing_engine
    energy, power, time = result["friction_energy_total"], result["friction_power"], result["time"]
    assert energy[0] == 0 and np.all(np.diff(energy) >= 0)
    sliding = np.trapezoid(power, time)
    assert energy[-1] >= 0.98 * sliding > 0


def test_corners_stick_and_reverse_only_near_the_dead_centres(rubbing_engine):
    """A held corner comes to rest along the liner, or reverses its slip, only where the piston's axial speed
    passes zero: near top and bottom dead centre (crank angle 0 or 180 degrees, mod 180), the tilt's share of a
    corner's axial speed moving the instant by less than a degree."""
    _, events = rubbing_engine
    turns = events[np.isin(events["kind"], ["stick", "slip"])]
    assert len(turns) > 0
    off_centre = np.abs((turns["crank_angle_deg"] + 90) % 180 - 90)
    assert off_centre.max() < 1, turns


def test_the_roller_refuses_friction(unpacked_fmu):
    """Model variant 2 is frictionless: a non-zero friction is refused at initialization, naming the parameter."""
    with Instance(unpacked_fmu) as fmu:
        with pytest.raises(FMICallException):
            fmu.initialize(model_variant=2, friction=0.1)
        assert any("friction" in m for m in fmu.messages(FMI_ERROR)), fmu.messages()


#: The default engine rubbing on a horizontal liner (mu = 0.1, gravity across the bore) with a free crank, no gas,
#: load or joint damping: what it dissipates is all impact and friction loss.
RUBBING_FREE = {
    "crank_mode": 2,
    "pressure_source": 1,
    "gas_pressure": 0.0,
    "load_torque": 0.0,
    "damping_main": 0.0,
    "damping_crank_pin": 0.0,
    "damping_piston_pin": 0.0,
    "friction": 0.1,
    "gravity_lateral": 9.81,
}
ENERGY_OUTPUTS = [
    "kinetic_energy",
    "potential_energy",
    "impact_energy_total",
    "friction_energy_total",
    "dissipated_energy_total",
]


@pytest.mark.parametrize("case", [FLORES, RUBBING_FREE], ids=["Flores as published", "rubbing engine"])
def test_energy_books_partition_the_dissipation(case):
    """Without drive, gas, load or damping, the impacts' normal (restitution) loss and all friction work add up to
    the drop in kinetic plus potential energy at every communication point, to 1e-7 of the initial energy E0, and
    dissipated_energy_total is their sum. On the Flores case 6.69 % of E0 is lost in 0.2 s."""
    result = simulate(stop_time=0.2, output_interval=1e-3, start_values=case, output=ENERGY_OUTPUTS)
    energy = result["kinetic_energy"] + result["potential_energy"]
    parts = result["impact_energy_total"] + result["friction_energy_total"]
    np.testing.assert_array_equal(result["dissipated_energy_total"], parts)
    assert np.abs(parts - (energy[0] - energy)).max() <= 1e-7 * energy[0]
    assert result["impact_energy_total"][-1] > 0 and result["friction_energy_total"][-1] > 0
    if case is FLORES:
        assert (energy[0] - energy[-1]) / energy[0] == pytest.approx(0.0669, abs=5e-4)


def test_kinetic_energy_at_the_start_is_the_free_cranks_start_speed():
    """Flores at q = 0 with the crank at 150 rad/s: the crank turns about its axis, the rod about the piston pin
    (at rest at TDC) at 150 l1/l2 = 75 rad/s, the slider tilts at -0.01 rad/s: T = 7.4956 J from the published
    masses and inertias, at t = 0 already (the state the first step starts from)."""
    result = simulate(
        stop_time=1e-3, output_interval=1e-3, start_values=FLORES, output=["kinetic_energy", "crank_speed_actual"]
    )
    l1, l2, m1, m2, j1, j2, j3 = 0.153, 0.306, 0.038, 0.038, 7.4e-5, 5.9e-4, 2.7e-6
    closed = 0.5 * (j1 + m1 * (l1 / 2) ** 2) * 150**2 + 0.5 * (j2 + m2 * (l2 / 2) ** 2) * 75**2 + 0.5 * j3 * 0.01**2
    assert result["crank_speed_actual"][0] == 150.0
    assert result["kinetic_energy"][0] == pytest.approx(closed, rel=1e-12)


BOOKS_OUTPUTS = [
    "kinetic_energy",
    "potential_energy",
    "film_relaxation_work",
    "drive_work_total",
    "gas_work_total",
    "damping_energy_total",
    "dissipated_energy_total",
]


@pytest.mark.parametrize(
    "case",
    [{"friction": 0.1}, {"crank_mode": 2, "friction": 0.1}, {"skirt_model": 2}, {"skirt_model": 2, "crank_mode": 2}],
    ids=["dry held", "dry free", "lubricated held", "lubricated free"],
)
def test_energy_books_close_from_the_outputs_with_drive_gas_and_damping(case):
    """The default engine over one cycle, its gas on the crown and its joint damping on: at every communication
    point dissipated_energy_total + film_relaxation_work = drive_work_total + gas_work_total − damping_energy_total
    less the rise of kinetic_energy + potential_energy, to 1e-4 of what was dissipated by the end (measured: 1e-5 dry
    held, 2e-7 in the others), from the end of the first step (the start's outputs show the state before the first
    step rebuilds it at the crank speed). Neither dissipated_energy_total nor damping_energy_total ever falls. Some
    10² J of gas work flow through drive and damping meanwhile."""
    result = simulate(stop_time=0.1, output_interval=1e-4, start_values=case, output=BOOKS_OUTPUTS)[1:]
    change = {name: result[name] - result[name][0] for name in BOOKS_OUTPUTS}
    work = change["drive_work_total"] + change["gas_work_total"] - change["damping_energy_total"]
    taken = change["dissipated_energy_total"] + change["film_relaxation_work"]
    residual = work - change["kinetic_energy"] - change["potential_energy"] - taken
    dissipated = change["dissipated_energy_total"][-1]
    assert abs(change["gas_work_total"][-1]) > 100 and change["damping_energy_total"][-1] > 10
    assert dissipated > 0 and np.abs(residual).max() < 1e-4 * dissipated, (np.abs(residual).max(), dissipated)
    assert np.all(np.diff(result["damping_energy_total"]) >= 0)
    assert np.all(np.diff(result["dissipated_energy_total"]) >= -1e-12 * dissipated)


def test_a_film_relaxation_too_long_for_the_motion_is_said_in_the_demo():
    """On the default oiled engine the film's relaxation term does a few 1e-4 of the film's dissipation, and the demo
    says nothing; a piston thrown at 2 m/s onto 0.1 mPa·s oil reaches the liner within film_relaxation, the term gives
    back most of what the film takes at the motion's rates, and the demo warns."""
    outputs = ["film_relaxation_work", "film_energy_total"]
    quiet = simulate(stop_time=0.1, start_values={"skirt_model": 2}, output=outputs)
    thrown = {"skirt_model": 2, "oil_viscosity": 1e-4, "piston_lateral_velocity_start": 2.0, "pressure_source": 1}
    loud = simulate(stop_time=0.02, output_interval=1e-4, start_values=thrown, output=outputs)
    assert abs(quiet["film_relaxation_work"][-1]) < 1e-3 * quiet["film_energy_total"][-1]
    assert -loud["film_relaxation_work"][-1] > 0.5 * loud["film_energy_total"][-1]
    assert demo.relaxation(quiet) is None
    assert "lower film_relaxation" in demo.relaxation(loud)
