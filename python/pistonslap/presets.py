"""PistonSlap's engine presets (`--engine NAME`): start values (SI) of whole engines, each from a cited source.

Only what the source gives is set; everything else keeps the FMU's default (Awrejcewicz & Kudra's engine), and each
preset says which of its values are read how.
"""

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Preset:
    summary: str
    source: str
    values: dict = field(default_factory=dict)


#: Farahanchi's table is in US customary units: pound-force and inch, masses in lbf·s²/in, inertias in lbf·s²·in.
_LBF, _INCH = 4.4482216152605, 0.0254

PRESETS = {
    "awrejcewicz-kudra": Preset(
        summary="the FMU's default: the academic engine of the paper (1200 rpm, 80 bar, 80 µm)",
        source="J. Awrejcewicz, G. Kudra, Int. J. Bifurcation and Chaos 15 (2005), section 8",
    ),
    "flores": Preset(
        summary="the Flores-Leine-Glocker slider crank with a free crank at 150 rad/s, mu = 0.01, gravity across",
        source=(
            "P. Flores, R. Leine, C. Glocker, Multibody System Dynamics 23 (2010) 165-190, as published "
            "(the mapping of /work/shared/benchmarks/flores-slider-crank.md)"
        ),
        values={
            "crank_mode": 2,
            "pressure_source": 1,
            "crank_speed": 150.0,
            "gas_pressure": 0.0,
            "load_torque": 0.0,
            "crank_radius": 0.153,
            "rod_length": 0.306,
            "crank_com": 0.0765,
            "rod_com": 0.153,
            "piston_com": 0.0,
            "crank_mass": 0.038,
            "rod_mass": 0.038,
            "piston_mass": 0.076,
            "crank_inertia": 7.4e-5,
            "rod_inertia": 5.9e-4,
            "piston_inertia": 2.7e-6,
            "piston_diameter": 0.05,
            "skirt_length": 0.1,
            "pin_height": 0.05,
            "bore": 0.052,
            "restitution": 0.4,
            "damping_main": 0.0,
            "damping_crank_pin": 0.0,
            "damping_piston_pin": 0.0,
            "gravity": 0.0,
            "gravity_lateral": 9.81,
            "friction": 0.01,
            "piston_tilt_rate_start": -0.01,
        },
    ),
    "lu2018-diesel": Preset(
        summary="a 110 mm bore diesel at 1680 rpm (piston 1.39 kg, rod 1.7 kg, 50 µm radial skirt clearance)",
        source=(
            'Y. J. Lu, S. Li, P. Wang, C. Liu, Y. Zhang, N. Müller, "The Analysis of Secondary Motion and '
            'Lubrication Performance of Piston considering the Piston Skirt Profile", Shock and Vibration 2018, '
            "3240469, Table 2. Read as: rod centre of mass from the crank pin, piston centre of mass from the pin, "
            "pin 37.3 mm below the skirt top, the 50 µm clearance radial (bore = piston + 2 x 50 µm), the "
            "solid-solid friction coefficient 0.1 as liner friction; the gas pressure is not in the table (the "
            "built-in curve at its default peak)"
        ),
        values={
            "crank_speed": 1680 * 3.141592653589793 / 30,
            "crank_radius": 0.072,
            "rod_length": 0.223,
            "rod_com": 0.072,
            "piston_com": 0.0108,
            "crank_mass": 23.5,
            "crank_inertia": 2.0,
            "rod_mass": 1.7,
            "rod_inertia": 0.017,
            "piston_mass": 1.39,
            "piston_inertia": 0.003,
            "piston_diameter": 0.110,
            "bore": 0.110 + 2 * 50e-6,
            "skirt_length": 0.0828,
            "pin_height": 0.0373,
            "pin_offset": 0.0,
            "friction": 0.1,
        },
    ),
    "ford-gasoline": Preset(
        summary="a Ford four-cylinder gasoline car engine's slider crank (84 mm stroke, piston 0.368 kg, rod 0.699 kg)",
        source=(
            "F. Farahanchi, Chaotic and periodic dynamics of a slider crank mechanism with slider clearance, "
            "M.S. thesis, Michigan State University, 1991, section 4.1: a Ford Motor Company automotive four-cylinder "
            "gasoline engine (from H. H. Denman, Mechanism and Machine Theory 23 (1988) 435-439): crank radius "
            "1.6535 in, rod 5.4570 in, rod mass 0.00399 and piston mass 0.00210 lbf s^2/in, rod inertia about its "
            "centre of mass 0.0295 lbf s^2 in; the rod uniform (section 2.2), its centre of mass at mid-length. "
            "Not in the source, so the FMU's defaults: the 80 mm piston, its skirt, pin height and inertia, the "
            "80 µm clearance, 1200 rpm and the built-in pressure curve at 80 bar"
        ),
        values={
            "crank_radius": 1.6535 * _INCH,
            "rod_length": 5.4570 * _INCH,
            "rod_com": 5.4570 * _INCH / 2,
            "rod_mass": 0.00399 * _LBF / _INCH,
            "piston_mass": 0.00210 * _LBF / _INCH,
            "rod_inertia": 0.0295 * _LBF * _INCH,
        },
    ),
}


#: Lu et al.'s engine on its oil film: the dry entry's values plus Table 2's lubrication data. Only the abstract and
#: Table 2 of the paper could be read (the body was not in any stored source), so its skirt profile and the liner's
#: modulus are not known here: the FMU's default barrel and composite modulus stand.
PRESETS["lu2018-diesel-oil"] = Preset(
    summary="lu2018-diesel on its skirt's oil film (skirt_model = 2, SAE 10W-40 at 100 °C: 5.6 mPa·s)",
    source=(
        PRESETS["lu2018-diesel"].source + "; lubricated as Table 2 gives it: viscosity 0.0056 Pa·s, the combined "
        "roughness 0.54 µm as skirt_roughness, the solid-solid coefficient 0.1 also as boundary_friction"
    ),
    values={
        **PRESETS["lu2018-diesel"].values,
        "skirt_model": 2,
        "oil_viscosity": 0.0056,
        "skirt_roughness": 0.54e-6,
        "boundary_friction": 0.1,
    },
)


#: Running temperatures of a warm engine at part load, typical values, not from the presets' sources: liner and skirt
#: at 100 °C, 10 K above a 90 °C coolant (a measured 800 cc gasoline engine's wall ran 20–30 K above its coolant at
#: 6000 rpm, its mid-stroke near 120 °C: Korean Society of Automotive Engineers, riss.kr control no.
#: 5747798778e0f6c6), the skirt taken at the liner's temperature (it runs hotter toward its top end), from 20 °C; the
#: FMU's default expansion coefficients (Al–Si piston 21e-6 1/K, grey cast iron liner 11e-6 1/K). At 120 °C these
#: coefficients would leave neither engine's clearance: its 80 µm (gasoline) and 100 µm (diesel) are taken as given
#: at 20 °C.
RUNNING = {"reference_temperature": 293.15, "piston_temperature": 373.15, "liner_temperature": 373.15}
RUNNING_LABEL = (
    "running temperatures (typical values, not from the source): liner and skirt at 100 °C from 20 °C, the FMU's "
    "expansion coefficients of an Al–Si piston in a grey cast iron liner"
)


def _at_running_temperature(name, cold_um, hot_um):
    """Preset `name` at the `RUNNING` temperatures, its diametral clearance `cold_um` at 20 °C and `hot_um` running."""
    return Preset(
        summary=f"{name} at running temperature: {hot_um} µm of clearance running, {cold_um} µm at 20 °C",
        source=f"{PRESETS[name].source}; {RUNNING_LABEL}",
        values={**PRESETS[name].values, **RUNNING},
    )


PRESETS["ford-gasoline-hot"] = _at_running_temperature("ford-gasoline", 80, 16.1)
PRESETS["lu2018-diesel-oil-hot"] = _at_running_temperature("lu2018-diesel-oil", 100, 12.1)


#: A running engine's oil film, typical values, not from the presets' sources: the mass-conserving film
#: (`cavitation = 2`) fed by a limited supply (`oil_supply = 2`) of 2 µm of oil left on the liner. The residual film
#: the oil control ring leaves is a few µm: an ultrasonic measurement on a fired diesel's liner found the minimum oil
#: film between liner and rings/skirt 1–3.5 µm (Int. J. Engine Research 2022, doi 10.1177/14680874221088547), and
#: skirt films of 2–21 µm (SAE 2006-01-0648, ultrasound on a single-cylinder engine).
SUPPLY = {"skirt_model": 2, "cavitation": 2, "oil_supply": 2, "liner_oil_film": 2e-6}
SUPPLY_LABEL = (
    "a running engine's film (typical values, not from the source): mass-conserving cavitation fed by 2 µm of oil "
    "left on the liner (a few µm behind the oil control ring: 1–3.5 µm measured by ultrasound on a fired diesel's "
    "liner, Int. J. Engine Research 2022, doi 10.1177/14680874221088547)"
)


def _on_limited_supply(name):
    """Preset `name` (at running temperature) on the `SUPPLY` film."""
    return Preset(
        summary=f"{name} on a limited oil supply: 2 µm of oil on the liner, mass-conserving film",
        source=f"{PRESETS[name].source}; {SUPPLY_LABEL}",
        values={**PRESETS[name].values, **SUPPLY},
    )


PRESETS["ford-gasoline-running"] = _on_limited_supply("ford-gasoline-hot")
PRESETS["lu2018-diesel-oil-running"] = _on_limited_supply("lu2018-diesel-oil-hot")


def help_text():
    """The presets for --help: name, summary, source."""
    return "; ".join(f"{name}: {p.summary}" for name, p in PRESETS.items())
