"""The lubricated skirt (skirt_model = 2) through fmpy: the default engine at 1200 and 3000 rpm rides on its oil
film (a coarse Reynolds grid keeps the test short; the grid is the film solver's own concern, tested in Rust)."""

import numpy as np
import pytest
from fmpy.fmi1 import FMICallException

from pistonslap.fmu import simulate

from harness import FMI_ERROR, Instance

FILM = [
    "min_film_thickness_thrust",
    "min_film_thickness_antithrust",
    "film_force",
    "asperity_force",
    "skirt_friction_force",
    "skirt_friction_power",
    "film_energy_total",
    "dissipated_energy_total",
    "impact_energy_total",
    "friction_energy_total",
    "crank_angle",
    "impact_count",
]


@pytest.mark.parametrize("rpm", [1200, 3000])
def test_the_default_engine_rides_on_the_film(rpm):
    """Two crank revolutions at 0.1 ms steps: films between 1 µm and the 80 µm diametral clearance on both sides,
    the film pushing back (its side force of hundreds of newtons), a skirt friction of newtons to tens of
    newtons, and the film's absorbed work in the dissipation total."""
    omega = rpm * np.pi / 30
    result = simulate(
        stop_time=4 * np.pi / omega,
        output_interval=1e-4,
        output=FILM,
        start_values={"skirt_model": 2, "crank_speed": omega, "skirt_grid_circumferential": 6, "skirt_grid_axial": 8},
    )
    for side in ("thrust", "antithrust"):
        film = result[f"min_film_thickness_{side}"]
        assert np.all(film > 1e-6) and np.all(film < 80e-6)
    assert 100 < np.max(np.abs(result["film_force"])) < 1e4
    assert 1 < np.max(np.abs(result["skirt_friction_force"])) < 300
    total = result["impact_energy_total"] + result["friction_energy_total"] + result["film_energy_total"]
    assert result["dissipated_energy_total"] == pytest.approx(total, rel=1e-12, abs=1e-15)
    assert result["film_energy_total"][-1] > 0


def test_dry_skirt_outputs_are_the_corner_gaps():
    """skirt_model = 1 (the default): no film loads; the smallest film per side is the smaller corner gap there."""
    result = simulate(stop_time=0.01, output_interval=1e-3, output=FILM)
    for name in ("film_force", "asperity_force", "skirt_friction_force", "film_energy_total"):
        assert np.all(result[name] == 0)
    # (a corner held on the liner sits within the event tolerance, 1e-12 m, of it)
    assert np.all(result["min_film_thickness_thrust"] >= -1e-12) and np.all(
        result["min_film_thickness_thrust"] <= 80e-6
    )


def test_an_elastic_skirt_lowers_the_peak_film_pressure_and_deflects():
    """Half a revolution at 1200 rpm, rigid (skirt_compliance = 0) against the built-in shell (1) of a 2 mm wall:
    the peak film pressure is defined for both, the shell's lower at its highest; the rigid skirt does not deflect,
    the shell by µm to tenths of a millimetre."""
    omega = 1200 * np.pi / 30

    def run(compliance):
        start = {"skirt_model": 2, "crank_speed": omega, "skirt_compliance": compliance, "skirt_wall_thickness": 2e-3}
        output = ["film_peak_pressure", "skirt_max_deflection"]
        return simulate(stop_time=np.pi / omega, output_interval=1e-3, output=output, start_values=start)

    rigid, shell = run(0), run(1)
    assert np.all(rigid["film_peak_pressure"] >= 0) and np.max(rigid["film_peak_pressure"]) > 1e5
    assert np.all(rigid["skirt_max_deflection"] == 0)
    assert 0 < np.max(shell["film_peak_pressure"]) < np.max(rigid["film_peak_pressure"])
    assert 1e-6 < np.max(shell["skirt_max_deflection"]) < 3e-4


def test_a_missing_compliance_file_is_refused_at_exit_initialization(unpacked_fmu, tmp_path):
    path = tmp_path / "compliance.csv"
    with Instance(unpacked_fmu) as s:
        s.slave.setupExperiment(startTime=0.0)
        s.set(skirt_model=2, skirt_compliance=2, skirt_compliance_file=str(path))
        s.slave.enterInitializationMode()
        with pytest.raises(FMICallException):
            s.slave.exitInitializationMode()
        errors = s.messages(FMI_ERROR)
        assert any("skirt_compliance_file" in m and "cannot be read" in m for m in errors), errors
