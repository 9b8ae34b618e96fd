"""Driving the packaged FMU call by call through fmpy's FMU2Slave, with its log messages captured."""

import itertools
from ctypes import byref

from fmpy.fmi2 import (
    FMU2Slave,
    calloc,
    fmi2CallbackAllocateMemoryTYPE,
    fmi2CallbackFreeMemoryTYPE,
    fmi2CallbackFunctions,
    fmi2CallbackLoggerTYPE,
    free,
)
from fmpy.logging import addLoggerProxy

#: Every message any instance logged in this process: (instance name, status, category, message).
LOG = []


def _collect(_env, instance_name, status, category, message):
    LOG.append((instance_name.decode(), status, (category or b"").decode(), (message or b"").decode()))


# fmpy's native proxy formats the variadic message and forwards it to one process-wide Python logger:
# install ours once and tell the instances apart by name. The callbacks must outlive every instance.
CALLBACKS = fmi2CallbackFunctions()
CALLBACKS.logger = fmi2CallbackLoggerTYPE(_collect)
CALLBACKS.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
CALLBACKS.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
addLoggerProxy(byref(CALLBACKS))

_names = (f"pistonslap_test_{i}" for i in itertools.count())

FMI_ERROR = 3


class Instance:
    """One FMU instance: `with Instance(fmu) as s:` instantiates it and frees it afterwards.

    `fmu` is the `unpacked_fmu` fixture: (unzip directory, model description).
    """

    def __init__(self, fmu, guid=None):
        unzipdir, self.md = fmu
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        self.types = {v.name: v.type for v in self.md.modelVariables}
        self.name = next(_names)
        self.slave = FMU2Slave(
            guid=self.md.guid if guid is None else guid,
            unzipDirectory=unzipdir,
            modelIdentifier=self.md.coSimulation.modelIdentifier,
            instanceName=self.name,
        )
        self.time = 0.0

    def __enter__(self):
        self.slave.instantiate(callbacks=CALLBACKS, loggingOn=True)
        return self

    def __exit__(self, *exc):
        self.slave.freeInstance()

    def messages(self, min_status=0):
        """What this instance logged with at least `min_status` (3 = error)."""
        return [m for name, status, _, m in LOG if name == self.name and status >= min_status]

    def set(self, **values):
        for name, value in values.items():
            setter = {
                "Real": self.slave.setReal,
                "Integer": self.slave.setInteger,
                "Boolean": self.slave.setBoolean,
                "String": self.slave.setString,
            }[self.types[name]]
            setter([self.vr[name]], [value])

    def get(self, *names):
        """Values of the named variables, in order (a Real output is a float, an Integer output an int)."""
        getters = {"Real": self.slave.getReal, "Integer": self.slave.getInteger}
        return [getters[self.types[n]]([self.vr[n]])[0] for n in names]

    def initialize(self, start_time=0.0, **values):
        """setupExperiment, start values, initialization mode: the instance is then in step mode at `start_time`."""
        self.slave.setupExperiment(startTime=start_time)
        self.set(**values)
        self.slave.enterInitializationMode()
        self.slave.exitInitializationMode()
        self.time = start_time
        return self

    def step(self, h, n=1, record=()):
        """`n` steps of size `h` from the current time; returns the `record`ed variables after each step."""
        rows = []
        for _ in range(n):
            self.slave.doStep(currentCommunicationPoint=self.time, communicationStepSize=h)
            self.time += h
            rows.append(self.get(*record))
        return rows
