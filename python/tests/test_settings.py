"""Start values as users write them: `--set NAME=VALUE` with the units the model description declares, a TOML
parameter file, the diametral clearance, the engine presets; unknown names and units refused by name."""

import fmpy
import numpy as np
import pytest

from pistonslap.fmu import simulate
from pistonslap.presets import PRESETS
from pistonslap.refusal import Refusal
from pistonslap.settings import display_unit, parse_set, read_params, to_fmu
from pistonslap.sweep_point import defaults


@pytest.fixture(scope="module")
def md(fmu_file):
    return fmpy.read_model_description(fmu_file)


def test_display_units_convert_to_si(md):
    values = parse_set(
        [
            "crank_speed=3000rpm",
            "peak_pressure=90 bar",
            "clearance=40um",
            "restitution=0.3",
            "pressure_source=3",
            "pressure_trace=x.csv",
            "crank_angle_start=180deg",
        ],
        md,
    )
    assert values["crank_speed"] == pytest.approx(3000 * np.pi / 30, rel=1e-15)
    assert values["peak_pressure"] == pytest.approx(9e6, rel=1e-15)
    assert parse_set(["bore=80.1mm"], md)["bore"] == pytest.approx(0.0801, rel=1e-15)
    assert values["crank_angle_start"] == pytest.approx(np.pi, rel=1e-15)
    assert (values["restitution"], values["pressure_source"], values["pressure_trace"]) == (0.3, 3, "x.csv")
    # the diametral clearance sets the bore from the piston diameter
    assert to_fmu({"clearance": 40e-6}, defaults(md))["bore"] == pytest.approx(0.08004, rel=1e-15)
    assert display_unit("clearance", md) == ("µm", 1e6) and display_unit("crank_speed", md)[0] == "rpm"


@pytest.mark.parametrize(
    "assignment, words",
    [
        ("crank_sped=3000rpm", ["crank_sped", "crank_speed"]),
        ("crank_speed=3000rpx", ["rpx", "rpm"]),
        ("peak_pressure=90psi", ["psi", "bar"]),
        ("crank_speed", ["NAME=VALUE"]),
        ("pressure_source=1.5", ["whole number"]),
        ("impact_count=3", ["impact_count"]),
    ],
)
def test_unknown_names_and_units_are_refused(md, assignment, words):
    with pytest.raises(Refusal) as refused:
        parse_set([assignment], md)
    for word in words:
        assert word in str(refused.value), refused.value


def test_a_parameter_file(md, tmp_path):
    path = tmp_path / "engine.toml"
    path.write_text('crank_speed = "3000 rpm"\nrestitution = 0.2\nclearance = "60 um"\n')
    assert read_params(path, md) == pytest.approx({"crank_speed": 100 * np.pi, "restitution": 0.2, "clearance": 6e-5})
    path.write_text('crank_speed = "3000 rpx"\n')
    with pytest.raises(Refusal, match="rpx"):
        read_params(path, md)


@pytest.mark.parametrize("name", sorted(PRESETS))
def test_every_preset_runs(name):
    """Each preset names its source and runs a millisecond (an FMU refusal would raise)."""
    result = simulate(stop_time=1e-3, output_interval=1e-3, start_values=PRESETS[name].values, output=["crank_angle"])
    assert PRESETS[name].source and result["crank_angle"][-1] > 0
