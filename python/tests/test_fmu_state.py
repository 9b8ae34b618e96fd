"""getFMUstate / setFMUstate / (de)serialization through fmpy: a restored state continues bit-identically,
event history included. The state is taken at 30 ms (crank angle ≈ 216°); the 20 ms compared after it hold impacts."""

import numpy as np
import pytest

from harness import Instance

H = 1e-4
BEFORE, AFTER = 300, 200  # steps before the state is taken, steps compared after it
RECORD = (
    "piston_lateral",
    "piston_lateral_velocity",
    "piston_tilt",
    "crank_angle",
    "crank_torque",
    "side_force",
    "impact_count",
    "impacts_in_step",
    "impact_velocity",
    "impact_energy_total",
    "contact_state_1",
    "contact_force_1",
    "contact_state_4",
    "contact_force_4",
)


def exact(rows):
    """The rows as raw bytes of float64, so that equality means bit-identical (and NaN would compare)."""
    return np.array(rows, dtype=float).tobytes()


@pytest.fixture
def started(unpacked_fmu):
    with Instance(unpacked_fmu) as fmu:
        fmu.initialize()
        fmu.step(H, BEFORE)
        yield fmu


def test_restored_state_continues_bit_identically(started):
    fmu = started
    state = fmu.slave.getFMUstate()
    t, (count,) = fmu.time, fmu.get("impact_count")
    original = fmu.step(H, AFTER, RECORD)
    assert original[-1][RECORD.index("impact_count")] > count
    fmu.slave.setFMUstate(state)
    fmu.time = t
    assert exact(fmu.step(H, AFTER, RECORD)) == exact(original)
    fmu.slave.freeFMUstate(state)


def test_serialized_state_continues_bit_identically_in_another_instance(started, unpacked_fmu):
    fmu = started
    state = fmu.slave.getFMUstate()
    serialized = fmu.slave.serializeFMUstate(state)
    fmu.slave.freeFMUstate(state)
    t = fmu.time
    original = fmu.step(H, AFTER, RECORD)
    with Instance(unpacked_fmu) as other:
        other.initialize()
        other.slave.setFMUstate(other.slave.deSerializeFMUstate(serialized))
        other.time = t
        assert exact(other.step(H, AFTER, RECORD)) == exact(original)


def test_instances_do_not_share_state(unpacked_fmu):
    """Two instances stepped in turn, one with e = 0.9, give what each gives alone (no global mutable state)."""

    def alone(**values):
        with Instance(unpacked_fmu) as fmu:
            fmu.initialize(**values)
            return exact(fmu.step(H, BEFORE, RECORD))

    with Instance(unpacked_fmu) as a, Instance(unpacked_fmu) as b:
        a.initialize()
        b.initialize(restitution=0.9)
        rows_a, rows_b = [], []
        for _ in range(BEFORE):
            rows_a += a.step(H, 1, RECORD)
            rows_b += b.step(H, 1, RECORD)
    assert exact(rows_a) == alone()
    assert exact(rows_b) == alone(restitution=0.9)
    assert exact(rows_a) != exact(rows_b)
