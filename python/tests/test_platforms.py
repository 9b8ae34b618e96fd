"""Every platform the FMUs carry, run for real: the win64 DLL under Wine and the linux64 binary natively, driven by
the same C host (tests/c_host/trace.c, which prints every output's bits after every step), give bit-identical
outputs in every scenario, so do the FMI 3.0 FMUs' x86_64-windows and x86_64-linux binaries driven by the host's
FMI 3.0 build, and an FMU state saved on one platform continues on the other. The binaries' symbol
tables: exactly the fmi2 Co-Simulation functions and the fmi3 functions exported, no glibc symbol newer than the 2.28
baseline, only system DLLs imported. `make test` installs the cross toolchain (`make toolchain`); a missing piece
fails these tests."""

import re
import shutil
import subprocess
from pathlib import Path

import fmpy
import pytest
from wine import bcrypt_shim, tool, windows_path, wine_env

ROOT = Path(__file__).resolve().parents[2]
ENGINE_FMU = Path(__file__).resolve().parents[1] / "pistonslap" / "fmu" / "EngineCycle.fmu"

#: The oldest glibc the linux64 binary may need: RHEL/Rocky 8, Ubuntu 20.04 and SLES 15 have it or newer.
GLIBC_BASELINE = (2, 28)

#: DLLs every Windows 10 and later has; the win64 binary may import nothing else (no MinGW runtime).
SYSTEM_DLLS = {
    "kernel32.dll",
    "ntdll.dll",
    "msvcrt.dll",
    "userenv.dll",
    "ws2_32.dll",
    "bcryptprimitives.dll",
    "api-ms-win-core-synch-l1-2-0.dll",
}

STEPS, STEP = 2000, 1e-4

#: name: (FMU, parameters as (kind, variable name, value)); kind r, i or s as the host's options take them.
SCENARIOS = {
    "default": ("PistonSlap", []),
    # a trace from resources/, found through the resource URI Windows hosts pass (file:///Z:/...)
    "pressure_trace": ("PistonSlap", [("i", "pressure_source", 3), ("s", "pressure_trace", "full_load.csv")]),
    "friction_free_crank": ("PistonSlap", [("r", "friction", 0.1), ("i", "crank_mode", 2)]),
    "engine_cycle": ("EngineCycle", []),
}


#: platform folder: (FMI version, run under Wine). The FMI 3.0 FMUs carry the FMI 2.0 FMUs' binaries under FMI 3.0's
#: folder names; the host (trace.c) is compiled for each version.
PLATFORMS = {"linux64": (2, False), "win64": (2, True), "x86_64-linux": (3, False), "x86_64-windows": (3, True)}


@pytest.fixture(scope="module")
def build(tmp_path_factory, fmu_file):
    """The unpacked FMUs of both versions and the hosts, native and win64 (a folder per Windows platform, with the
    Wine-only stand-in DLL beside the host and the FMUs' DLLs)."""
    out = tmp_path_factory.mktemp("platforms")
    fmus = {}
    for name, path in [("PistonSlap", Path(fmu_file)), ("EngineCycle", ENGINE_FMU)]:
        for version, suffix in ((2, ""), (3, "3")):
            archive = str(path.with_name(f"{name}{suffix}.fmu"))
            unzipdir = Path(fmpy.extract(archive, unzipdir=out / f"{name}{suffix}"))
            fmus[name, version] = (unzipdir, fmpy.read_model_description(archive))
    headers = ROOT / "fmi_headers"
    source = ROOT / "tests" / "c_host" / "trace.c"
    mingw = tool("x86_64-w64-mingw32-gcc")
    for platform, (version, wine) in PLATFORMS.items():
        flags = ["-std=c99", "-O1", "-Wall", "-Wextra", "-Werror", "-I", str(headers)] + ["-DFMI3"] * (version == 3)
        extension = "dll" if wine else "so"
        for name in ("PistonSlap", "EngineCycle"):
            binary = fmus[name, version][0] / "binaries" / platform / f"{name}.{extension}"
            assert binary.is_file(), f"{name}'s FMI {version}.0 FMU carries no {platform} binary (`make toolchain fmu`)"
        if wine:
            folder = out / platform
            folder.mkdir()
            subprocess.run([mingw, *flags, "-o", folder / "trace.exe", source], check=True)
            bcrypt_shim(folder)
            for name in ("PistonSlap", "EngineCycle"):
                shutil.copy(fmus[name, version][0] / "binaries" / platform / f"{name}.dll", folder)
        else:
            subprocess.run([tool("gcc"), *flags, "-o", out / f"trace{version}", source, "-ldl"], check=True)
    return out, fmus


def run(build, scenario, platform, *extra):
    """The host's lines (step, output bits) for a scenario on one of `PLATFORMS`."""
    out, fmus = build
    version, wine = PLATFORMS[platform]
    name, parameters = SCENARIOS[scenario]
    unzipdir, md = fmus[name, version]
    by_name = {v.name: v for v in md.modelVariables}
    outputs = [v for v in md.modelVariables if v.causality == "output"]
    reals = ",".join(str(v.valueReference) for v in outputs if v.type in ("Real", "Float64"))
    integers = ",".join(str(v.valueReference) for v in outputs if v.type not in ("Real", "Float64"))
    options = [f"{kind}:{by_name[var].valueReference}={value}" for kind, var, value in parameters]
    resources = (unzipdir / "resources").as_posix()
    # FMI 2.0 takes the resources as a file URI, FMI 3.0 as a path ending in a separator.
    if wine:
        location = "file:///Z:" + resources if version == 2 else windows_path(resources) + "\\"
        command = [tool("wine"), str(out / platform / "trace.exe"), f"{name}.dll", md.guid, location]
        env, cwd = wine_env(out), out / platform
        extra = [re.sub(r"(save|load):(\d+):(.*)", lambda m: f"{m[1]}:{m[2]}:{windows_path(m[3])}", e) for e in extra]
    else:
        location = "file://" + resources if version == 2 else resources + "/"
        library = unzipdir / "binaries" / platform / f"{name}.so"
        command = [str(out / f"trace{version}"), str(library), md.guid, location]
        env, cwd = None, out
    done = subprocess.run(
        [*command, str(STEPS), repr(STEP), reals, integers, *options, *extra],
        capture_output=True,
        text=True,
        env=env,
        cwd=cwd,
        timeout=600,
    )
    assert done.returncode == 0, f"{platform} {scenario}: exit {done.returncode}\n{done.stderr[-2000:]}"
    lines = done.stdout.splitlines()
    assert lines, f"{platform} {scenario}: no output"
    return [line.rstrip("\r") for line in lines]


def assert_same(reference, other):
    assert len(reference) == STEPS == len(other)
    different = [(a, b) for a, b in zip(reference, other, strict=True) if a != b]
    assert not different, f"{len(different)} of {STEPS} steps differ, first:\n{different[0][0]}\n{different[0][1]}"


@pytest.fixture(scope="module")
def linux64(build):
    """The FMI 2.0 linux64 run of every scenario, the reference of the others."""
    return {scenario: run(build, scenario, "linux64") for scenario in SCENARIOS}


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_win64_outputs_equal_linux64_bit_for_bit(build, linux64, scenario):
    assert_same(linux64[scenario], run(build, scenario, "win64"))


@pytest.mark.parametrize("platform", ["x86_64-linux", "x86_64-windows"])
@pytest.mark.parametrize("scenario", SCENARIOS)
def test_the_fmi3_fmus_give_the_fmi2_outputs_bit_for_bit_on_both_platforms(build, linux64, scenario, platform):
    assert_same(linux64[scenario], run(build, scenario, platform))


# FMI 2.0's and FMI 3.0's FMU states are the same bytes: a state crosses versions as it crosses platforms.
@pytest.mark.parametrize(
    "saved_on, restored_on",
    [("linux64", "win64"), ("win64", "linux64"), ("x86_64-windows", "linux64"), ("linux64", "x86_64-linux")],
)
def test_a_state_saved_on_one_platform_continues_on_the_other(build, tmp_path, saved_on, restored_on):
    state = tmp_path / "state.bin"
    straight = run(build, "friction_free_crank", saved_on, f"save:{STEPS // 2}:{state}")
    assert state.stat().st_size > 0
    continued = run(build, "friction_free_crank", restored_on, f"load:{STEPS // 2}:{state}")
    assert continued == straight[STEPS // 2 :]


def objdump(binary, *flags):
    program = "x86_64-w64-mingw32-objdump" if str(binary).endswith(".dll") else "objdump"
    return subprocess.run([tool(program), *flags, str(binary)], capture_output=True, text=True, check=True).stdout


def fmi2_functions():
    """The functions a Co-Simulation FMU exports: the header's common and Co-Simulation sections."""
    text = (ROOT / "fmi_headers" / "fmi2FunctionTypes.h").read_text()
    model_exchange = text[text.index("/* Model Exchange only") : text.index("/* Co-Simulation only")]
    return set(re.findall(r"(fmi2\w+)TYPE\s*\(", text.replace(model_exchange, "")))


FMI2_FUNCTIONS = fmi2_functions()

#: Every FMI 3.0 function (fmi_headers/fmi3Functions.h): hosts bind them all, the FMUs refuse the absent ones.
FMI3_FUNCTIONS = set(re.findall(r"(fmi3\w+);", (ROOT / "fmi_headers" / "fmi3Functions.h").read_text()))

EXPORTED = FMI2_FUNCTIONS | FMI3_FUNCTIONS


def test_the_headers_list_the_34_co_simulation_functions_and_fmi3s_75():
    assert len(FMI2_FUNCTIONS) == 34 and {"fmi2DoStep", "fmi2Instantiate"} <= FMI2_FUNCTIONS
    assert len(FMI3_FUNCTIONS) == 75 and {"fmi3DoStep", "fmi3InstantiateCoSimulation"} <= FMI3_FUNCTIONS


@pytest.mark.parametrize("name", ["PistonSlap", "EngineCycle"])
def test_linux64_exports_only_fmi_functions_and_needs_glibc_2_28(build, name):
    _, fmus = build
    so = fmus[name, 2][0] / "binaries" / "linux64" / f"{name}.so"
    table = objdump(so, "-T")
    defined = {
        line.split()[-1] for line in table.splitlines() if re.match(r"[0-9a-f]+ g ", line) and "*UND*" not in line
    }
    assert defined == EXPORTED, defined ^ EXPORTED
    versions = {tuple(int(p) for p in v.split(".")) for v in re.findall(r"GLIBC_([0-9.]+)", table)}
    assert versions and max(versions) <= GLIBC_BASELINE, sorted(versions)[-3:]
    needed = set(re.findall(r"NEEDED\s+(\S+)", objdump(so, "-p")))
    assert needed <= {"libc.so.6", "ld-linux-x86-64.so.2", "libpthread.so.0", "libdl.so.2", "libgcc_s.so.1"}, needed


@pytest.mark.parametrize("name", ["PistonSlap", "EngineCycle"])
def test_win64_exports_only_fmi_functions_and_imports_only_system_dlls(build, name):
    _, fmus = build
    headers = objdump(fmus[name, 2][0] / "binaries" / "win64" / f"{name}.dll", "-p")
    exports = headers.split("[Ordinal/Name Pointer] Table")[-1]
    assert set(re.findall(r"\]\s+(fmi[23]\w+)", exports)) == EXPORTED
    assert len(re.findall(r"^\s+\[\s*\d+\]\s+\w+$", exports, re.M)) == len(EXPORTED)
    imported = {d.lower() for d in re.findall(r"DLL Name: (\S+)", headers)}
    assert imported <= SYSTEM_DLLS, imported - SYSTEM_DLLS


def test_the_scenarios_differ(linux64):
    """Each scenario runs what it names: the trace, friction and the free crank change the outputs."""
    last = {s: linux64[s][-1] for s in ("default", "pressure_trace", "friction_free_crank")}
    assert len(set(last.values())) == 3
