"""A sweep's TOML spec, checked against the FMU's model description before anything runs, and its points.

    name = "clearance_speed"        # the results go to DIR/<name>/
    cycles = 40                     # cycles per run: engine cycles (4π) for model_variant 1, crank turns (2π) for 2
    skip_cycles = 10                # the transient: not counted in the per-cycle metrics
    model_variant = 1               # optional
    [start]                         # fixed start values of any parameter or input
    peak_pressure = 6e6
    [grid]                          # full factorial: a list, or {start, stop, num} (evenly spaced, both ends)
    clearance = {start = "40 um", stop = "200 um", num = 5}   # SI numbers, or strings with a unit the FMU declares
    restitution = [0.3, 0.5, 0.8]
    [random]                        # optional Latin hypercube of n samples, crossed with the grid
    n = 20
    seed = 1
    crank_speed = ["1000 rpm", "2000 rpm"]    # [low, high]

`clearance` is the diametral clearance bore - piston_diameter (`settings.CLEARANCE`); the runs set `bore` from it.
"""

import itertools
import math
import tomllib
from dataclasses import dataclass

import numpy as np

from .refusal import Refusal
from .settings import CLEARANCE, POSITIVE, bound, same_thing, value_of

#: The sweep sets the impact log itself (one per run, read for the metrics).
RESERVED = ("impact_log",)
_TOP_LEVEL = {"name", "cycles", "skip_cycles", "model_variant", "start", "grid", "random"}


class SpecError(ValueError):
    """A spec that cannot run: the message names the entry at fault."""


@dataclass(frozen=True)
class Spec:
    name: str
    cycles: int
    skip_cycles: int
    #: start values every run shares (model_variant included when the spec sets it)
    fixed: dict
    #: the swept variables, in the order of the results' columns
    swept: tuple
    #: one dict of swept values per point; a point's index in this list is its identity in the results
    points: list


def load(path, model_description):
    """The spec in the TOML file at `path`, checked against `model_description` (fmpy's); raises `SpecError`."""
    try:
        with open(path, "rb") as f:
            raw = tomllib.load(f)
    except tomllib.TOMLDecodeError as e:
        raise SpecError(f"{path}: not TOML: {e}") from None
    return parse(raw, model_description)


def parse(raw, model_description):
    """The spec of the dict `raw` (a parsed TOML document), checked against `model_description`."""
    unknown = set(raw) - _TOP_LEVEL
    if unknown:
        raise SpecError(f"unknown entries {sorted(unknown)}; a spec has {sorted(_TOP_LEVEL)}")
    name = raw.get("name")
    if not isinstance(name, str) or not name or not name.replace("-", "").replace("_", "").replace(".", "").isalnum():
        raise SpecError(
            f"name = {name!r}: give a non-empty name of letters, digits, '-', '_' or '.' (it names the results folder)"
        )
    cycles = _integer(raw.get("cycles"), "cycles", minimum=1)
    skip = _integer(raw.get("skip_cycles", 0), "skip_cycles", minimum=0)
    if skip >= cycles:
        raise SpecError(f"skip_cycles = {skip} leaves no cycle of the {cycles} to count")
    variables = Variables(model_description)

    fixed = {name: _value(variables, f"start.{name}", name, value) for name, value in raw.get("start", {}).items()}
    if "model_variant" in raw:
        if "model_variant" in fixed:
            raise SpecError("model_variant is given both at the top and in [start]")
        fixed["model_variant"] = _value(variables, "model_variant", "model_variant", raw["model_variant"])

    grid = {name: _grid_values(variables, name, entry) for name, entry in raw.get("grid", {}).items()}
    random = _latin_hypercube(variables, raw["random"]) if "random" in raw else {}
    for name in grid.keys() & random.keys() | (grid.keys() | random.keys()) & fixed.keys():
        raise SpecError(f"{name} is given in more than one of [start], [grid] and [random]")
    try:
        same_thing(fixed.keys() | grid.keys() | random.keys(), "[start], [grid] and [random]")
    except Refusal as e:
        raise SpecError(str(e)) from None
    if not grid and not random:
        raise SpecError("nothing to sweep: give [grid] or [random]")

    swept = tuple(grid) + tuple(random)
    samples = [dict(zip(random, row, strict=True)) for row in zip(*random.values(), strict=True)] if random else [{}]
    points = [
        dict(zip(grid, combination, strict=True), **sample)
        for combination in itertools.product(*grid.values())
        for sample in samples
    ]
    return Spec(name=name, cycles=cycles, skip_cycles=skip, fixed=fixed, swept=swept, points=points)


def _integer(value, entry, minimum):
    if isinstance(value, bool) or not isinstance(value, int) or value < minimum:
        raise SpecError(f"{entry} = {value!r}: give an integer >= {minimum}")
    return value


class Variables(dict):
    """The variables by name (with the diametral `clearance`) and the model description they are from."""

    def __init__(self, model_description):
        super().__init__({v.name: v for v in model_description.modelVariables}, clearance=CLEARANCE)
        self.model_description = model_description


def _variable(variables, name, entry):
    """The settable FMU variable `name`, or a `SpecError` naming `entry`."""
    if name in RESERVED:
        raise SpecError(f"{entry}: {name} is set by the sweep itself")
    variable = variables.get(name)
    if variable is None:
        raise SpecError(f"{entry}: the FMU has no variable {name!r}")
    if variable.causality not in ("parameter", "input"):
        raise SpecError(f"{entry}: {name} is an {variable.causality}, not a parameter or input")
    return variable


def _value(variables, entry, name, value):
    """`value` checked against the type and the declared range of the variable `name`."""
    variable = _variable(variables, name, entry)
    if isinstance(value, str) and variable.type != "String":
        try:
            value = value_of(name, value, variables.model_description, entry)
        except Refusal as e:
            raise SpecError(str(e)) from None
    if variable.type == "String":
        if not isinstance(value, str):
            raise SpecError(f"{entry} = {value!r}: {name} takes a string")
        return value
    if isinstance(value, bool) != (variable.type == "Boolean"):
        raise SpecError(f"{entry} = {value!r}: {name} is a {variable.type}")
    if variable.type == "Boolean":
        return value
    if not isinstance(value, (int, float)) or not math.isfinite(value):
        raise SpecError(f"{entry} = {value!r}: {name} takes a finite number")
    if variable.type in ("Integer", "Enumeration"):
        if value != int(value):
            raise SpecError(f"{entry} = {value!r}: {name} is an {variable.type} and takes whole numbers")
        value = int(value)
    low, high = bound(variable, "min"), bound(variable, "max")
    if (low is not None and value < low) or (high is not None and value > high):
        shown = (-math.inf if low is None else low, math.inf if high is None else high)
        raise SpecError(f"{entry} = {value!r} is outside {name}'s range [{shown[0]}, {shown[1]}] (SI)")
    if name in POSITIVE and not value > 0:
        raise SpecError(f"{entry} = {value!r}: give more than 0: {POSITIVE[name]}")
    return float(value) if variable.type == "Real" else value


def _grid_values(variables, name, entry):
    """The values of one [grid] entry: a non-empty list, or {start, stop, num} with num >= 1."""
    where = f"grid.{name}"
    _variable(variables, name, where)
    if isinstance(entry, dict):
        if set(entry) != {"start", "stop", "num"}:
            raise SpecError(f"{where} = {entry!r}: give a list or {{start, stop, num}}")
        num = _integer(entry["num"], f"{where}.num", minimum=1)
        start, stop = (_value(variables, f"{where}.{key}", name, entry[key]) for key in ("start", "stop"))
        if num == 1 and start != stop:
            raise SpecError(f"{where}: num = 1 cannot span start = {entry['start']} to stop = {entry['stop']}")
        entry = np.linspace(start, stop, num).tolist()
    if not isinstance(entry, list) or not entry:
        raise SpecError(f"{where} = {entry!r}: give a non-empty list or {{start, stop, num}}")
    values = [_value(variables, f"{where}[{i}]", name, value) for i, value in enumerate(entry)]
    if len(set(values)) != len(values):
        raise SpecError(f"{where}: repeated values {values}")
    return values


def _latin_hypercube(variables, random):
    """[random]: n samples of each range [low, high], one per stratum of width (high - low)/n in every variable,
    strata paired at random (numpy's default generator seeded with `seed`)."""
    n = _integer(random.get("n"), "random.n", minimum=1)
    seed = _integer(random.get("seed"), "random.seed", minimum=0)
    ranges = {name: entry for name, entry in random.items() if name not in ("n", "seed")}
    if not ranges:
        raise SpecError("[random] has no variable ranges")
    rng = np.random.default_rng(seed)
    samples = {}
    for name, entry in ranges.items():
        where = f"random.{name}"
        variable = _variable(variables, name, where)
        if variable.type != "Real":
            raise SpecError(f"{where}: {name} is an {variable.type}; [random] samples Real variables (use [grid])")
        if not (isinstance(entry, list) and len(entry) == 2):
            raise SpecError(f"{where} = {entry!r}: give [low, high]")
        low, high = (_value(variables, f"{where}[{i}]", name, bound) for i, bound in enumerate(entry))
        if not low < high:
            raise SpecError(f"{where} = {entry!r}: low must be below high")
        strata = (rng.permutation(n) + rng.random(n)) / n
        samples[name] = (low + strata * (high - low)).tolist()
    return samples
