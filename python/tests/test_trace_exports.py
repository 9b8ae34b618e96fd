"""Pressure traces as indicating systems, GT-POWER and spreadsheets export them, given to `pistonslap demo
--pressure-trace` as a user types it: each export style is read into the same samples as the shipped full-load trace
(the FMU runs them in Pa, `pressure_trace_as_run.csv` in --out), absolute unless its header says gauge, which the run
says; the styles that cannot be read are refused in one line naming the file, the line and the angle as written, and
leave nothing in --out."""

from pathlib import Path

import numpy as np
import pytest
from cli import pistonslap

RESOURCES = Path(__file__).resolve().parents[2] / "resources"
#: The full-load example: -360…359.5° every 0.5°, absolute bar.
ANGLES, BAR = np.loadtxt(RESOURCES / "full_load.csv", delimiter=",", skiprows=1, unpack=True)


def rows(separator=",", comma=False, angles=ANGLES, bar=BAR):
    """The full-load samples as rows, `separator` apart, with a decimal comma when `comma`."""
    cell = (lambda x: repr(float(x)).replace(".", ",")) if comma else (lambda x: repr(float(x)))
    return "".join(f"{cell(a)}{separator}{cell(p)}\n" for a, p in zip(angles, bar, strict=True))


#: export style: (file name, its text, what the run must say of the pressure's reference).
READ = {
    "units in parentheses": (
        "indicated.csv",
        "Crank Angle (deg),Cylinder Pressure (bar)\n" + rows(),
        "absolute (the default for a cylinder pressure",
    ),
    "GT-POWER names, 0-720 from the gas-exchange TDC": (
        "gtpower.csv",
        "CA [deg],PCYL1 [bar]\n" + rows(angles=ANGLES + 360),
        "absolute (the default for a cylinder pressure",
    ),
    "a unit row under the header": (
        "unit_row.csv",
        "crank angle,cylinder pressure\ndeg,bar\n" + rows(),
        "absolute (the default for a cylinder pressure",
    ),
    "semicolons and decimal commas": (
        "kurbelwinkel.csv",
        "Kurbelwinkel [°KW];Zylinderdruck [bar]\n" + rows(";", comma=True),
        "absolute (the default for a cylinder pressure",
    ),
    "a title line, tab-separated names and units, a comment": (
        "indicom.txt",
        "Cylinder 1 - full load 1200 rpm\nAngle\tPressure\n°CA\tbar\n# averaged over 100 cycles\n" + rows("\t"),
        "absolute (the default for a cylinder pressure",
    ),
    "the guide's own header": (
        "guide.csv",
        "crank angle [deg],cylinder pressure [bar] absolute\n" + rows(),
        "absolute (as its header says)",
    ),
    "three columns, the pressure told by its unit": (
        "three.csv",
        "CA [deg],P [bar],T [K]\n"
        + "".join(f"{a!r},{p!r},800.0\n" for a, p in zip(ANGLES.tolist(), BAR.tolist(), strict=True)),
        "absolute (the default for a cylinder pressure",
    ),
    "gauge in the unit": (
        "gauge.csv",
        "crank angle [deg],cylinder pressure [barg]\n" + rows(bar=BAR - 1),
        "gauge (as its header says)",
    ),
}

#: export style: (file name, its bytes, words the one line of refusal must hold).
REFUSED = {
    "a PNG image": ("plot.png", b"\x89PNG\r\n\x1a\n" + bytes(range(256)) * 4, ["plot.png", "not a text file", "PNG"]),
    "a NaN in the pressure": (
        "nan.csv",
        ("crank angle [deg],cylinder pressure [bar]\n" + rows(bar=np.where(ANGLES == 10, np.nan, BAR))).encode(),
        ["nan.csv", "line 742", "crank angle 10.0°", "'nan'", "not a finite number"],
    ),
    "no pressure unit": (
        "nounit.csv",
        ("crank angle [deg],cylinder pressure\n" + rows()).encode(),
        ["nounit.csv", "line 1", "names no unit"],
    ),
    "angles in radians": (
        "radians.csv",
        ("crank angle [rad],cylinder pressure [bar]\n" + rows(angles=np.radians(ANGLES))).encode(),
        ["radians.csv", "line 1", "[rad]", "degrees"],
    ),
    "half a cycle": (
        "half.csv",
        ("crank angle [deg],cylinder pressure [bar]\n" + rows(angles=ANGLES[:720], bar=BAR[:720])).encode(),
        ["half.csv", "line 721", "span 359.5°", "720°"],
    ),
    "a 0-720 trace whose peak is far from every TDC": (
        "late.csv",
        ("CA [deg],PCYL1 [bar]\n" + rows(angles=ANGLES + 450)).encode(),
        ["late.csv", "peak pressure lies at 461°", "--firing-tdc"],
    ),
    "three columns, none a pressure": (
        "columns.csv",
        b"CA [deg],lift [mm],T [K]\n-360,1,2\n",
        ["columns.csv", "line 1", "none named a pressure", "lift [mm], T [K]"],
    ),
    "decreasing angles": (
        "backwards.csv",
        ("crank angle [deg];p [bar]\n" + rows(";", comma=True)).replace("\n-359,0;", "\n-361,0;").encode(),
        ["backwards.csv", "line 4", "crank angle -361,0°", "does not increase"],
    ),
}


def demo(*args, cwd):
    return pistonslap("demo", "--cycles", "1", "--plots", "none", *args, cwd=cwd)


def as_run(out, name="pressure_trace_as_run.csv"):
    """(angles [deg], pressures [Pa], header) of the trace the FMU ran."""
    path = out / name
    header = path.read_text().splitlines()[0]
    angles, pressures = np.loadtxt(path, delimiter=",", skiprows=1, unpack=True)
    return angles, pressures, header


@pytest.mark.parametrize("style", READ)
def test_an_export_style_is_read_as_the_same_trace(style, tmp_path):
    name, text, reference = READ[style]
    (tmp_path / name).write_text(text, encoding="cp1252" if "°" in text and style.startswith("semi") else "utf-8")
    done = demo("--pressure-trace", name, "--out", "out", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert f"pressure trace {name}" in done.stdout and reference in done.stdout, done.stdout
    angles, pressures, header = as_run(tmp_path / "out")
    np.testing.assert_array_equal(angles, ANGLES)
    gauge = "gauge" in reference
    assert header.endswith("gauge" if gauge else "absolute"), header
    np.testing.assert_allclose(pressures, (BAR - gauge) * 1e5, rtol=1e-15, atol=1e-9)


def test_the_gas_exchange_tdc_trace_is_said_shifted(tmp_path):
    name, text, _ = READ["GT-POWER names, 0-720 from the gas-exchange TDC"]
    (tmp_path / name).write_text(text)
    done = demo("--pressure-trace", name, "--out", "out", cwd=tmp_path)
    assert "peak at 371°, firing TDC at 360° (detected" in done.stdout and "shifted by -360°" in done.stdout


def test_a_bare_name_is_found_in_the_fmus_resources(tmp_path):
    """The guide's lookup: `--pressure-trace full_load.csv` from a folder without it runs the shipped trace."""
    done = demo("--pressure-trace", "full_load.csv", "--out", "out", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert "pressure trace full_load.csv (the FMU's resources)" in done.stdout, done.stdout
    angles, pressures, _ = as_run(tmp_path / "out")
    np.testing.assert_array_equal(angles, ANGLES)
    np.testing.assert_array_equal(pressures, BAR * 1e5)


def test_a_missing_trace_names_where_it_was_looked_for(tmp_path):
    done = demo("--pressure-trace", "fulload.csv", "--out", "out", cwd=tmp_path)
    assert done.returncode == 2 and len(done.stderr.splitlines()) == 1, done.stderr
    assert "fulload.csv" in done.stderr and "full_load.csv, motored.csv" in done.stderr, done.stderr
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("style", REFUSED)
def test_an_export_that_cannot_be_read_is_refused_in_one_line_leaving_nothing(style, tmp_path):
    name, data, words = REFUSED[style]
    (tmp_path / name).write_bytes(data)
    done = demo("--pressure-trace", name, "--out", "out", cwd=tmp_path)
    line = done.stderr.strip()
    assert done.returncode == 2 and len(done.stderr.splitlines()) == 1 and "Traceback" not in line, done.stderr
    for word in words:
        assert word in line, (word, line)
    assert "pressure_trace_as_run" not in line, "the message names the user's file"
    assert not (tmp_path / "out").exists(), "a refusal leaves nothing behind"


def test_a_trace_set_as_a_parameter_is_read_as_exported(tmp_path):
    """`pressure_trace` from --set (or a parameter file) goes through the same reader as --pressure-trace."""
    name, text, reference = READ["semicolons and decimal commas"]
    (tmp_path / name).write_text(text)
    done = demo("--set", "pressure_source=3", "--set", f"pressure_trace={name}", "--out", "out", cwd=tmp_path)
    assert done.returncode == 0 and reference in done.stdout, done.stderr
    np.testing.assert_allclose(as_run(tmp_path / "out")[1], BAR * 1e5, rtol=1e-15)


def sweep(spec, cwd):
    (cwd / "spec.toml").write_text(spec)
    return pistonslap("sweep", "spec.toml", "--workers", "1", "--out", "sweeps", cwd=cwd)


def test_a_sweep_runs_an_exported_trace_and_refuses_a_bad_one_before_starting(tmp_path):
    """A spec's [start] trace goes through the same reader: an export runs (its FMU form in the results' folder), a
    PNG is refused in one line before any worker starts."""
    name, text, reference = READ["units in parentheses"]
    (tmp_path / name).write_text(text)
    spec = 'name = "traced"\ncycles = 2\n[start]\npressure_source = 3\npressure_trace = "{}"\n'
    spec += "[grid]\nrestitution = [0.5]\n"
    done = sweep(spec.format(name), tmp_path)
    assert done.returncode == 0 and reference in done.stdout and "(1 points, 1 run now, 0 failed)" in done.stdout, (
        done.stdout,
        done.stderr,
    )
    np.testing.assert_allclose(as_run(tmp_path / "sweeps" / "traced")[1], BAR * 1e5, rtol=1e-15)
    (tmp_path / "plot.png").write_bytes(REFUSED["a PNG image"][1])
    done = sweep(spec.format("plot.png").replace("traced", "png"), tmp_path)
    assert done.returncode == 2 and len(done.stderr.splitlines()) == 1 and "not a text file" in done.stderr
    assert not (tmp_path / "sweeps" / "png").exists()


def test_a_sweep_over_exported_traces_reads_each_and_refuses_a_bad_one_before_starting(tmp_path):
    """Traces swept in a [grid] go through the same reader, each written in its FMU form into the results' folder; one
    PNG among them is refused in one line before any worker starts, leaving no folder."""
    styles = ["units in parentheses", "semicolons and decimal commas"]
    for style in styles:
        (tmp_path / READ[style][0]).write_text(READ[style][1])
    names = [f'"{READ[style][0]}"' for style in styles]
    spec = 'name = "{}"\ncycles = 2\n[start]\npressure_source = 3\n[grid]\npressure_trace = [{}]\n'
    done = sweep(spec.format("traces", ", ".join(names)), tmp_path)
    assert done.returncode == 0 and "(2 points, 2 run now, 0 failed)" in done.stdout, (done.stdout, done.stderr)
    for k, style in enumerate(styles):
        assert READ[style][2] in done.stdout
        written = as_run(tmp_path / "sweeps" / "traces", f"{k}_{Path(READ[style][0]).stem}_as_run.csv")
        np.testing.assert_allclose(written[1], BAR * 1e5, rtol=1e-15)
    (tmp_path / "plot.png").write_bytes(REFUSED["a PNG image"][1])
    done = sweep(spec.format("png", ", ".join([*names, '"plot.png"'])), tmp_path)
    assert done.returncode == 2 and len(done.stderr.splitlines()) == 1 and "not a text file" in done.stderr
    assert not (tmp_path / "sweeps" / "png").exists()
