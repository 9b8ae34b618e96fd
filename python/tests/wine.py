"""The toolchain pieces the win64 tests share: a tool `make toolchain` installs (missing: a failure, never a skip),
Wine's environment and paths, and the stand-in DLL Wine 8 lacks."""

import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def tool(name):
    path = shutil.which(name)
    if path is None:
        pytest.fail(f"{name} not found: `make toolchain` installs it")
    return path


def wine_env(out):
    # One prefix for the whole session (Wine takes ~15 s to create one); no Mono or Gecko installers.
    return dict(os.environ, WINEPREFIX=str(out / "wineprefix"), WINEDEBUG="-all", WINEDLLOVERRIDES="mscoree,mshtml=")


def windows_path(path):
    """What Wine's Z: drive calls a Linux path."""
    return "Z:" + str(path).replace("/", "\\")


def bcrypt_shim(directory):
    """The test-only bcryptprimitives.dll (tests/c_host/wine/) built into `directory`: a win64 program there loads
    it, and so do the FMU binaries it loads."""
    shim = ROOT / "tests" / "c_host" / "wine" / "bcryptprimitives.c"
    mingw = tool("x86_64-w64-mingw32-gcc")
    subprocess.run([mingw, "-O1", "-shared", "-o", directory / "bcryptprimitives.dll", shim, "-ladvapi32"], check=True)
