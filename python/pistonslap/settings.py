"""Start values as users write them: `NAME=VALUE` with a unit the model description declares (`crank_speed=3000rpm`,
`peak_pressure=90bar`, `bore=80.08mm`; no unit = SI), a TOML file of such values, and the engine presets.

Every value is checked against the FMU's model description here: an unknown name or unit is a `Refusal` naming it,
and so is a number outside the variable's declared range (`within_range`, in the unit the user typed), a bare crank
speed (rpm or rad/s?) and two values that set the same thing (`bore` and `clearance`); the relations between
parameters the FMU checks itself (`refusal.check_start_values`).
"""

import difflib
import re
import tomllib
from pathlib import Path
from types import SimpleNamespace

from .refusal import Refusal

#: Spellings of display units without the micro sign.
_ALIASES = {"um": "µm", "μm": "µm"}
_NUMBER_AND_UNIT = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(\S*)\s*$")


def _unit_of(variable):
    return variable.unit or (variable.declaredType.unit if variable.declaredType else None)


def units(model_description):
    """{unit: {display unit: (factor, offset)}} of the model description (display = factor · SI + offset)."""
    table = {}
    for unit in model_description.unitDefinitions:
        table[unit.name] = {d.name: (d.factor, d.offset) for d in unit.displayUnits}
    return table


#: The running clearance as engine people quote it: diametral, c = D − d (bore less piston diameter), m (display µm).
#: Not an FMU variable: it sets `bore` to `piston_diameter` + c (`to_fmu`).
CLEARANCE = SimpleNamespace(
    name="clearance",
    type="Real",
    causality="parameter",
    unit="m",
    min="0",
    max=None,
    start=None,
    declaredType=SimpleNamespace(unit="m", min=None, max=None, displayUnit="µm"),
    description="diametral clearance c = bore - piston_diameter",
)


def settable(model_description):
    """The parameters and inputs by name, with the diametral `clearance`."""
    variables = {v.name: v for v in model_description.modelVariables if v.causality in ("parameter", "input")}
    return dict(variables, clearance=CLEARANCE)


def to_fmu(values, defaults):
    """`values` with a diametral `clearance` turned into `bore` (piston_diameter from `values`, else `defaults`),
    over any bore given."""
    if "clearance" not in values:
        return dict(values)
    values = dict(values)
    clearance = values.pop("clearance")
    values["bore"] = values.get("piston_diameter", defaults["piston_diameter"]) + clearance
    return values


#: Variables a bare number may not be given for: engine people and the SI read it in different units.
NEEDS_UNIT = {"crank_speed": "rpm"}
#: Variables whose value must be above 0: the runs sample the cycle in crank angle.
POSITIVE = {"crank_speed": "the runs sample the cycle in crank angle"}
#: Names that set the same thing, refused together in one source.
SAME_THING = (("bore", "clearance"),)


def bound(variable, which):
    """The variable's declared `min` or `max` (SI), or None."""
    text = getattr(variable, which) or (variable.declaredType and getattr(variable.declaredType, which))
    return None if text is None else float(text)


def within_range(name, si, model_description, where, typed=None):
    """`si` (the SI value of `name`) when within its declared range (and above 0 where `POSITIVE`), else a `Refusal`
    naming `where` with the bounds in the unit typed (`typed`: the number and display unit as written; None: SI)."""
    variable = settable(model_description)[name]
    unit = _unit_of(variable) or ""
    number, shown = typed or (si, unit)
    factor, offset = units(model_description).get(unit, {}).get(shown, (1.0, 0.0))
    low, high = bound(variable, "min"), bound(variable, "max")
    said = f"{where}: {name} = {number:g}{' ' + shown if shown else ''}"
    if name in POSITIVE and not si > 0:
        raise Refusal(f"{said}: give more than 0 {shown}: {POSITIVE[name]}".rstrip())
    for limit, wrong, word in (
        (low, low is not None and si < low, "below"),
        (high, high is not None and si > high, "above"),
    ):
        if wrong:
            raise Refusal(
                f"{said} is {word} its declared {'minimum' if word == 'below' else 'maximum'} "
                f"{limit * factor + offset:g} {shown}".rstrip()
            )
    return si


def same_thing(names, where):
    """Refuses names of one source that set the same thing (`SAME_THING`)."""
    for group in SAME_THING:
        given = [n for n in group if n in names]
        if len(given) > 1:
            raise Refusal(
                f"{where}: {' and '.join(given)} both set the bore (clearance = bore - piston_diameter): give one"
            )


def _unknown(name, names, where):
    close = difflib.get_close_matches(name, names, n=3)
    hint = f" (did you mean {', '.join(close)}?)" if close else ""
    return Refusal(f"{where}: the FMU has no parameter or input {name!r}{hint}")


def value_of(name, text, model_description, where):
    """The SI start value of `name` from `text` (a number with an optional unit, or a TOML value), checked."""
    variables = settable(model_description)
    if name not in variables:
        raise _unknown(name, variables, where)
    variable = variables[name]
    if variable.type == "String":
        return str(text)
    if isinstance(text, bool) or variable.type == "Boolean":
        if variable.type != "Boolean" or (not isinstance(text, bool) and text not in ("true", "false")):
            wanted = "true or false" if variable.type == "Boolean" else "a number"
            raise Refusal(f"{where}: {name} is a {variable.type}; give {wanted}")
        return text if isinstance(text, bool) else text == "true"
    if isinstance(text, (int, float)):
        number, unit = float(text), ""
        if name in NEEDS_UNIT:
            raise Refusal(
                f'{where}: {name} = {text} names no unit: write "{text} {NEEDS_UNIT[name]}" or "{text} '
                f'{_unit_of(variable)}"'
            )
    else:
        match = _NUMBER_AND_UNIT.match(str(text))
        if not match:
            raise Refusal(f"{where}: {name} = {text!r} is not a number with an optional unit")
        number, unit = float(match.group(1)), _ALIASES.get(match.group(2), match.group(2))
        if name in NEEDS_UNIT and not unit:
            raise Refusal(
                f"{where}: {name} = {text} names no unit: write {text}{NEEDS_UNIT[name]} or {text}{_unit_of(variable)}"
            )
    si_unit, value = _unit_of(variable), number
    if unit and unit != si_unit:
        display = units(model_description).get(si_unit, {})
        if unit not in display:
            known = [u for u in (si_unit, *display) if u]
            raise Refusal(f"{where}: {name} takes {' or '.join(known) if known else 'no unit'}, not {unit!r}")
        factor, offset = display[unit]
        value = (number - offset) / factor
    if variable.type in ("Integer", "Enumeration"):
        if value != int(value):
            raise Refusal(f"{where}: {name} = {text} is an {variable.type}: give a whole number")
        return int(value)
    return within_range(name, value, model_description, where, (number, unit or si_unit or ""))


def add_parameter_options(parser, whose, examples):
    """`--params FILE` and repeatable `--set NAME=VALUE` for `whose` parameters (`parse_set`, `read_params`), the
    help naming `examples` of assignments."""
    parser.add_argument("--params", type=Path, help=f'TOML file of {whose} parameters: name = SI or "number unit"')
    parser.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help=f"any {whose} parameter, SI or with a unit it declares ({examples}); repeatable",
    )


def parse_set(assignments, model_description):
    """`--set NAME=VALUE` arguments as start values."""
    values = {}
    for assignment in assignments:
        name, equals, text = assignment.partition("=")
        if not equals or not name.strip():
            raise Refusal(f"--set {assignment!r}: give NAME=VALUE, e.g. crank_speed=3000rpm")
        values[name.strip()] = value_of(name.strip(), text.strip(), model_description, f"--set {assignment}")
    same_thing(values, "--set")
    return values


def read_params(path, model_description):
    """A TOML file of `name = value` (a number in SI, or a string with a unit: `crank_speed = "3000 rpm"`)."""
    path = Path(path)
    if not path.is_file():
        raise Refusal(f"--params {path}: no such file")
    try:
        with open(path, "rb") as f:
            raw = tomllib.load(f)
    except tomllib.TOMLDecodeError as e:
        raise Refusal(f"--params {path}: not TOML: {e}") from None
    same_thing(raw, f"--params {path}")
    return {name: value_of(name, value, model_description, f"{path}: {name}") for name, value in raw.items()}


#: A value the FMU's messages give in SI: `name = value unit`.
_SI_VALUE = re.compile(r"\b([a-z][a-z0-9_]*) = (-?\d[\d.]*(?:e[-+]?\d+)?) ([^\s,;:()]+)")


def in_display_units(message, model_description):
    """`message` with each `name = value unit` of a parameter or input given in its SI unit shown in its display unit
    (`bore = 70 mm`, not `bore = 0.07 m`), as the commands take and print values."""

    def shown(match):
        name, value, unit = match.groups()
        variable = settable(model_description).get(name)
        display, factor = display_unit(name, model_description)
        if variable is None or _unit_of(variable) != unit or display == unit:
            return match.group(0)
        return f"{name} = {float(value) * factor:g} {display}"

    return _SI_VALUE.sub(shown, message)


def display_unit(name, model_description):
    """(unit, factor) to show the SI values of `name` in: its display unit where it declares one, else its unit."""
    variable = settable(model_description).get(name)
    if variable is None or variable.type != "Real":
        return "1", 1.0
    si = _unit_of(variable)
    shown = variable.declaredType.displayUnit if variable.declaredType else None
    factor, _ = units(model_description).get(si, {}).get(shown, (1.0, 0.0))
    return (shown, factor) if shown and si != shown and factor else (si or "1", 1.0)
