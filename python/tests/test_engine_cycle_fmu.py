"""EngineCycle.fmu through fmpy: each FMU's binary refuses the other FMU's GUID, an implausible cycle is refused
with its reason, fmpy's validation finds nothing, and the presets give the indicated efficiencies and peak
pressures published for such engines."""

import fmpy
import numpy as np
import pytest
from fmpy.fmi1 import FMICallException
from fmpy.validation import validate_fmu

from pistonslap.engine_cycle_presets import PRESETS
from pistonslap.master import ENGINE_FMU

from harness import FMI_ERROR, Instance


@pytest.fixture(scope="module")
def unpacked_engine(tmp_path_factory):
    unzipdir = fmpy.extract(str(ENGINE_FMU), unzipdir=tmp_path_factory.mktemp("engine"))
    return str(unzipdir), fmpy.read_model_description(str(ENGINE_FMU))


def refused_guid(fmu, guid):
    instance = Instance(fmu, guid=guid)
    with pytest.raises(Exception, match="Failed to instantiate"):  # fmi2Instantiate returned NULL
        instance.__enter__()
    messages = instance.messages(FMI_ERROR)
    instance.slave.freeLibrary()
    return messages


def test_each_binary_refuses_the_other_fmus_guid(unpacked_engine, unpacked_fmu):
    engine_guid, slap_guid = unpacked_engine[1].guid, unpacked_fmu[1].guid
    messages = refused_guid(unpacked_engine, slap_guid)
    assert any(
        f"fmuGUID {slap_guid} does not match this binary's {engine_guid}: it instantiates EngineCycle only" in m
        for m in messages
    ), messages
    messages = refused_guid(unpacked_fmu, engine_guid)
    assert any(
        f"fmuGUID {engine_guid} does not match this binary's {slap_guid}: it instantiates PistonSlap only" in m
        for m in messages
    ), messages


@pytest.mark.parametrize(
    "values, reason",
    [
        ({"heat_release": 1e9}, "heat_release = 1000000000 J is implausible"),
        ({"intake_pressure": 3e5, "compression_ratio": 22.0, "heat_release": 3800.0}, "exceeds 300 bar"),
        ({"intake_temperature": 1000.0}, "intake_temperature = 1000 K is out of range"),
    ],
)
def test_an_implausible_cycle_is_refused_with_its_reason(unpacked_engine, values, reason):
    with Instance(unpacked_engine) as fmu:
        fmu.slave.setupExperiment(startTime=0.0)
        fmu.set(**values)
        fmu.slave.enterInitializationMode()
        with pytest.raises(FMICallException):
            fmu.slave.exitInitializationMode()
        assert any(reason in m for m in fmu.messages(FMI_ERROR)), fmu.messages()


def test_fmpy_validation_finds_nothing_and_the_documentation_is_packed():
    assert validate_fmu(str(ENGINE_FMU)) == []
    import zipfile

    with zipfile.ZipFile(ENGINE_FMU) as z:
        page = z.read("documentation/index.html").decode()
    for text in ("Woschni", "GRI-Mech 3.0", "linux64", "<code>wall_heat_total</code>"):
        assert text in page, text


def one_cycle(values):
    """A fired cycle at 0.1° resolution: (indicated efficiency, peak pressure in Pa, its angle after TDC in deg)."""
    speed = values["speed_start"]
    period = 4 * np.pi / speed
    result = fmpy.simulate_fmu(
        str(ENGINE_FMU),
        start_values=values,
        stop_time=period,
        output_interval=period / 7200,
        output=["crank_angle", "indicated_torque", "cylinder_pressure"],
    )
    angle, torque = result["crank_angle"], result["indicated_torque"]
    work = np.sum(0.5 * (torque[1:] + torque[:-1]) * np.diff(angle))
    k = np.argmax(result["cylinder_pressure"])
    return work / values["heat_release"], result["cylinder_pressure"][k], np.degrees(angle[k])


# Bounds on what the presets give, and where each comes from:
# - peak-pressure angle of the spark-ignition engine 5-15° after TDC: where its thermal efficiency is highest
#   (Journal of Combustion 2011, article 678719, abstract: a two-zone Wiebe model checked against experiments);
# - peak pressure of the turbocharged diesel up to 210 bar: the peak pressures modern passenger-car diesel engines
#   are designed for (MAHLE, passenger-car diesel pistons, product description);
# - the efficiencies (SI 0.35-0.40, diesel 0.42-0.50), the SI peak pressure 50-70 bar, the diesel's lower bound
#   130 bar and its peak angle 5-20° are those of Heywood (1988) ch. 9 and 10 as the presets' author recalled them:
#   no public source read here states them.
PUBLISHED = {
    "gasoline-na": {"efficiency": (0.35, 0.40), "peak_bar": (50, 70), "peak_deg": (5, 15)},
    "diesel-turbo": {"efficiency": (0.42, 0.50), "peak_bar": (130, 210), "peak_deg": (5, 20)},
}


@pytest.mark.parametrize("name", sorted(PRESETS))
def test_presets_fire_in_the_published_ranges(name):
    efficiency, peak, at = one_cycle(PRESETS[name]["engine"])
    ranges = PUBLISHED[name]
    print(f"{name}: indicated efficiency {efficiency:.3f}, peak {peak / 1e5:.1f} bar at {at:.1f}° after TDC")
    assert ranges["efficiency"][0] <= efficiency <= ranges["efficiency"][1]
    assert ranges["peak_bar"][0] <= peak / 1e5 <= ranges["peak_bar"][1]
    assert ranges["peak_deg"][0] <= at <= ranges["peak_deg"][1]


def test_an_unknown_preset_is_refused_in_one_line(tmp_path):
    import subprocess
    import sys
    from pathlib import Path

    pistonslap = Path(sys.executable).parent / "pistonslap"
    done = subprocess.run(
        [str(pistonslap), "coupled", "--engine", "steam", "--out", str(tmp_path)], capture_output=True, text=True
    )
    assert done.returncode == 2
    assert done.stderr.strip() == "pistonslap coupled: unknown --engine 'steam' (presets: gasoline-na, diesel-turbo)"
