"""The FMU's `skirt_map`: the lubricated skirt's film over both sides' grids at a chosen crank angle, the film the
outputs of that communication point describe; refused on the dry skirt."""

import re

import numpy as np
import pytest
from fmpy.fmi1 import FMICallException

from pistonslap import skirt_map
from pistonslap.fmu import simulate

from harness import FMI_ERROR, Instance

#: 20° after firing TDC at 1200 rpm (7200°/s), the FMU's default engine: the power stroke's side force on the film.
ANGLE = np.radians(20)
STEP = 5e-5
GRID = (12, 18)


def test_the_map_is_the_film_of_its_communication_point(tmp_path):
    path = tmp_path / "map.csv"
    values = {"skirt_model": 2, "skirt_map": str(path), "skirt_map_crank_angle": ANGLE}
    result = simulate(start_values=values, stop_time=0.004, output_interval=STEP)
    drawn = skirt_map.read(path)
    row = np.argmin(np.abs(result["time"] - drawn["time"]))
    assert result["time"][row] == pytest.approx(drawn["time"], abs=1e-12)
    # Written at the first communication point at or after the angle.
    assert result["crank_angle"][row - 1] < ANGLE <= result["crank_angle"][row]
    assert np.radians(drawn["crank_angle_deg"]) == pytest.approx(result["crank_angle"][row], rel=1e-12)
    force = 0.0
    for side in ("thrust", "antithrust"):
        m = drawn[side]
        # The closed grid: the nodes and the edges around them, where the film pressure is zero.
        assert m["film_pressure"].shape == (GRID[1] + 2, GRID[0] + 2)
        p = m["film_pressure"]
        assert np.all(p >= 0) and not np.any(p[[0, -1], :]) and not np.any(p[:, [0, -1]])
        assert m["film_thickness"].min() == pytest.approx(result[f"min_film_thickness_{side}"][row], rel=1e-12)
        force += skirt_map.film_force(m, 0.08008)
    # 20° after firing TDC the gas load presses the piston onto the major-thrust wall: the film pushes back.
    assert drawn["thrust"]["film_pressure"].max() > 1e5 > drawn["antithrust"]["film_pressure"].max()
    assert force == pytest.approx(result["film_force"][row], rel=1e-9) and force < 0


def test_a_map_of_the_dry_skirt_is_refused(unpacked_fmu, tmp_path):
    with Instance(unpacked_fmu) as fmu:
        fmu.slave.setupExperiment(startTime=0.0)
        fmu.set(skirt_map=str(tmp_path / "map.csv"))
        fmu.slave.enterInitializationMode()
        with pytest.raises(FMICallException):
            fmu.slave.exitInitializationMode()
        assert re.search(r"skirt_map .* skirt_model = 2", fmu.messages(FMI_ERROR)[-1])
    assert not (tmp_path / "map.csv").exists()
