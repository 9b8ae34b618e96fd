"""The `pistonslap` command as a user types it: a subprocess of this environment's entry point, plots without a
display, its output captured as text."""

import os
import subprocess
import sys
from pathlib import Path

PISTONSLAP = Path(sys.executable).parent / "pistonslap"


def pistonslap(*args, cwd, timeout=600):
    """`pistonslap ARGS` run in `cwd`; the completed process (returncode, stdout, stderr)."""
    return subprocess.run(
        [str(PISTONSLAP), *map(str, args)],
        cwd=cwd,
        env=dict(os.environ, MPLBACKEND="Agg"),
        capture_output=True,
        text=True,
        timeout=timeout,
    )
