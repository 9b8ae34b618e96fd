"""Operating points of the partner FMU EngineCycle (`pistonslap coupled --engine NAME`): start values of
EngineCycle.fmu, SI units, and the PistonSlap geometry that matches them (crank radius, rod, piston and bore, the
default 80 µm diametral clearance), so that the gas force acts on the crown the pressure was computed for.

Both run at full load, 2000 rpm, with the default real-gas properties and Woschni's wall heat transfer.

Sources of the constants:
- Wiebe function x_b = 1 − exp(−a ((ϑ − ϑ0)/Δϑ)^(m+1)) with a = 5, m = 2: the efficiency factor a = 5 of Kirkpatrick,
  *Internal Combustion Engines: Applied Thermosciences* (Wiley, the edition citing Ghojel 2010), eq 2.70 and
  Example 2.4; m = 2 as Heywood (1988) eq 9.23 fits spark-ignition burn profiles, cited from memory (neither the
  value nor the equation number is checked against the book). The diesel preset uses the same single Wiebe shape: its
  premixed and diffusion phases (a double Wiebe) are not modelled, only their span.
- Woschni's C1 = 2.28 and C2 = 3.24e-3 m/(s·K) (SAE 670931, 1967) and Hohenberg's correlation (SAE 790825, 1979) are
  built into the FMU (src/models/engine_cycle/heat_transfer.rs, which states their forms and units), chosen by
  `heat_transfer` = 1 or 2.
- Fuels: lower heating values and H/C ratios of Çengel & Boles, *Thermodynamics: An Engineering Approach*
  (McGraw-Hill, 8th ed. 2015), Table A-27: gasoline CnH1.87n 44.0 MJ/kg, light diesel CnH1.8n 43.2 MJ/kg (Heywood
  1988, App. D, Table D.4 is recalled to give the same; not checked).
- `heat_release` is 0.95 (gasoline, stoichiometric charge less incomplete combustion) and 0.70 (diesel, the smoke
  limit of full load) of the fuel the trapped charge can burn, the bound EngineCycle enforces: 1483 of 1561 J and
  2378 of 3398 J.

What they give (tested in python/tests/test_engine_cycle_fmu.py): the gasoline engine an indicated efficiency of
0.39 and a peak pressure of 59 bar at 14° after TDC, the diesel 0.46 and 154 bar at 13°.
"""

import math

RPM = math.pi / 30

PRESETS = {
    "gasoline-na": {
        "description": "naturally aspirated spark-ignition gasoline engine, CR 10, wide open throttle, 2000 rpm",
        "engine": {
            "bore": 0.086,
            "stroke": 0.086,
            "rod_length": 0.143,
            "compression_ratio": 10.0,
            "intake_pressure": 0.95e5,
            "intake_temperature": 330.0,
            "residual_gas_fraction": 0.07,
            "exhaust_pressure": 1.1e5,
            "wall_temperature": 450.0,
            "fuel_heating_value": 44.0e6,
            "fuel_hydrogen_carbon_ratio": 1.87,
            "heat_release": 1483.0,
            "burn_start": math.radians(-20.0),
            "burn_duration": math.radians(55.0),
            "wiebe_efficiency": 5.0,
            "wiebe_form": 2,
            "exhaust_valve_opening": math.radians(130.0),
            "speed_start": 2000 * RPM,
            "speed_end": 2000 * RPM,
        },
    },
    "diesel-turbo": {
        "description": "turbocharged direct-injection diesel engine, CR 16.5, 2.2 bar boost, full load, 2000 rpm",
        "engine": {
            "bore": 0.082,
            "stroke": 0.090,
            "rod_length": 0.145,
            "compression_ratio": 16.5,
            "intake_pressure": 2.2e5,
            "intake_temperature": 330.0,
            "residual_gas_fraction": 0.03,
            "exhaust_pressure": 2.0e5,
            "wall_temperature": 500.0,
            "fuel_heating_value": 43.2e6,
            "fuel_hydrogen_carbon_ratio": 1.8,
            "heat_release": 2378.0,
            "burn_start": math.radians(-12.0),
            "burn_duration": math.radians(50.0),
            "wiebe_efficiency": 5.0,
            "wiebe_form": 2,
            "exhaust_valve_opening": math.radians(130.0),
            "speed_start": 2000 * RPM,
            "speed_end": 2000 * RPM,
        },
    },
}

#: PistonSlap's default diametral clearance, m.
CLEARANCE = 80e-6


def slap_geometry(engine):
    """PistonSlap start values matching EngineCycle's `engine` start values."""
    return {
        "crank_radius": engine["stroke"] / 2,
        "rod_length": engine["rod_length"],
        "piston_diameter": engine["bore"],
        "bore": engine["bore"] + CLEARANCE,
    }
