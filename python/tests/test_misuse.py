"""A host that misuses the FMU gets fmi2Error and a log message through fmpy, never a crash.

These run in the pytest process on purpose: a crash in the FMU would end the whole test run."""

import math

import pytest
from fmpy.fmi1 import FMICallException

from harness import FMI_ERROR, Instance

H = 1e-3


def refused(call, *args, **kwargs):
    """The call fails with fmi2Error (not fmi2Fatal, which would mean a caught panic)."""
    with pytest.raises(FMICallException) as info:
        call(*args, **kwargs)
    assert info.value.status == FMI_ERROR, info.value
    return info.value


@pytest.fixture
def stepping(unpacked_fmu):
    with Instance(unpacked_fmu) as fmu:
        fmu.initialize()
        fmu.step(H, 20)
        yield fmu


@pytest.mark.parametrize("name", ["crank_speed", "gas_pressure", "load_torque"])
@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf])
def test_non_finite_input_is_refused_and_the_state_restorable(stepping, unpacked_fmu, name, value):
    fmu = stepping
    state, t = fmu.slave.getFMUstate(), fmu.time
    try:
        fmu.set(**{name: value})
    except FMICallException as refusal:  # refused when set, or else at the next step
        assert refusal.status == FMI_ERROR
    else:
        refused(fmu.slave.doStep, currentCommunicationPoint=t, communicationStepSize=H)
    assert any(name in m for m in fmu.messages(FMI_ERROR)), fmu.messages()
    # the standard's way out of fmi2Error: restore a state taken before it, then carry on
    fmu.slave.setFMUstate(state)
    fmu.time = t
    record = ("crank_angle", "piston_lateral", "impact_count")
    with Instance(unpacked_fmu) as untouched:
        untouched.initialize()
        untouched.step(H, 20)
        assert fmu.step(H, 10, record) == untouched.step(H, 10, record)


@pytest.mark.parametrize("step", [-H, math.nan, math.inf])
def test_bad_step_size_is_refused(stepping, step):
    refused(stepping.slave.doStep, currentCommunicationPoint=stepping.time, communicationStepSize=step)
    assert stepping.messages(FMI_ERROR)


@pytest.mark.parametrize("offset", [H, -H, math.nan])
def test_step_from_another_time_is_refused(stepping, offset):
    refused(stepping.slave.doStep, currentCommunicationPoint=stepping.time + offset, communicationStepSize=H)
    assert stepping.messages(FMI_ERROR)


def test_step_before_initialization_is_refused(unpacked_fmu):
    with Instance(unpacked_fmu) as fmu:
        refused(fmu.slave.doStep, currentCommunicationPoint=0.0, communicationStepSize=H)
        assert fmu.messages(FMI_ERROR)


def test_step_in_initialization_mode_is_refused(unpacked_fmu):
    with Instance(unpacked_fmu) as fmu:
        fmu.slave.setupExperiment(startTime=0.0)
        fmu.slave.enterInitializationMode()
        refused(fmu.slave.doStep, currentCommunicationPoint=0.0, communicationStepSize=H)
        assert fmu.messages(FMI_ERROR)


def test_step_after_terminate_is_refused(stepping):
    stepping.slave.terminate()
    refused(stepping.slave.doStep, currentCommunicationPoint=stepping.time, communicationStepSize=H)
    assert stepping.messages(FMI_ERROR)


def test_exit_initialization_without_entering_is_refused(unpacked_fmu):
    with Instance(unpacked_fmu) as fmu:
        fmu.slave.setupExperiment(startTime=0.0)
        refused(fmu.slave.exitInitializationMode)
        assert fmu.messages(FMI_ERROR)


def test_fixed_parameter_cannot_change_while_stepping(stepping):
    refused(stepping.set, restitution=0.9)
    assert stepping.messages(FMI_ERROR)


def test_wrong_guid_is_refused_at_instantiation(unpacked_fmu):
    fmu = Instance(unpacked_fmu, guid="{00000000-0000-0000-0000-000000000000}")
    with pytest.raises(Exception, match="Failed to instantiate"):  # fmi2Instantiate returned NULL
        fmu.__enter__()
    assert any("guid" in m.lower() for m in fmu.messages(FMI_ERROR)), fmu.messages()
    fmu.slave.freeLibrary()


@pytest.mark.parametrize(
    "call",
    [
        lambda slave, vr: slave.getReal([vr]),
        lambda slave, vr: slave.getInteger([vr]),
        lambda slave, vr: slave.setReal([vr], [0.0]),
    ],
    ids=["getReal", "getInteger", "setReal"],
)
def test_unknown_value_reference_is_refused(stepping, call):
    refused(call, stepping.slave, max(stepping.vr.values()) + 1000)
    assert stepping.messages(FMI_ERROR)


def corruptions(serialized):
    yield b"not a PistonSlap state" * 4
    yield serialized[: len(serialized) // 2]
    yield bytes(len(serialized))
    yield b""


def test_corrupt_serialized_state_is_refused(stepping):
    state = stepping.slave.getFMUstate()
    serialized = stepping.slave.serializeFMUstate(state)
    stepping.slave.freeFMUstate(state)
    for corrupt in corruptions(serialized):
        refused(stepping.slave.deSerializeFMUstate, corrupt)
    assert stepping.messages(FMI_ERROR)


@pytest.mark.parametrize(
    "name, value, named",
    [
        ("piston_mass", -0.4, ["piston_mass"]),
        ("rod_length", -0.15, ["rod_length"]),
        ("skirt_length", -0.01, ["skirt_length"]),
        ("restitution", 1.5, ["restitution"]),
        ("restitution", -0.1, ["restitution"]),
        ("bore", 0.0799, ["bore", "piston_diameter"]),  # smaller than the piston (0.08 m)
        ("crank_radius", 0.2, ["crank_radius", "rod_length"]),  # longer than the rod (0.15 m)
    ],
)
def test_out_of_range_parameter_is_refused_at_exit_initialization(unpacked_fmu, name, value, named):
    """The log message names the parameter (or, for a relation between two, one of them)."""
    with Instance(unpacked_fmu) as fmu:
        fmu.slave.setupExperiment(startTime=0.0)
        fmu.set(**{name: value})
        fmu.slave.enterInitializationMode()
        refused(fmu.slave.exitInitializationMode)
        assert any(n in m for m in fmu.messages(FMI_ERROR) for n in named), fmu.messages()
