"""The gasoline car preset: its US-customary source numbers converted to SI reproduce the source's own dimensionless
groups, the engine slaps on both walls at 3000 rpm with the piston kept within its clearance, and a pin offset toward
the major-thrust side changes the power-stroke slap over as offset pistons are designed to."""

import numpy as np
import pytest
from fmpy.fmi1 import FMICallException

from pistonslap.fmu import simulate, simulate_with_events
from pistonslap.presets import PRESETS
from pistonslap.tables import side_changes

from harness import FMI_ERROR, Instance

CAR = PRESETS["ford-gasoline"].values


def test_the_converted_numbers_give_farahanchis_dimensionless_groups():
    """Farahanchi (1991) section 4.1 prints ξ = r/l = 0.3030, α = m/M = 1.9000 and β = J/(M l²) = 0.4719 for these
    numbers; unit for unit his inputs give β = 0.47173, so β holds to the table's rounding (3e-4)."""
    assert CAR["crank_radius"] / CAR["rod_length"] == pytest.approx(0.3030, abs=5e-5)
    assert CAR["rod_mass"] / CAR["piston_mass"] == pytest.approx(1.9000, abs=5e-5)
    beta = CAR["rod_inertia"] / (CAR["piston_mass"] * CAR["rod_length"] ** 2)
    assert beta == pytest.approx(0.4719, abs=3e-4)


def test_the_car_engine_slaps_on_both_walls_at_3000_rpm():
    """Two engine cycles at 3000 rpm (built-in 80 bar curve): the second has slaps on both walls, the piston
    centre stays within the radial clearance (40 µm) to the event tolerance."""
    omega = 3000 * np.pi / 30
    values = dict(CAR, crank_speed=omega)
    result = simulate(
        stop_time=2 * 4 * np.pi / omega + 1e-4,
        output_interval=1e-4,
        start_values=values,
        output=["piston_lateral", "cycle_slaps_thrust", "cycle_slaps_antithrust", "cycle_impacts"],
    )
    last = result[-1]
    assert last["cycle_slaps_thrust"] >= 1 and last["cycle_slaps_antithrust"] >= 1, last
    assert last["cycle_impacts"] >= last["cycle_slaps_thrust"] + last["cycle_slaps_antithrust"]
    assert np.abs(result["piston_lateral"]).max() <= 40e-6 + 1e-10


def power_stroke_landing(pin_offset, rpm):
    """The first landing on the major-thrust wall within 30° of the second firing TDC (one engine cycle after the
    start, which is the first, the piston centred): (crank angle from that firing TDC in degrees, corner)."""
    omega = rpm * np.pi / 30
    cycle = 4 * np.pi / omega
    window = np.radians(30) / omega
    _, events = simulate_with_events(
        start_values=dict(CAR, crank_speed=omega, pin_offset=pin_offset),
        stop_time=cycle + window,
        output_interval=1e-4,
        output=["cycle_count"],
    )
    thrust = side_changes(events) & (events["corner"] >= 3) & (np.abs(events["time"] - cycle) < window)
    first = events[thrust][0]
    return np.degrees((first["time"] - cycle) * omega), first["corner"]


@pytest.mark.parametrize("rpm", [1200, 3000])
def test_a_thrust_side_pin_offset_changes_over_earlier_on_the_lower_skirt(rpm):
    """Offsetting the pin 1 mm toward the major-thrust side (pin_offset > 0) is meant to move the power-stroke side
    change earlier, toward the low pressure before combustion, the piston tilted so that the lower end of the skirt
    (K4) reaches the thrust wall first. The centred pin and the opposite offset land later; the opposite offset
    leads with the upper corner (K3)."""
    toward, centred, away = (power_stroke_landing(offset, rpm) for offset in (1e-3, 0.0, -1e-3))
    assert toward[0] < min(centred[0], away[0]) - 1.0, (toward, centred, away)
    assert toward[1] == 4 and away[1] == 3, (toward, away)


def test_the_running_clearance_of_the_hot_car_engine_is_the_hand_calculation():
    """At 100 °C from 20 °C the 80 mm piston grows 0.08 × 21e-6 × 80 = 134.4 µm and the 80.08 mm bore
    0.08008 × 11e-6 × 80 = 70.4704 µm: 80 + 70.4704 − 134.4 = 16.0704 µm of running clearance, on both skirt models."""
    for skirt_model in (1, 2):
        values = dict(PRESETS["ford-gasoline-hot"].values, skirt_model=skirt_model)
        result = simulate(stop_time=1e-4, output_interval=1e-4, start_values=values, output=["running_clearance"])
        assert result["running_clearance"][-1] == pytest.approx(16.0704e-6, abs=1e-15)
    cold = simulate(stop_time=1e-4, output_interval=1e-4, start_values=CAR, output=["running_clearance"])
    assert cold["running_clearance"][-1] == pytest.approx(80e-6, abs=1e-15)


def test_a_piston_too_hot_for_its_bore_is_refused_at_initialization(unpacked_fmu):
    """The skirt at 150 °C in the 100 °C liner: 0.08 × 21e-6 × 130 = 218.4 µm of growth against the bore's 70.4704 µm
    and the 80 µm clearance, −67.9296 µm: fmi2ExitInitializationMode refuses it, naming the temperatures."""
    with Instance(unpacked_fmu) as fmu:
        fmu.slave.setupExperiment(startTime=0.0)
        fmu.set(**dict(PRESETS["ford-gasoline-hot"].values, piston_temperature=423.15))
        fmu.slave.enterInitializationMode()
        with pytest.raises(FMICallException) as refusal:
            fmu.slave.exitInitializationMode()
        assert refusal.value.status == FMI_ERROR
        message = fmu.messages(FMI_ERROR)[-1]
    assert message.startswith("fmi2ExitInitializationMode") and "m ≤ 0" in message, message
    clearance = float(message.split("running clearance ")[1].split(" m")[0])
    assert clearance == pytest.approx(-67.9296e-6, abs=1e-15), message
    assert "piston_temperature = 423.15 K" in message and "liner_temperature = 373.15 K" in message, message
