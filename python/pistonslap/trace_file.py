"""A cylinder pressure trace as indicating systems, GT-POWER and spreadsheets export it, read into crank angles and
pressures in Pa, or refused with the user's file, line and angle as written.

What is read:
- separators `,`, `;`, tab or spaces; with `;`, tab or spaces a decimal comma (`12,5`) is read as a decimal point;
- title lines before the header, comment lines (`#`, `//`, `%`) and blank lines anywhere;
- the header row naming the columns, the units in `[...]` or `(...)` in it or in a unit row under it
  (`Kurbelwinkel [°KW];Zylinderdruck [bar]`, `Crank Angle (deg),Cylinder Pressure (bar)`, a row `deg<TAB>bar`);
- the crank angle in the first column, in degrees (`deg`, `°`, `°CA`, `°KW`; no unit is taken as degrees); the
  pressure in the only other column, or the first whose name says pressure (`pressure`, `druck`, `pcyl`, ...), in
  bar, mbar, Pa, hPa, kPa, MPa or psi;
- absolute pressure unless the header says gauge (`gauge`, `barg`, `psig`, `relative`): indicating systems and
  GT-POWER write absolute cylinder pressure and rarely say so. The reference taken is said (`Trace.reference`).

The samples follow the FMU's rules (`src/models/gas/trace.rs`): finite numbers, angles increasing over one 720° cycle
± one sample, an absolute pressure never negative, at least 4 samples. `for_fmu` writes the trace in the FMU's own
form (`crank angle [deg],cylinder pressure [Pa] absolute|gauge`).
"""

import re
import zipfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .refusal import Refusal

#: Pressure units, Pa per unit.
PRESSURE_UNITS = {"bar": 1e5, "mbar": 1e2, "pa": 1.0, "hpa": 1e2, "kpa": 1e3, "mpa": 1e6, "psi": 6894.757293168361}
#: Words of a header field naming the cylinder pressure column.
PRESSURE_WORDS = ("pressure", "druck", "pcyl", "p_cyl", "pzyl", "p_zyl", "cylinder", "zylinder")
#: Words saying a pressure is gauge (relative to ambient), and absolute.
GAUGE_WORDS = ("gauge", "barg", "psig", "kpag", "relative", "überdruck", "(g)")
ABSOLUTE_WORDS = ("absolute", "abs", "bara", "psia", "kpaa", "(a)")
#: Comment lines start with one of these.
COMMENTS = ("#", "//", "%")
#: Separators tried, the first that reads the most rows of two numbers wins.
SEPARATORS = ("\t", ";", ",", None)
SEPARATOR_NAMES = {"\t": "tab", ";": "';'", ",": "','", None: "spaces"}
#: Fewer samples cannot describe a compression, a combustion and a gas exchange (as the FMU).
MIN_SAMPLES = 4
EXAMPLE = "crank angle [deg],cylinder pressure [bar]"
_UNIT_IN_FIELD = re.compile(r"[\[(]([^\])]*)[\])]")


@dataclass
class Trace:
    """A trace as read: where from, its samples, and what was taken of its header."""

    #: the file as the user named it (with where it was found, for a resource)
    name: str
    #: crank angle of each sample, deg
    angles: np.ndarray
    #: pressure of each sample, Pa
    pressures: np.ndarray
    absolute: bool
    #: the column read and how its reference was taken, in words
    reference: str

    def for_fmu(self, shift=0.0):
        """The FMU's own form of the trace, its angles moved by `shift` degrees, pressures in Pa."""
        word = "absolute" if self.absolute else "gauge"
        rows = "".join(
            f"{a + shift!r},{p!r}\n" for a, p in zip(self.angles.tolist(), self.pressures.tolist(), strict=True)
        )
        return f"crank angle [deg],cylinder pressure [Pa] {word}\n{rows}"


def load(path, fmu=None):
    """The trace in the file `path` (a bare name not in the working directory: the FMU `fmu`'s resources), read."""
    path = Path(path)
    if path.is_file():
        return parse(path.read_bytes(), str(path))
    if path.exists():
        raise Refusal(f"--pressure-trace {path}: is not a file")
    shipped = _resources(fmu) if fmu is not None and path.name == str(path) else {}
    if path.name in shipped:
        return parse(shipped[path.name], f"{path} (the FMU's resources)")
    looked = " nor among the FMU's resources (" + ", ".join(sorted(shipped)) + ")" if shipped else ""
    raise Refusal(f"--pressure-trace {path}: no such file in the working directory{looked}")


def _resources(fmu):
    """{file name: bytes} of the traces the FMU ships in its resources/ folder."""
    with zipfile.ZipFile(fmu) as archive:
        return {
            Path(n).name: archive.read(n)
            for n in archive.namelist()
            if n.startswith("resources/") and n.lower().endswith(".csv")
        }


def parse(data, name):
    """The trace in the bytes `data` of the file `name` (for the messages)."""
    refuse = _refuser(name)
    text = _text(data, refuse)
    rows = [(number, line.strip()) for number, line in enumerate(text.splitlines(), 1)]
    rows = [(n, line) for n, line in rows if line and not line.startswith(COMMENTS)]
    if not rows:
        refuse(None, f"holds no samples: give a header ({EXAMPLE}) and rows of crank angle and pressure")
    separator = max(SEPARATORS, key=lambda s: sum(_numbers(line, s) is not None for _, line in rows))
    first = next((i for i, (_, line) in enumerate(rows) if _numbers(line, separator) is not None), None)
    if first is None:
        refuse(None, "has no row of two numbers (crank angle, pressure)")
    if first == 0:
        refuse(rows[0][0], f"holds numbers, not a header: name the columns and the pressure's unit ({EXAMPLE})")
    header, units = _header(rows[:first], separator)
    fields = _split(header[1], separator)
    angle_column, pressure_column = _columns(
        fields, [_unit(f, units, i) for i, f in enumerate(fields)], refuse, header[0]
    )
    angle_unit = _unit(fields[angle_column], units, angle_column)
    if angle_unit is not None and not _is_degrees(angle_unit):
        refuse(header[0], f"crank angle in [{angle_unit}]: give it in degrees [deg]")
    pressure_field = fields[pressure_column]
    pressure_unit = _unit(pressure_field, units, pressure_column)
    if pressure_unit is None:
        refuse(
            header[0],
            f"the pressure column {pressure_field!r} names no unit: give [bar], [Pa], [kPa], [MPa] or [psi] in its "
            f"header, in brackets or parentheses, or in a row of units under it ({EXAMPLE})",
        )
    scale, absolute, reference = _pressure(pressure_field, pressure_unit, refuse, header[0])
    angles, angle_texts, pressures, lines = [], [], [], []
    for number, line in rows[first:]:
        cells = _split(line, separator)
        needed = max(angle_column, pressure_column) + 1
        if len(cells) < needed:
            refuse(number, f"{len(cells)} columns, the header has {len(fields)} ({SEPARATOR_NAMES[separator]} apart)")
        angle = _finite(cells[angle_column], separator, refuse, number, "crank angle")
        where = f"crank angle {cells[angle_column]}°"
        pressure = _finite(cells[pressure_column], separator, refuse, number, f"at {where} the pressure")
        if angles and angle <= angles[-1]:
            refuse(number, f"{where} does not increase (the line before: {angle_texts[-1]}°)")
        if absolute and pressure < 0:
            refuse(number, f"at {where} the absolute pressure {cells[pressure_column]} is negative")
        angles.append(angle)
        angle_texts.append(cells[angle_column])
        pressures.append(pressure * scale)
        lines.append(number)
    if len(angles) < MIN_SAMPLES:
        refuse(None, f"{len(angles)} samples, at least {MIN_SAMPLES} needed")
    sample = float(np.max(np.diff(angles)))
    span = angles[-1] - angles[0]
    if abs(span - 720.0) > sample * (1 + 1e-9):
        refuse(
            lines[-1],
            f"the angles span {span:g}° ({angle_texts[0]}° to {angle_texts[-1]}°), not one four-stroke cycle of "
            f"720° ± one sample ({sample:g}°)",
        )
    column = f"column {pressure_field!r}"
    return Trace(
        name=name,
        angles=np.array(angles),
        pressures=np.array(pressures),
        absolute=absolute,
        reference=f"{column} [{pressure_unit}], {reference}",
    )


def _refuser(name):
    def refuse(line, what):
        raise Refusal(f"--pressure-trace {name}" + (f", line {line}" if line else "") + f": {what}")

    return refuse


def _text(data, refuse):
    """The file's bytes as text; a file that is not text (an image, a spreadsheet) refused."""
    kinds = {b"\x89PNG": "a PNG image", b"%PDF": "a PDF", b"PK\x03\x04": "a zip archive (an .xlsx workbook?)"}
    kind = next((what for magic, what in kinds.items() if data.startswith(magic)), None)
    if kind or b"\0" in data[:4096]:
        refuse(None, f"is not a text file ({kind or 'binary data'}): export the trace as CSV or text")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        return data.decode("cp1252", errors="replace")


def _split(line, separator):
    cells = [c.strip() for c in (line.split(separator) if separator else line.split())]
    while len(cells) > 1 and not cells[-1]:
        cells.pop()
    return cells


def _float(cell, separator):
    """The number in `cell` (a decimal comma read unless `,` separates), or None."""
    if separator != "," and "," in cell and "." not in cell:
        cell = cell.replace(",", ".")
    try:
        return float(cell)
    except ValueError:
        return None


def _numbers(line, separator):
    """The line's first two cells as numbers, or None when it is not a row of numbers."""
    cells = _split(line, separator)
    if len(cells) < 2:
        return None
    values = [_float(c, separator) for c in cells[:2]]
    return None if None in values else values


def _finite(cell, separator, refuse, line, what):
    value = _float(cell, separator)
    if value is None or not np.isfinite(value):
        refuse(line, f"{what} {cell!r} is not a finite number")
    return value


def _header(rows, separator):
    """((line, header row), units row or None) of the lines before the first sample; lines before them are titles."""
    last_line, last = rows[-1]
    cells = _split(last, separator)
    if len(rows) >= 2 and len(cells) >= 2 and all(not c or _is_unit(c) for c in cells):
        return rows[-2], cells
    return (last_line, last), None


def _is_unit(cell):
    word = cell.strip("[]() ").lower()
    return _is_degrees(word) or _pressure_unit(word) is not None or word in ("-", "s", "ms", "rad")


def _is_degrees(unit):
    unit = unit.lower().replace(" ", "")
    return unit in ("deg", "degree", "degrees", "°", "grad", "cad", "kw", "ca") or unit.startswith(("°", "deg"))


def _pressure_unit(unit):
    """(unit, Pa per unit, 'a', 'g' or '') of a pressure unit's text, or None."""
    unit = unit.lower().replace(" ", "").replace("(a)", "a").replace("(g)", "g")
    if unit in PRESSURE_UNITS:
        return unit, PRESSURE_UNITS[unit], ""
    if unit[:-1] in PRESSURE_UNITS and unit[-1:] in ("a", "g"):
        return unit[:-1], PRESSURE_UNITS[unit[:-1]], unit[-1]
    return None


def _columns(fields, column_units, refuse, line):
    """(angle column, pressure column) of the header row's fields and their units: the angle first, the pressure the
    only other column, or the first whose name says pressure, or else the first in a pressure unit."""
    if len(fields) < 2:
        refuse(line, f"the header names {len(fields)} column: name the crank angle and the pressure ({EXAMPLE})")
    if len(fields) == 2:
        return 0, 1
    named = [i for i, f in enumerate(fields[1:], 1) if any(w in f.lower() for w in PRESSURE_WORDS)]
    named += [i for i, u in enumerate(column_units[1:], 1) if u is not None and _pressure_unit(u) is not None]
    if not named:
        refuse(line, f"{len(fields)} columns and none named a pressure or in a pressure unit ({', '.join(fields[1:])})")
    return 0, named[0]


def _unit(field, units, column):
    """The unit of a header field: in brackets or parentheses in it, else in the units row."""
    found = _UNIT_IN_FIELD.findall(field)
    if found:
        return found[-1].strip()
    if units is not None and column < len(units) and units[column]:
        return units[column].strip("[]() ")
    return None


def _pressure(field, unit, refuse, line):
    """(Pa per unit, absolute, the reference in words) of the pressure column."""
    found = _pressure_unit(unit)
    if found is None:
        refuse(line, f"pressure unit [{unit}] is not one of [bar], [mbar], [Pa], [hPa], [kPa], [MPa], [psi]")
    _, scale, suffix = found
    words = field.lower()
    gauge = suffix == "g" or any(w in words for w in GAUGE_WORDS)
    absolute = suffix == "a" or any(re.search(rf"(?<![a-z]){re.escape(w)}(?![a-z])", words) for w in ABSOLUTE_WORDS)
    if gauge and absolute:
        refuse(line, f"the pressure column {field!r} says both absolute and gauge: keep the one that is true")
    if gauge:
        return scale, False, "gauge (as its header says)"
    if absolute:
        return scale, True, "absolute (as its header says)"
    return scale, True, "absolute (the default for a cylinder pressure; write `gauge` in its header if it is not)"
