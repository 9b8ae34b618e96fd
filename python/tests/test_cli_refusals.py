"""Every refusal class of the `pistonslap` commands: exit status 2, exactly one line on stderr naming the cause,
no traceback; `--debug` shows the traceback instead. The cases are the ones a new user tried."""

import pytest
from cli import pistonslap

#: (arguments, words the one line must hold), one per refusal class.
CASES = {
    "usage error": (["demo", "--rpm", "abc"], ["--rpm", "invalid float"]),
    "unknown option": (["demo", "--bogus"], ["--bogus"]),
    "unknown command": (["demos"], ["demos"]),
    "value out of range before the FMU": (["demo", "--rpm", "0"], ["--rpm", "> 0"]),
    "negative speed": (["demo", "--rpm=-3000"], ["--rpm", "-3000"]),
    "no cycle": (["demo", "--cycles", "0"], ["--cycles"]),
    "negative cycles": (["demo", "--cycles", "-2"], ["--cycles"]),
    "no clearance": (["demo", "--clearance", "0"], ["--clearance", "diametral"]),
    "negative clearance": (["demo", "--clearance", "-20"], ["--clearance"]),
    "restitution above its declared range": (["demo", "--restitution", "1.5"], ["--restitution 1.5", "maximum 1"]),
    "FMU refusal": (["demo", "--set", "rod_length=0.03"], ["the FMU refuses", "rod_length"]),
    "FMU refusal of the pin offset": (["demo", "--pin-offset", "50"], ["pin_offset"]),
    "FMU refusal of the threshold": (["demo", "--slap-threshold", "-5"], ["slap_threshold"]),
    "firing TDC without a trace": (["demo", "--firing-tdc", "360"], ["--firing-tdc", "--pressure-trace"]),
    "missing file": (["sweep", "nonexist.toml"], ["nonexist.toml"]),
    "zero step": (["coupled", "--step", "0"], ["--step"]),
    "negative step": (["coupled", "--step", "-0.001"], ["--step"]),
    "step coarser than a fraction of a cycle": (["coupled", "--step", "0.05"], ["--step", "360°", "at most"]),
    "too few cycles to count": (["coupled", "--cycles", "2"], ["--cycles"]),
    "missing sweep results": (["map", "nowhere", "--x", "a", "--y", "b", "--metric", "c"], ["results.parquet"]),
    "analysis FMU refusal": (["analysis", "case", "--lam", "0.05", "--rho", "-1"], ["bore"]),
    "no crank speed in --set": (["demo", "--set", "crank_speed=0rpm"], ["crank_speed = 0 rpm", "more than 0 rpm"]),
    "a bare crank speed in --set": (["demo", "--set", "crank_speed=3000"], ["crank_speed = 3000", "3000rpm"]),
    "a speed above the declared maximum": (["demo", "--rpm", "25000"], ["--rpm 25000", "maximum 20000 rpm"]),
    "a peak pressure above the declared maximum": (
        ["demo", "--peak-pressure", "1000"],
        ["--peak-pressure 1000", "1000 bar", "maximum 300 bar"],
    ),
    "a negative peak pressure in bar, not Pa": (["demo", "--peak-pressure", "-5"], ["-5 bar", "minimum 0 bar"]),
    "the same in --set": (["demo", "--set", "peak_pressure=1000bar"], ["peak_pressure = 1000 bar", "300 bar"]),
    "oil of a million Pa s": (["demo", "--set", "oil_viscosity=1e6"], ["oil_viscosity = 1e+06 Pa.s", "maximum 10"]),
    "bore and clearance in --set": (
        ["demo", "--set", "bore=80.1mm", "--set", "clearance=40um"],
        ["bore and clearance", "give one"],
    ),
    "--clearance and --set bore": (["demo", "--clearance", "40", "--set", "bore=80.1mm"], ["--clearance", "bore"]),
    "a skirt map past the cycle": (["demo", "--skirt-map", "800"], ["--skirt-map", "800", "720"]),
    "an unknown plot": (["demo", "--plots", "slap,gifs"], ["--plots", "gifs"]),
    "an FMU relation in the units typed": (
        ["demo", "--set", "bore=70mm"],
        ["bore = 70 mm must exceed piston_diameter = 80 mm"],
    ),
    "the same in coupled": (["coupled", "--set", "rod_length=1mm"], ["crank_radius = 40 mm", "rod_length = 1 mm"]),
    "no cylinders": (["coupled", "--cylinders", "0"], ["--cylinders = 0", ">= 1"]),
    "a cylinder count without a common firing order": (["coupled", "--cylinders", "7"], ["--firing-order"]),
    "a firing order that is no permutation": (["coupled", "--firing-order", "1-2-2"], ["--firing-order", "once"]),
    "a firing order for another count": (["coupled", "--cylinders", "3", "--firing-order", "1-2"], ["3 cylinders"]),
    "a one-cylinder check of the whole engine": (["coupled", "--cylinders", "2", "--synchronisation"], ["--cylinders"]),
}


def _run(args, cwd):
    return pistonslap(*args, cwd=cwd)


@pytest.mark.parametrize("case", CASES)
def test_refusal_is_one_line_and_exit_2(case, tmp_path):
    args, words = CASES[case]
    done = _run([*args, "--out", str(tmp_path / "out")] if args[0] == "demo" else args, tmp_path)
    lines = done.stderr.splitlines()
    assert done.returncode == 2, (done.returncode, done.stderr)
    assert len(lines) == 1 and "Traceback" not in done.stderr, done.stderr
    assert lines[0].startswith("pistonslap"), lines
    for word in words:
        assert word in lines[0], (word, lines[0])
    assert not (tmp_path / "out").exists(), "nothing is written before the arguments are checked"


def test_a_bad_spec_is_one_line(tmp_path):
    spec = tmp_path / "bad.toml"
    spec.write_text('name = "x"\ncycles = 0\n[grid]\nbore = [0.08008]\n')
    done = _run(["sweep", str(spec)], tmp_path)
    assert done.returncode == 2 and len(done.stderr.splitlines()) == 1 and "cycles" in done.stderr, done.stderr


@pytest.mark.parametrize(
    "toml, words",
    [
        ("crank_speed = 3000\n", ["crank_speed = 3000 names no unit", '"3000 rpm"']),
        ('crank_speed = "0 rpm"\n', ["crank_speed = 0 rpm", "more than 0"]),
        ('bore = "80.1 mm"\nclearance = "40 um"\n', ["bore and clearance"]),
    ],
)
def test_a_params_file_is_refused_by_the_entry_at_fault(toml, words, tmp_path):
    (tmp_path / "engine.toml").write_text(toml)
    done = _run(["demo", "--params", "engine.toml", "--out", "out"], tmp_path)
    assert done.returncode == 2 and len(done.stderr.splitlines()) == 1, done.stderr
    for word in words:
        assert word in done.stderr, (word, done.stderr)
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize(
    "entry, words",
    [
        ('[start]\ncrank_speed = "0 rpm"', ["crank_speed = 0 rpm", "more than 0"]),
        ("[start]\ncrank_speed = 0.0", ["crank_speed = 0.0", "more than 0"]),
        ("[start]\ncrank_speed = 3000.0", ["crank_speed = 3000.0 is outside", "2094.3", "(SI)"]),
        ('[start]\nbore = 0.0801\n[grid]\nclearance = ["40 um", "60 um"]', ["bore and clearance"]),
    ],
)
def test_a_spec_is_refused_before_any_worker_starts(entry, words, tmp_path):
    spec = tmp_path / "spec.toml"
    grid = "" if "[grid]" in entry else "\n[grid]\nrestitution = [0.3, 0.5]"
    spec.write_text(f'name = "x"\ncycles = 2\n{entry}{grid}\n')
    done = _run(["sweep", str(spec), "--workers", "1", "--out", "sweeps"], tmp_path)
    assert done.returncode == 2 and len(done.stderr.splitlines()) == 1, done.stderr
    for word in words:
        assert word in done.stderr, (word, done.stderr)
    assert not (tmp_path / "sweeps").exists(), "nothing is written before the spec is checked"


def test_out_naming_an_existing_file_is_refused(tmp_path):
    (tmp_path / "out").write_text("results of another day\n")
    done = _run(["demo", "--out", "out"], tmp_path)
    assert done.returncode == 2 and len(done.stderr.splitlines()) == 1 and "--out out: is a file" in done.stderr
    assert (tmp_path / "out").read_text() == "results of another day\n"


def test_debug_shows_the_traceback(tmp_path):
    done = _run(["--debug", "demo", "--rpm", "0", "--out", str(tmp_path / "out")], tmp_path)
    assert done.returncode != 0 and "Traceback" in done.stderr and "Refusal" in done.stderr, done.stderr


@pytest.fixture(scope="module")
def swept(tmp_path_factory):
    """A sweep of two restitutions and two clearances, two cycles each, for `pistonslap map`."""
    folder = tmp_path_factory.mktemp("map")
    (folder / "s.toml").write_text(
        'name = "m"\ncycles = 2\n[grid]\nrestitution = [0.3, 0.5]\nclearance = ["40 um", "60 um"]\n'
    )
    done = _run(["sweep", "s.toml", "--workers", "1", "--out", "sw"], folder)
    assert done.returncode == 0, done.stderr
    return folder


@pytest.mark.parametrize(
    "args, words",
    [
        (["--where", "restitution=0.4"], ["--where restitution=0.4", "no point", "0.3, 0.5"]),
        (["--where", "clearance=50um"], ["--where clearance=50um", "no point has clearance = 5e-05"]),
        (["--out", "map.toml"], ["--out map.toml", ".png"]),
        (["--metric", "nosuch"], ["--metric nosuch"]),
    ],
)
def test_map_refuses_in_one_line(swept, args, words):
    base = ["map", "sw/m", "--x", "restitution", "--y", "clearance", "--metric", "impacts_per_cycle"]
    done = _run([*base, *args], swept)
    assert done.returncode == 2 and len(done.stderr.splitlines()) == 1 and "Traceback" not in done.stderr, done.stderr
    for word in words:
        assert word in done.stderr, (word, done.stderr)


def test_map_selects_in_the_unit_typed(swept):
    done = _run(
        [
            "map",
            "sw/m",
            "--x",
            "restitution",
            "--y",
            "clearance",
            "--metric",
            "impacts_per_cycle",
            "--where",
            "clearance=40um",
            "--out",
            "c40.png",
        ],
        swept,
    )
    assert done.returncode == 0 and (swept / "c40.png").stat().st_size > 1000, done.stderr
