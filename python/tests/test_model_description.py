"""The packaged FMU as a host sees it before running it: fmpy's validation and the variable contract (DESIGN.md §4)."""

import re

import numpy as np
from fmpy.validation import validate_fmu

INPUTS = {"crank_speed": "rad/s", "gas_pressure": "Pa", "load_torque": None}
REAL_OUTPUTS = [
    "impact_velocity",
    "max_impact_velocity_in_step",
    "impact_energy_in_step",
    "impact_energy_total",
    "last_impact_crank_angle",
    "piston_lateral",
    "piston_lateral_velocity",
    "piston_tilt",
    "piston_axial",
    "crank_angle",
    "rod_angle",
    "crank_torque",
    "side_force",
    "engine_torque",
    "gas_pressure_acting",
    "skirt_top_lateral",
    "skirt_bottom_lateral",
    "cycle_impact_energy",
    "cycle_max_impact_energy_thrust",
    "cycle_max_impact_energy_antithrust",
] + [f"contact_force_{i}" for i in range(1, 5)]
INTEGER_OUTPUTS = ["impact_count", "impacts_in_step", "last_impact_corner", "cycle_count", "cycle_slap_events"] + [
    f"contact_state_{i}" for i in range(1, 5)
]
PARAMETERS = [
    "model_variant",
    "crank_mode",
    "pressure_source",
    "roller_forcing",
    "peak_pressure",
    "crank_radius",
    "rod_length",
    "crank_com",
    "rod_com",
    "piston_com",
    "crank_mass",
    "rod_mass",
    "piston_mass",
    "crank_inertia",
    "rod_inertia",
    "piston_inertia",
    "piston_diameter",
    "skirt_length",
    "pin_height",
    "bore",
    "pin_offset",
    "restitution",
    "damping_main",
    "damping_crank_pin",
    "damping_piston_pin",
    "gravity",
    "crank_angle_start",
    "impact_log",
    "slap_threshold",
]
ANGLES = ["last_impact_crank_angle", "piston_tilt", "crank_angle", "rod_angle", "crank_angle_start"]


def unit_of(variable):
    """A variable's unit, given on the variable or on its declared type."""
    return variable.unit or (variable.declaredType.unit if variable.declaredType else None)


def test_fmpy_validation_finds_no_problem(fmu_file):
    assert validate_fmu(fmu_file) == []


def test_co_simulation_capabilities(unpacked_fmu):
    _, md = unpacked_fmu
    cs = md.coSimulation
    assert md.fmiVersion == "2.0" and cs is not None
    assert cs.canGetAndSetFMUstate and cs.canSerializeFMUstate
    assert cs.canHandleVariableCommunicationStepSize
    assert md.defaultExperiment is not None and md.defaultExperiment.stopTime is not None


def test_variable_contract(unpacked_fmu):
    _, md = unpacked_fmu
    variables = {v.name: v for v in md.modelVariables}
    for name, unit in INPUTS.items():
        assert variables[name].causality == "input" and variables[name].type == "Real"
        assert unit is None or unit_of(variables[name]) == unit
    for name in REAL_OUTPUTS + INTEGER_OUTPUTS:
        assert variables[name].causality == "output", name
        assert variables[name].type == ("Real" if name in REAL_OUTPUTS else "Integer"), name
    for name in PARAMETERS:
        assert variables[name].causality == "parameter", name
    assert variables["impact_log"].type == "String"
    # SI inside, the engine's everyday units for display
    display = {u.name: {d.name for d in u.displayUnits} for u in md.unitDefinitions}
    assert "rpm" in display["rad/s"] and "bar" in display["Pa"]
    assert "mm" in display["m"] and {"um", "µm"} & display["m"]
    for name in ANGLES:
        v = variables[name]
        assert unit_of(v) == "rad" and (v.displayUnit or v.declaredType.displayUnit) == "deg", name
    for name in [*REAL_OUTPUTS, "slap_threshold"]:
        assert unit_of(variables[name]) is not None, f"{name} has no unit"


def test_header_dates_the_generation_and_names_the_licence(unpacked_fmu):
    _, md = unpacked_fmu
    assert re.fullmatch(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ", md.generationDateAndTime), md.generationDateAndTime
    assert md.license == "MIT"


def test_default_experiment_samples_every_half_degree_or_finer(unpacked_fmu):
    """At the default crank speed (125.66 rad/s) a communication step of the default experiment turns the crank by
    at most 0.5°, fine enough to resolve a slap."""
    _, md = unpacked_fmu
    assert np.degrees(125.66 * float(md.defaultExperiment.stepSize)) <= 0.5
