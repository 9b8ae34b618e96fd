"""The FMU Compliance Checker (modelica-tools/FMUComplianceChecker, built by `make toolchain` from the pinned sources
in build/vendor/) checks each packed FMU's model description and simulates it through its Co-Simulation interface,
linux64 natively and win64 under Wine: it reports no warning and no error, and what it simulated equals fmpy's run
of the same FMU. A missing checker fails these tests, like the rest of the cross toolchain."""

import csv
import os
import re
import subprocess
from pathlib import Path

import fmpy
import numpy as np
import pytest
from wine import bcrypt_shim, tool, windows_path, wine_env

FMU_DIR = Path(__file__).resolve().parents[1] / "pistonslap" / "fmu"
#: Where build/toolchain.sh links the checker: in the Makefile's CROSS_CACHE.
CACHE = os.environ.get("CROSS_CACHE") or Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "pistonslap"
CHECKER = Path(CACHE) / "fmucheck"

#: The summary the checker ends its log with: the FMU's logged warnings and errors, then its own.
SUMMARY = re.compile(
    r"FMU reported:\s+(\d+) warning\(s\) and error\(s\)\s+"
    r"Checker reported:\s+(\d+) Warning\(s\)\s+(\d+) Error\(s\)"
)

STOP, STEP = 0.05, 1e-4


def executable(name):
    path = CHECKER / name
    if not path.is_file():
        pytest.fail(f"{path} not found: `make toolchain` builds it")
    return path


@pytest.fixture(scope="module")
def wine_dir(tmp_path_factory):
    """The win64 checker beside the stand-in DLL Wine 8 lacks (the FMU binaries import it)."""
    out = tmp_path_factory.mktemp("fmucheck_win64")
    exe = executable("fmuCheck.win64.exe")
    (out / exe.name).write_bytes(exe.read_bytes())
    bcrypt_shim(out)
    return out


def check(name, platform, tmp_path, wine_dir):
    """(the checker's log, its result rows) for the packed FMU `name` on `platform`, a STOP s run at STEP."""
    fmu, log, result, unpack = FMU_DIR / f"{name}.fmu", tmp_path / "log.txt", tmp_path / "result.csv", tmp_path / "z"
    unpack.mkdir()
    if platform == "linux64":
        command, env, path = [str(executable("fmuCheck.linux64"))], None, str
    else:
        command, env, path = [tool("wine"), str(wine_dir / "fmuCheck.win64.exe")], wine_env(wine_dir), windows_path
    options = ["-k", "cs", "-l", "3", "-s", repr(STOP), "-h", repr(STEP), "-n", "0"]
    files = ["-e", path(log), "-o", path(result), "-z", path(unpack), path(fmu)]
    done = subprocess.run([*command, *options, *files], capture_output=True, text=True, env=env, timeout=600)
    text = log.read_text() if log.is_file() else ""
    assert done.returncode == 0, f"{platform} {name}: exit {done.returncode}\n{text[-2000:]}{done.stderr[-2000:]}"
    with open(result, newline="") as f:
        rows = list(csv.reader(f))
    return text, rows


@pytest.mark.parametrize("platform", ["linux64", "win64"])
@pytest.mark.parametrize("name", ["PistonSlap", "EngineCycle"])
def test_the_checker_reports_nothing_and_simulates_what_fmpy_does(name, platform, tmp_path, wine_dir):
    log, rows = check(name, platform, tmp_path, wine_dir)
    counts = SUMMARY.search(log)
    assert counts, f"no summary in the checker's log:\n{log[-2000:]}"
    assert counts.groups() == ("0", "0", "0"), log[-4000:]

    # It ran the whole experiment: one row per communication point, every output, the same numbers as fmpy.
    header, values = rows[0], np.array(rows[1:], dtype=float)
    md = fmpy.read_model_description(str(FMU_DIR / f"{name}.fmu"))
    outputs = [v.name for v in md.modelVariables if v.causality == "output"]
    assert header == ["time", *outputs]
    assert len(values) == round(STOP / STEP) + 1 and values[-1, 0] == pytest.approx(STOP, rel=1e-12)
    reference = fmpy.simulate_fmu(
        str(FMU_DIR / f"{name}.fmu"), stop_time=STOP, step_size=STEP, output_interval=STEP, output=outputs
    )
    assert len(reference) == len(values)
    for column, output in enumerate(outputs, start=1):
        # fmpy steps to the times n·h, the checker adds h up: communication times that differ at round-off, which
        # PistonSlap's impacts amplify to 1e-8 of an output's range; a wrong parameter or input differs by far more.
        scale = np.abs(reference[output]).max()
        np.testing.assert_allclose(values[:, column], reference[output], rtol=0, atol=1e-6 * scale, err_msg=output)
