"""The co-simulation master of PistonSlap and EngineCycle on fmpy's `FMU2Slave`: each cylinder a PistonSlap
instance driven by its own EngineCycle instance, any number of cylinders in one process.

At each communication point t_k = t_0 + k h the master reads EngineCycle's `crank_speed` and `gas_pressure`,
sets them as PistonSlap's inputs (with `pressure_source = 1`) and, with `derivatives=True`, passes their
first time derivatives (`fmi2GetRealOutputDerivatives`) on as input derivatives
(`fmi2SetRealInputDerivatives`), so that PistonSlap's inputs follow the engine's slope over the step instead of
being held. Then both FMUs step to t_{k+1}. EngineCycle has no inputs, so the order of the two steps does not
matter.
"""

import shutil
from pathlib import Path

import fmpy
import numpy as np
from fmpy.fmi2 import FMU2Slave

from .fmu import fmu_path

#: The partner FMU the package carries next to PistonSlap.fmu (`make fmu` copies both).
ENGINE_FMU = Path(__file__).resolve().parent / "fmu" / "EngineCycle.fmu"

#: (EngineCycle output, PistonSlap input).
WIRES = (("crank_speed", "crank_speed"), ("gas_pressure", "gas_pressure"))

#: Columns of a coupled run, one row per communication point.
COLUMNS = (
    "time",
    "engine_crank_angle",
    "engine_crank_speed",
    "gas_pressure",
    "crank_angle",
    "gas_pressure_acting",
    "piston_lateral",
    "impact_count",
    "impacts_in_step",
    "max_impact_velocity_in_step",
    "impact_energy_total",
)


class Extracted:
    """An FMU unpacked once for any number of instances: they share its one loaded library, as the instances of a
    host's process do."""

    def __init__(self, path):
        self.description = fmpy.read_model_description(str(path))
        self.variables = {v.name: v for v in self.description.modelVariables}
        self.unzipdir = fmpy.extract(str(path))

    def remove(self):
        shutil.rmtree(self.unzipdir, ignore_errors=True)


class Slave:
    """One FMU instance stepped by the master: fmpy's FMU2Slave on an `Extracted` FMU, value references by name."""

    def __init__(self, extracted, name, start_values, start_time):
        self.variables = extracted.variables
        self.fmu = FMU2Slave(
            guid=extracted.description.guid,
            unzipDirectory=extracted.unzipdir,
            modelIdentifier=extracted.description.coSimulation.modelIdentifier,
            instanceName=name,
        )
        self.fmu.instantiate()
        self.fmu.setupExperiment(startTime=start_time)
        self.fmu.enterInitializationMode()
        for name_, value in start_values.items():
            self.set(name_, value)

    def vrs(self, names):
        return [self.variables[n].valueReference for n in names]

    def set(self, name, value):
        v = self.variables[name]
        {"Real": self.fmu.setReal, "Integer": self.fmu.setInteger, "String": self.fmu.setString}[v.type](
            [v.valueReference], [value]
        )

    def free(self):
        self.fmu.terminate()
        self.fmu.freeInstance()


class Cylinder:
    """A PistonSlap instance driven by its EngineCycle instance (both in initialization mode), recording `COLUMNS`
    and the PistonSlap outputs `recorded` (its Real ones first, then its Integer ones) at `points` communication
    points."""

    def __init__(self, engine, slap, recorded, points):
        self.engine, self.slap = engine, slap
        self.outputs = engine.vrs([w[0] for w in WIRES])
        self.inputs = slap.vrs([w[1] for w in WIRES])
        self.engine_read = engine.vrs(["crank_angle", "crank_speed", "gas_pressure"])
        real = [n for n in recorded if slap.variables[n].type == "Real"]
        integer = [n for n in recorded if slap.variables[n].type == "Integer"]
        self.slap_real = slap.vrs(
            [
                "crank_angle",
                "gas_pressure_acting",
                "piston_lateral",
                "max_impact_velocity_in_step",
                "impact_energy_total",
                *real,
            ]
        )
        self.slap_int = slap.vrs(["impact_count", "impacts_in_step", *integer])
        self.rows = np.zeros(
            points, dtype=[(c, "f8") for c in COLUMNS] + [(n, "f8") for n in real] + [(n, "i8") for n in integer]
        )

    def initialize(self):
        self.engine.fmu.exitInitializationMode()
        self.slap.fmu.setReal(self.inputs, self.engine.fmu.getReal(self.outputs))
        self.slap.fmu.exitInitializationMode()

    def step(self, t, step, derivatives):
        """Passes the engine's outputs (and with `derivatives` their slopes) on, then steps both from `t`."""
        self.slap.fmu.setReal(self.inputs, self.engine.fmu.getReal(self.outputs))
        if derivatives:
            orders = [1] * len(WIRES)
            self.slap.fmu.setRealInputDerivatives(
                self.inputs, orders, self.engine.fmu.getRealOutputDerivatives(self.outputs, orders)
            )
        self.engine.fmu.doStep(t, step)
        self.slap.fmu.doStep(t, step)

    def record(self, k, t):
        a, w, p = self.engine.fmu.getReal(self.engine_read)
        angle, acting, lateral, vmax, energy, *real = self.slap.fmu.getReal(self.slap_real)
        count, in_step, *integer = self.slap.fmu.getInteger(self.slap_int)
        self.rows[k] = (t, a, w, p, angle, acting, lateral, count, in_step, vmax, energy, *real, *integer)


def run(stop_time, step, engine_values=None, slap_values=None, derivatives=True, start_time=0.0, step_finished=None):
    """Runs the coupled system from `start_time` to `stop_time` with communication step `step` (s).

    `engine_values` and `slap_values` are start values by name; PistonSlap always gets `pressure_source = 1`.
    With `derivatives`, the engine's output derivatives are passed on as PistonSlap's input derivatives.
    `step_finished(time)` is called after each step (a progress line). Returns a structured array with `COLUMNS`,
    one row per communication point including the start.
    """
    (rows,) = run_cylinders(
        stop_time, step, [(engine_values or {}, slap_values or {})], derivatives, start_time, step_finished
    )
    return rows


def run_cylinders(stop_time, step, cylinders, derivatives=True, start_time=0.0, step_finished=None, recorded=()):
    """`run` for several cylinders in one process: `cylinders` holds each one's `(engine_values, slap_values)`,
    each a PistonSlap instance driven by its own EngineCycle instance, all instances of one FMU sharing its loaded
    library and stepped in turn at each communication point (instances named engine_1, slap_1, ..., or engine and
    slap for one cylinder). Returns one structured array per cylinder: `COLUMNS`, then the
    PistonSlap outputs `recorded`.
    """
    steps = round((stop_time - start_time) / step)
    if steps < 1 or abs(start_time + steps * step - stop_time) > 1e-9 * max(1.0, abs(stop_time)):
        raise ValueError(f"stop_time - start_time = {stop_time - start_time} s is not a whole number of {step} s steps")
    names = [""] if len(cylinders) == 1 else [f"_{k}" for k in range(1, len(cylinders) + 1)]
    engine_fmu, slap_fmu = Extracted(ENGINE_FMU), Extracted(fmu_path())
    slaves, pairs = [], []
    try:
        for name, (engine_values, slap_values) in zip(names, cylinders, strict=True):
            slaves.append(Slave(engine_fmu, f"engine{name}", engine_values, start_time))
            slaves.append(Slave(slap_fmu, f"slap{name}", {**slap_values, "pressure_source": 1}, start_time))
            pairs.append(Cylinder(*slaves[-2:], recorded, steps + 1))
        for pair in pairs:
            pair.initialize()
            pair.record(0, start_time)
        for k in range(steps):
            t, reached = start_time + k * step, start_time + (k + 1) * step
            for pair in pairs:
                pair.step(t, step, derivatives)
                pair.record(k + 1, reached)
            if step_finished is not None:
                step_finished(reached)
        return [pair.rows for pair in pairs]
    finally:
        for slave in slaves:
            slave.free()
        engine_fmu.remove()
        slap_fmu.remove()
