"""The measured tables of `documentation/validation/` that run through the packaged FMU, each printed as the
markdown its page holds (`python/tests/test_validation_tables.py` checks every page against what its commands print):

    python -m pistonslap.validation pin-offset ENGINE RPM [RPM ...]   slaps against ±1 mm of pin offset
    python -m pistonslap.validation input-derivatives                 a fed pressure, held against first order
    python -m pistonslap.validation coupled                           EngineCycle → PistonSlap, held or interpolated
    python -m pistonslap.validation published-piston                  Lu et al.'s diesel on oil, six skirt profiles
    python -m pistonslap.validation landings ENGINE RPM [RPM ...]     landings on oil against ±1 mm of pin offset
    python -m pistonslap.validation landing-clearance ENGINE RPM ...  landings on oil against the clearance
    python -m pistonslap.validation vanishing-film ENGINE RPM         landings as the oil thins toward the dry skirt
    python -m pistonslap.validation landing-motion ENGINE RPM         the thrust landing's translation and tilt, ±1 mm
    python -m pistonslap.validation hot-film ENGINE RPM [RPM ...]     thinnest films on oil, cold against ENGINE-hot
    python -m pistonslap.validation cavitation ENGINE RPM [RPM ...]   the film on oil, Reynolds against mass-conserving
    python -m pistonslap.validation oil-supply ENGINE RPM [RPM ...]   the film flooded against a limited oil supply
    python -m pistonslap.validation running-engine ENGINE RPM ...     cold and hot, flooded and limited (ENGINE-running)
    python -m pistonslap.validation film-books ENGINE:RPM:MPAS:MM ... the oiled skirt's books against its powers

The runs are cached per process, so that the tests which assert on the same runs share them.
"""

import sys
from functools import cache

import fmpy
import numpy as np
from fmpy.fmi2 import FMU2Slave

from .demo import SAMPLE_DEG
from .fmu import CENTRED, CYCLE, fmu_path, simulate, simulate_with_logs
from .presets import PRESETS, SUPPLY
from .tables import sampled_metrics

MJ = 1e3
#: The FMU's default boundary_friction, for presets that keep it.
BOUNDARY_FRICTION = 0.1


def _table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines)


def _relative(value, reference):
    """`value` against `reference` in per cent with its sign, two decimals below 0.1 %."""
    percent = 100 * (value / reference - 1)
    text = f"{percent:+.2f}" if abs(percent) < 0.095 else f"{percent:+.1f}"
    return text.replace("-", "−") + " %"


# --- pin offset ---------------------------------------------------------------------------------------------------

#: Cycles each pin-offset run lasts; the table reads the last.
PIN_OFFSET_CYCLES = 6


@cache
def last_cycle(engine, rpm, overrides=(), cycles=PIN_OFFSET_CYCLES):
    """The FMU's outputs at the end of `cycles` cycles of preset `engine` at `rpm` with the parameters `overrides`
    ((name, SI value) pairs), run as `pistonslap demo` runs it (its sampling, its stop): the last completed cycle's
    `cycle_` outputs."""
    omega = rpm * np.pi / 30
    interval = np.radians(SAMPLE_DEG) / omega
    values = dict(PRESETS[engine].values, crank_speed=omega, **dict(overrides))
    result = simulate(
        stop_time=(cycles * CYCLE - CENTRED) / omega + interval, output_interval=interval, start_values=values
    )
    return result[-1]


def last_cycle_metrics(engine, rpm, pin_offset_mm):
    """`last_cycle` with the pin offset by `pin_offset_mm` toward the major-thrust wall."""
    return last_cycle(engine, rpm, (("pin_offset", pin_offset_mm * 1e-3),))


def pin_offset_table(engine, speeds):
    rows = []
    for rpm in speeds:
        for offset, shown in ((-1, "−1 mm"), (0, "0"), (1, "+1 mm")):
            m = last_cycle_metrics(engine, rpm, offset)
            rows.append(
                (
                    f"{rpm:g} rpm",
                    shown,
                    f"{m['cycle_slaps_thrust']} / {m['cycle_slaps_antithrust']}",
                    f"{m['cycle_max_slap_energy_thrust'] * MJ:.1f} mJ",
                    f"{m['cycle_max_slap_energy_antithrust'] * MJ:.1f} mJ",
                    f"{m['cycle_impacts']}, {m['cycle_impact_energy'] * MJ:.3g} mJ",
                )
            )
    header = (
        "speed",
        "pin offset",
        "slaps thrust / anti-thrust",
        "largest slap, thrust",
        "largest slap, anti-thrust",
        "impacts, energy",
    )
    return _table(header, rows)


# --- slap on oil: landings --------------------------------------------------------------------------------------------

#: Cycles each run on oil lasts; the tables read the last.
OIL_CYCLES = 4
UJ = 1e6


def _energy_at(energy, angle):
    """A landing's energy in µJ and its crank angle from firing TDC."""
    return f"{energy * UJ:.3g} µJ at {np.degrees(angle):.0f}°".replace("-", "−")


def _landing(m, wall):
    """The largest landing on `wall` of a last cycle."""
    return _energy_at(m[f"cycle_landing_energy_{wall}"], m[f"cycle_landing_crank_angle_{wall}"])


def _cushioned(m, wall):
    energy = m[f"cycle_landing_energy_{wall}"]
    return f"{100 * m[f'cycle_landing_loss_{wall}'] / energy:.0f} %" if energy > 0 else "–"


def _rise(m, wall):
    return f"{m[f'cycle_max_liner_force_rate_{wall}'] * 1e-6:.2f} kN/ms"


def _on_oil(engine, rpm, **overrides):
    return last_cycle(engine, rpm, tuple(sorted(dict(skirt_model=2, **overrides).items())), OIL_CYCLES)


def landings_table(engine, speeds):
    """Landings on the oiled skirt against ±1 mm of pin offset."""
    rows = []
    for rpm in speeds:
        for offset, shown in ((-1, "−1 mm"), (0, "0"), (1, "+1 mm")):
            m = _on_oil(engine, rpm, pin_offset=offset * 1e-3)
            rows.append(
                (
                    f"{rpm:g} rpm",
                    shown,
                    f"{m['cycle_landings_thrust']} / {m['cycle_landings_antithrust']}",
                    _landing(m, "thrust"),
                    _cushioned(m, "thrust"),
                    _rise(m, "thrust"),
                    _landing(m, "antithrust"),
                    f"{m['cycle_skirt_fmep'] * 1e-5:.3f} bar",
                )
            )
    header = (
        "speed",
        "pin offset",
        "landings thrust / anti-thrust",
        "largest landing, thrust",
        "cushioned",
        "thrust load rise",
        "largest landing, anti-thrust",
        "skirt FMEP",
    )
    return _table(header, rows)


def landing_clearance_table(engine, speeds):
    """Landings on the oiled skirt against the clearance: half, the preset's, twice."""
    rows = []
    defaults = PRESETS[engine].values
    piston = defaults.get("piston_diameter", 0.08)
    clearance = defaults.get("bore", 0.08008) - piston
    for rpm in speeds:
        for factor in (0.5, 1, 2):
            m = _on_oil(engine, rpm, bore=piston + factor * clearance)
            rows.append(
                (
                    f"{rpm:g} rpm",
                    f"{factor * clearance * 1e6:.0f} µm",
                    _landing(m, "thrust"),
                    _rise(m, "thrust"),
                    _landing(m, "antithrust"),
                    _rise(m, "antithrust"),
                )
            )
    header = (
        "speed",
        "clearance",
        "largest landing, thrust",
        "thrust load rise",
        "largest landing, anti-thrust",
        "anti-thrust load rise",
    )
    return _table(header, rows)


def vanishing_film_table(engine, rpm):
    """The largest landings as the oil thins toward the dry skirt (asperities as the preset has them)."""
    rows = []
    for viscosity in (10e-3, 1e-3, 0.1e-3, 0.01e-3):
        m = _on_oil(engine, float(rpm), oil_viscosity=viscosity)
        rows.append(
            (
                f"{viscosity * 1e3:g} mPa·s",
                _landing(m, "thrust"),
                _cushioned(m, "thrust"),
                _landing(m, "antithrust"),
                str(m["cycle_impacts"]),
            )
        )
    m = last_cycle(engine, float(rpm), (("skirt_model", 1),), OIL_CYCLES)
    rows.append(
        ("dry", _landing(m, "thrust"), _cushioned(m, "thrust"), _landing(m, "antithrust"), str(m["cycle_impacts"]))
    )
    header = ("oil", "largest landing, thrust", "taken by the landing", "largest landing, anti-thrust", "impacts")
    return _table(header, rows)


def landing_motion_table(engine, rpm):
    """The largest thrust landing of the last cycle on oil against ±1 mm of pin offset, split into the pin's
    translation and the tilt: the translation's share of its kinetic energy, the pin's, the skirt top's and bottom's
    lateral speeds toward the thrust wall and the tilt rate at its start (the speeds of the skirt's ends from the
    outputs' centred differences)."""
    omega = float(rpm) * np.pi / 30
    interval = np.radians(SAMPLE_DEG) / omega
    names = ["piston_lateral_velocity", "piston_tilt_rate", "skirt_top_lateral", "skirt_bottom_lateral"]
    default_mass = next(
        v.start for v in fmpy.read_model_description(str(fmu_path())).modelVariables if v.name == "piston_mass"
    )
    rows = []
    for offset, shown in ((-1, "−1 mm"), (0, "0"), (1, "+1 mm")):
        values = dict(PRESETS[engine].values, crank_speed=omega, skirt_model=2, pin_offset=offset * 1e-3)
        stop = (OIL_CYCLES * CYCLE - CENTRED) / omega + interval
        result, _, landed = simulate_with_logs(
            start_values=values,
            stop_time=stop,
            output_interval=interval,
            output=[*names, "cycle_landing_energy_thrust"],
        )
        largest = landed[landed["kinetic_energy"] == result["cycle_landing_energy_thrust"][-1]][0]
        at = int(np.argmin(np.abs(result["time"] - largest["time"])))
        speed = {n: np.gradient(result[n], result["time"])[at] for n in ("skirt_top_lateral", "skirt_bottom_lateral")}
        pin = result["piston_lateral_velocity"][at]
        translation = 0.5 * float(values.get("piston_mass", default_mass)) * pin**2
        rows.append(
            (
                shown,
                f"{_energy_at(largest['kinetic_energy'], largest['crank_angle'])}, {largest['leading_end']} first",
                f"{100 * translation / largest['kinetic_energy']:.0f} %",
                f"{pin * 1e3:.1f} mm/s",
                f"{speed['skirt_top_lateral'] * 1e3:.1f} / {speed['skirt_bottom_lateral'] * 1e3:.1f} mm/s".replace(
                    "-", "−"
                ),
                f"{result['piston_tilt_rate'][at]:.3f} rad/s".replace("-", "−"),
                f"{largest['peak_force_rate'] * 1e-6:.2f} kN/ms",
            )
        )
    header = (
        "pin offset",
        "largest landing, thrust",
        "pin's translation",
        "pin's lateral speed",
        "skirt top / bottom lateral speed",
        "tilt rate",
        "thrust load rise",
    )
    return _table(header, rows)


# --- the hot running clearance ---------------------------------------------------------------------------------------


def oil_cycle(engine, rpm, cavitation=1):
    """`sampled_metrics` of the last of `OIL_CYCLES` cycles (about firing TDC) of preset `engine` on oil at `rpm`
    with the film's `cavitation` condition, sampled as `last_cycle` samples, with its running clearance and skirt
    FMEP."""
    return _oil_run(engine, rpm, (("cavitation", cavitation), ("skirt_model", 2)))


@cache
def _oil_run(engine, rpm, overrides):
    """`oil_cycle` of preset `engine` with the parameters `overrides` ((name, SI value) pairs): also each wall's
    largest landing and the wetted fraction's mean and least, the share of the skirt's friction work its asperities'
    boundary friction did (from the samples: boundary_friction · asperity_force · |sliding speed| against
    skirt_friction_power) and the oil left on the liner at the end."""
    omega = rpm * np.pi / 30
    interval = np.radians(SAMPLE_DEG) / omega
    values = dict(PRESETS[engine].values, crank_speed=omega, **dict(overrides))
    result = simulate(
        stop_time=(OIL_CYCLES * CYCLE - CENTRED) / omega + interval, output_interval=interval, start_values=values
    )
    last = result[-1]
    metrics = sampled_metrics(result, OIL_CYCLES)
    # Each wall's load as the motion takes it, the mean over each communication step (its impulse over the step).
    cycle = result["time"] > result["time"][-1] - CYCLE / omega
    impulse = np.maximum(result["liner_impulse_thrust_in_step"], result["liner_impulse_antithrust_in_step"])
    speed = np.abs(np.gradient(result["piston_axial"], result["time"]))
    boundary = values.get("boundary_friction", BOUNDARY_FRICTION) * result["asperity_force"] * speed
    landings = {
        f"cycle_landing_{what}_{wall}": last[f"cycle_landing_{what}_{wall}"]
        for what in ("energy", "crank_angle")
        for wall in ("thrust", "antithrust")
    }
    return dict(
        metrics,
        **landings,
        running_clearance=last["running_clearance"],
        cycle_skirt_fmep=last["cycle_skirt_fmep"],
        cycle_max_wall_load=float(impulse[cycle].max() / interval),
        wetted_mean=float(result["skirt_wetted_fraction"][cycle].mean()),
        wetted_least=float(result["skirt_wetted_fraction"][cycle].min()),
        asperity_share=float(boundary[cycle].sum() / result["skirt_friction_power"][cycle].sum()),
        oil_left_on_liner=last["oil_left_on_liner"],
    )


def _thinnest(m, wall):
    angle = np.degrees(m[f"cycle_min_film_crank_angle_{wall}"])
    return f"{m[f'cycle_min_film_thickness_{wall}'] * 1e6:.3g} µm at {angle:.0f}°".replace("-", "−")


def hot_film_table(engine, speeds):
    """The thinnest film per side on oil, preset `engine` at 20 °C against `engine-hot` at its running temperature."""
    rows = []
    for rpm in speeds:
        for name, shown in ((engine, "cold"), (f"{engine}-hot", "hot")):
            m = oil_cycle(name, rpm)
            rows.append(
                (
                    f"{rpm:g} rpm",
                    shown,
                    f"{m['running_clearance'] * 1e6:.3g} µm",
                    _thinnest(m, "thrust"),
                    _thinnest(m, "antithrust"),
                    f"{m['cycle_max_asperity_force']:.3g} N",
                    f"{m['cycle_skirt_fmep'] * 1e-5:.3f} bar",
                )
            )
    header = (
        "speed",
        "temperature",
        "running clearance",
        "thinnest film, thrust",
        "thinnest film, anti-thrust",
        "peak asperity load",
        "skirt FMEP",
    )
    return _table(header, rows)


def cavitation_table(engine, speeds):
    """Preset `engine` on oil with the Reynolds cavitation condition against the mass-conserving one: the thinnest
    film per side, the largest film side force (`film_force`, the film at the rates now), the largest wall load as
    the motion takes it (a communication step's mean) and the skirt FMEP of the last cycle."""
    rows = []
    for rpm in speeds:
        for cavitation, shown in ((1, "Reynolds"), (2, "mass-conserving")):
            m = oil_cycle(engine, rpm, cavitation)
            rows.append(
                (
                    f"{rpm:g} rpm",
                    shown,
                    _thinnest(m, "thrust"),
                    _thinnest(m, "antithrust"),
                    f"{m['cycle_max_film_force']:.4g} N",
                    f"{m['cycle_max_wall_load']:.4g} N",
                    f"{m['cycle_skirt_fmep'] * 1e-5:.4f} bar",
                )
            )
    header = (
        "speed",
        "cavitation",
        "thinnest film, thrust",
        "thinnest film, anti-thrust",
        "film side force, peak",
        "wall load, peak step mean",
        "skirt FMEP",
    )
    return _table(header, rows)


#: The columns of `_film_cells`.
FILM_COLUMNS = (
    "thinnest film, thrust",
    "thinnest film, anti-thrust",
    "wetted, mean (least)",
    "asperity share of friction",
    "skirt FMEP",
    "largest landing, thrust",
    "largest landing, anti-thrust",
)


def _film_cells(m):
    """A supply run's cells under `FILM_COLUMNS`: the thinnest film per side, the wetted fraction's mean and least,
    the asperities' share of the skirt's friction, the skirt FMEP and each wall's largest landing."""
    return (
        _thinnest(m, "thrust"),
        _thinnest(m, "antithrust"),
        f"{m['wetted_mean']:.2f} ({m['wetted_least']:.2f})",
        f"{100 * m['asperity_share']:.1f} %",
        f"{m['cycle_skirt_fmep'] * 1e-5:.4f} bar",
        _landing(m, "thrust"),
        _landing(m, "antithrust"),
    )


def oil_supply_table(engine, speeds):
    """Preset `engine` (a limited supply's) on the mass-conserving film, fully flooded (`oil_supply = 1`) against its
    limited supply: the thinnest film per side, the wetted fraction's mean and least, the asperities' share of the
    skirt's friction, the skirt FMEP, each wall's largest landing and the oil left on the liner, of the last cycle."""
    rows = []
    for rpm in speeds:
        for supply, shown in ((1, "flooded"), (2, f"limited, {PRESETS[engine].values['liner_oil_film'] * 1e6:g} µm")):
            m = _oil_run(engine, rpm, (("oil_supply", supply),))
            rows.append(
                (
                    f"{rpm:g} rpm",
                    shown,
                    *_film_cells(m),
                    f"{m['oil_left_on_liner'] * 1e6:.3g} µm" if supply == 2 else "–",
                )
            )
    header = (
        "speed",
        "supply",
        *FILM_COLUMNS,
        "oil left on the liner",
    )
    return _table(header, rows)


def running_engine_table(engine, speeds):
    """Preset `engine` on the mass-conserving film at 20 °C and at its running temperature (`engine-hot`), each fully
    flooded and on the limited supply of `engine-running`: the thinnest film per side, the wetted fraction's mean and
    least, the asperities' share of the skirt's friction, the skirt FMEP and each wall's largest landing, of the last
    cycle."""
    running = f"{engine}-running"
    limited = f"limited, {PRESETS[running].values['liner_oil_film'] * 1e6:g} µm"
    rows = []
    for rpm in speeds:
        for temperature in ("cold", "hot"):
            for supply, shown in ((1, "flooded"), (2, limited)):
                if temperature == "hot":
                    m = _oil_run(running, rpm, (("oil_supply", supply),))
                else:
                    cold = {**SUPPLY, "oil_supply": supply}
                    m = _oil_run(engine, rpm, tuple(sorted(cold.items())))
                rows.append(
                    (
                        f"{rpm:g} rpm",
                        f"{temperature}, {m['running_clearance'] * 1e6:.3g} µm",
                        shown,
                        *_film_cells(m),
                    )
                )
    header = (
        "speed",
        "temperature, running clearance",
        "supply",
        *FILM_COLUMNS,
    )
    return _table(header, rows)


# --- a fed pressure: held against first-order input derivatives ------------------------------------------------------

#: rad/s, the crank speed of the fed-pressure runs (1200 rpm).
FED_SPEED = 125.66
#: The communication steps compared, s, and the reference's.
FED_STEPS = (1e-3, 5e-4, 2e-4, 1e-4)
FED_REFERENCE_STEP = 1e-5


class FullLoadPressure:
    """The shipped full-load trace (gauge) as a C¹ function of crank angle: cubic Hermite through its 0.5° samples
    with centred-difference slopes, and its crank-angle derivative. Independent of the FMU's interpolant."""

    def __init__(self, unzipdir):
        data = np.loadtxt(f"{unzipdir}/resources/full_load.csv", delimiter=",", skiprows=1)
        self.start, self.spacing = np.radians(data[0, 0]), np.radians(data[1, 0] - data[0, 0])
        self.p = (data[:, 1] - 1) * 1e5
        self.m = (np.roll(self.p, -1) - np.roll(self.p, 1)) / (2 * self.spacing)

    def __call__(self, theta):
        """(p, dp/dθ) at crank angle `theta`."""
        x = (theta - self.start) % (4 * np.pi) / self.spacing
        k = int(x) % len(self.p)
        s, k1, dx = x - int(x), (k + 1) % len(self.p), self.spacing
        p0, p1, m0, m1 = self.p[k], self.p[k1], self.m[k] * dx, self.m[k1] * dx
        value = (
            (2 * s**3 - 3 * s**2 + 1) * p0
            + (s**3 - 2 * s**2 + s) * m0
            + (3 * s**2 - 2 * s**3) * p1
            + (s**3 - s**2) * m1
        )
        slope = (6 * s**2 - 6 * s) * (p0 - p1) + (3 * s**2 - 4 * s + 1) * m0 + (3 * s**2 - 2 * s) * m1
        return value, slope / dx


@cache
def _unpacked():
    path = str(fmu_path())
    return fmpy.extract(path), fmpy.read_model_description(path)


@cache
def fed_cycles(h, first_order, cycles=2):
    """One warm-up cycle, then `cycles` at `FED_SPEED` with `gas_pressure` fed from the full-load trace at each step
    of `h` (and its time derivative ω dp/dθ when `first_order`): (impact energy per cycle [J], largest impact
    velocity [m/s]) after the warm-up."""
    unzipdir, md = _unpacked()
    vr = {v.name: v.valueReference for v in md.modelVariables}
    pressure = FullLoadPressure(unzipdir)
    cycle = 4 * np.pi / FED_SPEED
    steps, warm_up = round((cycles + 1) * cycle / h), round(cycle / h)
    slave = FMU2Slave(
        guid=md.guid, unzipDirectory=unzipdir, modelIdentifier=md.coSimulation.modelIdentifier, instanceName="fed"
    )
    slave.instantiate()
    try:
        slave.setupExperiment(startTime=0.0)
        slave.setInteger([vr["pressure_source"]], [1])
        slave.enterInitializationMode()
        slave.exitInitializationMode()
        fastest, t = 0.0, 0.0
        for k in range(steps):
            p, dp = pressure(FED_SPEED * k * h)
            slave.setReal([vr["gas_pressure"]], [p])
            if first_order:
                slave.setRealInputDerivatives([vr["gas_pressure"]], [1], [FED_SPEED * dp])
            slave.doStep(currentCommunicationPoint=t, communicationStepSize=h)
            t += h
            if k + 1 == warm_up:
                energy_at_warm_up = slave.getReal([vr["impact_energy_total"]])[0]
            elif k + 1 > warm_up:
                fastest = max(fastest, slave.getReal([vr["max_impact_velocity_in_step"]])[0])
        return (slave.getReal([vr["impact_energy_total"]])[0] - energy_at_warm_up) / cycles, fastest
    finally:
        slave.freeInstance()


def input_derivatives_table():
    energy, fastest = fed_cycles(FED_REFERENCE_STEP, True)
    rows = [(f"{FED_REFERENCE_STEP * 1e3:g} ms (reference)", "", "", f"{energy:.5f} J", f"{fastest:.4f} m/s")]
    for h in FED_STEPS:
        cells = [f"{h * 1e3:g} ms"]
        for first in (False, True):
            e, v = fed_cycles(h, first)
            cells += [f"{e:.5f} J ({_relative(e, energy)})", f"{v:.4f} m/s ({_relative(v, fastest)})"]
        rows.append(cells)
    header = (
        "step",
        "energy per cycle, held",
        "largest impact, held",
        "energy per cycle, first order",
        "largest impact, first order",
    )
    return _table(header, rows)


# --- EngineCycle → PistonSlap -------------------------------------------------------------------------------------

COUPLED_REFERENCE_STEP = 2e-5
COUPLED_STEPS = (1e-3, 2.5e-4)


@cache
def coupled_energy(h, derivatives):
    """Impact energy per cycle over cycles 2–5 of the default engines coupled at steps of `h`, J."""
    from .coupled import energy_per_cycle
    from .master import run

    return energy_per_cycle(run(0.6, h, derivatives=derivatives), 2, 5)


def coupled_table():
    reference = coupled_energy(COUPLED_REFERENCE_STEP, False)
    rows = [(f"{COUPLED_REFERENCE_STEP * 1e3:g} ms (reference)", f"{reference:.5f} J", "")]
    for h in COUPLED_STEPS:
        held, first = coupled_energy(h, False), coupled_energy(h, True)
        rows.append(
            (
                f"{h * 1e3:g} ms",
                f"{held:.5f} J ({_relative(held, reference)})",
                f"{first:.5f} J ({_relative(first, reference)})",
            )
        )
    return _table(("step", "held inputs", "first derivatives"), rows)


# --- a published piston on oil ---------------------------------------------------------------------------------------

#: Preset `lu2018-diesel-oil` on the coarse 6 × 8 film grid.
LU_ON_OIL = dict(PRESETS["lu2018-diesel-oil"].values, skirt_grid_circumferential=6, skirt_grid_axial=8)
#: The skirt profiles compared, (top drop, bottom drop) in µm.
PROFILES = ((0, 0), (10, 20), (5, 20), (20, 20), (10, 10), (10, 40))
PROFILE_OUTPUTS = (
    "crank_angle",
    "skirt_top_lateral",
    "skirt_bottom_lateral",
    "piston_lateral_velocity",
    "piston_axial",
    "film_force",
    "skirt_friction_force",
    "cycle_skirt_fmep",
)


def barrel(top_um, bottom_um):
    return f"parabola {top_um}e-6 {bottom_um}e-6"


@cache
def second_cycle(profile):
    """(the second cycle's samples, its skirt FMEP in Pa) of `LU_ON_OIL` with `skirt_profile = profile`, from the
    centred start at the preset's speed, sampled every 0.1 ms."""
    step = 1e-4
    result = simulate(
        stop_time=2 * CYCLE / LU_ON_OIL["crank_speed"] + 2 * step,
        output_interval=step,
        start_values=dict(LU_ON_OIL, skirt_profile=profile),
        output=list(PROFILE_OUTPUTS),
    )
    cycle = result[(result["crank_angle"] >= CYCLE) & (result["crank_angle"] < 2 * CYCLE)]
    return cycle, result["cycle_skirt_fmep"][-1]


def published_piston_table():
    rows = []
    for top, bottom in PROFILES:
        cycle, fmep = second_cycle(barrel(top, bottom))
        rows.append(
            (
                "straight" if top == bottom == 0 else f"{top} / {bottom} µm",
                f"{fmep * 1e-5:.4f} bar",
                f"{np.max(cycle['skirt_top_lateral']) * 1e6:.1f} µm",
                f"{-np.min(cycle['skirt_bottom_lateral']) * 1e6:.1f} µm",
                f"{np.max(np.abs(cycle['piston_lateral_velocity'])) * 1e3:.1f} mm/s",
            )
        )
    header = (
        "skirt profile (top / bottom drop)",
        "FMEP",
        "top eccentricity, thrust",
        "bottom, anti-thrust",
        "peak lateral speed",
    )
    return _table(header, rows)


# --- the film's books ---------------------------------------------------------------------------------------------

#: Samples per engine cycle of the film-books runs, and the cycles each lasts (the table reads the last completed).
BOOKS_SAMPLES, BOOKS_CYCLES = 4000, 3


def film_books_row(engine, rpm, viscosity_mpas, pin_offset_mm):
    """One row of `film_books_table`: preset `engine` on oil at `rpm`, `viscosity_mpas` and the pin offset."""
    omega = rpm * np.pi / 30
    period = CYCLE / omega
    values = dict(
        PRESETS[engine].values,
        skirt_model=2,
        crank_speed=omega,
        oil_viscosity=viscosity_mpas * 1e-3,
        pin_offset=pin_offset_mm * 1e-3,
    )
    outputs = ["skirt_friction_power", "cycle_skirt_fmep", "film_energy_total", "film_relaxation_work"]
    outputs += ["dissipated_energy_total", "contact_state_3", "contact_state_4"]
    r = simulate(
        stop_time=BOOKS_CYCLES * period, output_interval=period / BOOKS_SAMPLES, start_values=values, output=outputs
    )
    t, fmep = r["time"], r["cycle_skirt_fmep"]
    end = np.nonzero(np.diff(fmep))[0][-1] + 1
    cycle = (t >= t[end] - period - 1e-12) & (t <= t[end])
    integral = np.trapezoid(r["skirt_friction_power"][cycle], t[cycle])
    start = {v.name: v.start for v in fmpy.read_model_description(str(fmu_path())).modelVariables}
    diameter, crank = (float(values.get(name, start[name])) for name in ("piston_diameter", "crank_radius"))
    booked = fmep[end] * np.pi / 4 * diameter**2 * 2 * crank
    film = r["film_energy_total"][cycle][-1] - r["film_energy_total"][cycle][0]
    relaxation = r["film_relaxation_work"][cycle][-1] - r["film_relaxation_work"][cycle][0]
    falls = [-min(0.0, np.diff(r[name]).min()) for name in ("film_energy_total", "dissipated_energy_total")]
    held = np.mean((r["contact_state_3"] + r["contact_state_4"])[cycle] == 2)
    return [
        f"{engine}, {rpm:g} rpm, {viscosity_mpas:g} mPa·s, {pin_offset_mm:+g} mm",
        f"{held:.0%}",
        f"{booked:.4g}",
        f"{integral:.4g}",
        f"{booked / integral:.4f}",
        f"{film:.4g}",
        f"{relaxation:.3g}".replace("-", "−"),
        f"{max(falls):.0e}" if max(falls) > 0 else "0",
    ]


def film_books_table(*cases):
    """The oiled skirt's books over the last completed cycle, each case ENGINE:RPM:VISCOSITY_MPAS:PIN_OFFSET_MM: the
    skirt friction work `cycle_skirt_fmep` books against the integral of `skirt_friction_power` at the samples, the
    film's dissipation and its relaxation term's work, and the largest fall of the film's and the dissipated total."""
    header = [
        "case",
        "thrust corners held",
        "friction work booked, J",
        "∫ skirt_friction_power, J",
        "booked / integral",
        "film_energy_total, J",
        "film_relaxation_work, J",
        "largest fall, J",
    ]
    rows = []
    for case in cases:
        engine, rpm, viscosity, offset = case.split(":")
        rows.append(film_books_row(engine, float(rpm), float(viscosity), float(offset)))
    return _table(header, rows)


TABLES = {
    "pin-offset": lambda engine, *speeds: pin_offset_table(engine, [float(s) for s in speeds]),
    "input-derivatives": input_derivatives_table,
    "coupled": coupled_table,
    "published-piston": published_piston_table,
    "landings": lambda engine, *speeds: landings_table(engine, [float(s) for s in speeds]),
    "landing-clearance": lambda engine, *speeds: landing_clearance_table(engine, [float(s) for s in speeds]),
    "vanishing-film": vanishing_film_table,
    "landing-motion": landing_motion_table,
    "hot-film": lambda engine, *speeds: hot_film_table(engine, [float(s) for s in speeds]),
    "cavitation": lambda engine, *speeds: cavitation_table(engine, [float(s) for s in speeds]),
    "oil-supply": lambda engine, *speeds: oil_supply_table(engine, [float(s) for s in speeds]),
    "running-engine": lambda engine, *speeds: running_engine_table(engine, [float(s) for s in speeds]),
    "film-books": film_books_table,
}


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] not in TABLES:
        raise SystemExit(f"usage: python -m pistonslap.validation {{{','.join(TABLES)}}} [ARGS]")
    print(TABLES[argv[0]](*argv[1:]))


if __name__ == "__main__":
    main()
