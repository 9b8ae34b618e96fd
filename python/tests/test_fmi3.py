"""The FMI 3.0 FMUs PistonSlap3.fmu and EngineCycle3.fmu (`make fmu`: the FMI 2.0 FMUs' binary, the model description
in FMI 3.0's schema from the same table) through fmpy 0.3.32: they validate against FMI 3.0's schema, fmpy's
simulate_fmu gives FMI 2.0's results bit for bit at the same communication points, so does a coupled
EngineCycle3 → PistonSlap3 run, and an FMU state saved, serialized and restored through FMU3Slave continues
bit-identically."""

import functools
import itertools
import zipfile
from pathlib import Path

import fmpy
import numpy as np
import pytest
from fmpy.fmi2 import FMU2Slave
from fmpy.fmi3 import FMU3Slave
from fmpy.validation import validate_fmu

FMUS = Path(__file__).resolve().parents[1] / "pistonslap" / "fmu"
NAMES = ("PistonSlap", "EngineCycle")

_instances = (f"fmi3_test_{i}" for i in itertools.count())


def fmu(name, version):
    path = FMUS / f"{name}{'3' if version == 3 else ''}.fmu"
    assert path.is_file(), f"{path} is missing: `make fmu` builds it"
    return str(path)


def exact(values):
    """Raw float64 bytes: equality means bit-identical."""
    return np.asarray(values, dtype=float).tobytes()


@pytest.mark.parametrize("name", NAMES)
def test_the_fmi3_fmu_validates_and_carries_both_platforms(name):
    assert validate_fmu(fmu(name, 3)) == []
    md2, md3 = fmpy.read_model_description(fmu(name, 2)), fmpy.read_model_description(fmu(name, 3))
    assert md3.fmiVersion == "3.0" and md3.guid == md2.guid
    with zipfile.ZipFile(fmu(name, 3)) as archive:
        binaries = {n for n in archive.namelist() if n.startswith("binaries/")}
    assert binaries == {f"binaries/x86_64-linux/{name}.so", f"binaries/x86_64-windows/{name}.dll"}
    cs = md3.coSimulation
    assert cs.canGetAndSetFMUstate and cs.canSerializeFMUstate and cs.canHandleVariableCommunicationStepSize
    assert not cs.hasEventMode and not cs.canReturnEarlyAfterIntermediateUpdate
    # The same variables with the same value references, and the independent variable time beyond them.
    table2 = {v.name: (v.valueReference, v.causality, v.unit, v.start) for v in md2.modelVariables}
    table3 = {v.name: (v.valueReference, v.causality, v.unit, v.start) for v in md3.modelVariables}
    assert table3.pop("time") == (len(table2), "independent", "s", None)
    assert table3 == table2


@pytest.mark.parametrize("name", NAMES)
def test_the_default_experiment_gives_fmi2s_results_bit_for_bit(name):
    names = outputs(name)
    fmi2, fmi3 = (fmpy.simulate_fmu(fmu(name, version), output=names) for version in (2, 3))
    assert len(fmi3) == len(fmi2) > 100
    for column in ["time", *names]:
        assert exact(fmi3[column]) == exact(fmi2[column]), column


def test_early_return_allowed_changes_nothing_and_event_mode_is_refused():
    """The FMUs never return early (canReturnEarlyAfterIntermediateUpdate = false): allowed, the run is FMI 2.0's; they
    have no Event Mode (hasEventMode = false), so an instantiation that asks for it is refused, as the standard says."""
    fmi2 = fmpy.simulate_fmu(fmu("PistonSlap", 2), stop_time=0.02)
    allowed = fmpy.simulate_fmu(fmu("PistonSlap", 3), stop_time=0.02, early_return_allowed=True)
    assert all(exact(allowed[c]) == exact(fmi2[c]) for c in fmi2.dtype.names)
    messages = []
    with pytest.raises(Exception, match="Failed to instantiate"):
        fmpy.simulate_fmu(fmu("PistonSlap", 3), use_event_mode=True, logger=lambda *args: messages.append(args[-1]))
    assert any(b"eventModeUsed = true refused" in m for m in messages), messages


class Slave:
    """One instance of either version's FMU through fmpy, with the calls a master makes by variable name."""

    def __init__(self, name, version, tmp_path, **start_values):
        path = fmu(name, version)
        md = fmpy.read_model_description(path)
        self.variables = {v.name: v for v in md.modelVariables}
        self.name, self.version = name, version
        instance = next(_instances)
        self.fmu = (FMU3Slave if version == 3 else FMU2Slave)(
            guid=md.guid,
            unzipDirectory=fmpy.extract(path, unzipdir=tmp_path / instance),
            modelIdentifier=md.coSimulation.modelIdentifier,
            instanceName=instance,
        )
        self.fmu.instantiate()
        if version == 3:
            self.fmu.enterInitializationMode(startTime=0.0)
        else:
            self.fmu.setupExperiment(startTime=0.0)
            self.fmu.enterInitializationMode()
        self.set(**start_values)

    def vr(self, names):
        return [self.variables[n].valueReference for n in names]

    def set(self, **values):
        for name, value in values.items():
            integer = self.variables[name].type in ("Integer", "Int32")
            if self.version == 3:
                setter = self.fmu.setInt32 if integer else self.fmu.setFloat64
            else:
                setter = self.fmu.setInteger if integer else self.fmu.setReal
            setter(self.vr([name]), [value])

    def get(self, names):
        """The named variables, each as a float (Integers exactly)."""
        reals = [n for n in names if self.variables[n].type in ("Real", "Float64")]
        integers = [n for n in names if n not in reals]
        get_real, get_integer = (
            (self.fmu.getFloat64, self.fmu.getInt32) if self.version == 3 else (self.fmu.getReal, self.fmu.getInteger)
        )
        values = dict(zip(reals, get_real(self.vr(reals)), strict=True))
        values.update(zip(integers, get_integer(self.vr(integers)), strict=True))
        return [float(values[n]) for n in names]

    def step(self, t, h):
        self.fmu.doStep(currentCommunicationPoint=t, communicationStepSize=h)

    def outputs(self):
        return outputs(self.name)


@functools.cache
def outputs(name):
    """The FMU's outputs by name, in the table's order."""
    return [v.name for v in fmpy.read_model_description(fmu(name, 2)).modelVariables if v.causality == "output"]


def coupled(version, tmp_path, steps=200, h=5e-4):
    """EngineCycle driving PistonSlap (inputs held over each step): every PistonSlap output after each step."""
    engine = Slave("EngineCycle", version, tmp_path)
    slap = Slave("PistonSlap", version, tmp_path, pressure_source=1)
    wires = ["crank_speed", "gas_pressure"]
    try:
        engine.fmu.exitInitializationMode()
        slap.set(**dict(zip(wires, engine.get(wires), strict=True)))
        slap.fmu.exitInitializationMode()
        rows = []
        for k in range(steps):
            slap.set(**dict(zip(wires, engine.get(wires), strict=True)))
            engine.step(k * h, h)
            slap.step(k * h, h)
            rows.append(slap.get(slap.outputs()))
        return rows
    finally:
        engine.fmu.freeInstance()
        slap.fmu.freeInstance()


def test_a_coupled_run_gives_the_fmi2_pairs_results_bit_for_bit(tmp_path):
    fmi2, fmi3 = coupled(2, tmp_path), coupled(3, tmp_path)
    impacts = np.array(fmi3)[:, outputs("PistonSlap").index("impact_count")]
    assert impacts[-1] > impacts[0], "the run holds impacts"
    assert exact(fmi3) == exact(fmi2)


def test_a_state_restored_and_deserialized_through_fmu3slave_continues_bit_identically(tmp_path):
    h, before, after = 1e-4, 300, 200
    slap = Slave("PistonSlap", 3, tmp_path)
    slap.fmu.exitInitializationMode()
    names = slap.outputs()
    for k in range(before):
        slap.step(k * h, h)
    state = slap.fmu.getFMUState()
    serialized = slap.fmu.serializeFMUState(state)
    saved_at = slap.get(["time"])

    def go_on(instance):
        rows = []
        for k in range(before, before + after):
            instance.step(k * h, h)
            rows.append(instance.get(names))
        return rows

    straight = go_on(slap)
    assert straight[-1][names.index("impact_count")] > straight[0][names.index("impact_count")]
    slap.fmu.setFMUState(state)
    assert exact(go_on(slap)) == exact(straight)
    slap.fmu.freeFMUState(state)
    other = Slave("PistonSlap", 3, tmp_path)
    other.fmu.exitInitializationMode()
    other.fmu.setFMUState(other.fmu.deserializeFMUState(serialized))
    assert other.get(["time"]) == saved_at
    assert exact(go_on(other)) == exact(straight)
    for instance in (slap, other):
        instance.fmu.terminate()
        instance.fmu.freeInstance()
