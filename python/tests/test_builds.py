"""The FMU's two builds: binaries/linux64/PistonSlap.so runs anywhere and, on a CPU with the x86-64-v3
features, hands every call to PistonSlap.x86-64-v3.so beside it. Both are packed, the right one runs,
PISTONSLAP_BUILD=x86-64 keeps the portable one, and the two give the same results to the bit. The
choice is made once per process, so each run has a process of its own."""

import os
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np

SIBLING = "PistonSlap.x86-64-v3.so"

# Two engine cycles of the default case; prints the logBuild message, saves the outputs.
RUN = """
import sys, fmpy, numpy as np
messages = []
result = fmpy.simulate_fmu(sys.argv[1], stop_time=0.2, output_interval=1e-3, debug_logging=True,
                           logger=lambda env, name, status, category, message: messages.append((category, message)))
np.save(sys.argv[2], result)
print(*[m.decode() for c, m in messages if c == b"logBuild"], sep="\\n")
"""

# /proc/cpuinfo's names of the features rustc's x86-64-v3 adds to the baseline (pni = SSE3,
# cx16 = CMPXCHG16B, abm = LZCNT).
V3_FLAGS = {"avx", "avx2", "bmi1", "bmi2", "cx16", "f16c", "fma", "abm", "movbe", "popcnt", "pni", "sse4_1",
            "sse4_2", "ssse3", "xsave"}


def cpu_runs_x86_64_v3():
    for line in Path("/proc/cpuinfo").read_text().splitlines():
        if line.startswith("flags"):
            return V3_FLAGS <= set(line.split(":", 1)[1].split())
    return False


def run(fmu_file, out, **env):
    done = subprocess.run([sys.executable, "-c", RUN, fmu_file, str(out)], env={**os.environ, **env},
                          capture_output=True, text=True, check=True)
    return done.stdout.strip(), np.load(out)


def test_the_fmu_carries_both_builds(fmu_file):
    names = zipfile.ZipFile(fmu_file).namelist()
    assert "binaries/linux64/PistonSlap.so" in names
    assert f"binaries/linux64/{SIBLING}" in names


def test_the_chosen_build_and_the_portable_one_agree_to_the_bit(fmu_file, tmp_path):
    portable_log, portable = run(fmu_file, tmp_path / "portable.npy", PISTONSLAP_BUILD="x86-64")
    chosen_log, chosen = run(fmu_file, tmp_path / "chosen.npy")
    assert portable_log == "portable x86-64 build: PISTONSLAP_BUILD=x86-64 is set"
    if cpu_runs_x86_64_v3():
        assert chosen_log == "x86-64-v3 build (AVX2, FMA), chosen for this CPU"
    else:
        assert chosen_log.startswith("portable x86-64 build: this CPU lacks")
    assert len(chosen) == 201 and chosen["impact_count"][-1] > 100, "two cycles of the default case"
    assert portable.dtype == chosen.dtype
    assert portable.tobytes() == chosen.tobytes()
