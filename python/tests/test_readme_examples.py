"""The `pistonslap demo` and `coupled` command lines of the README and the guide run as written (from a scratch folder
holding what they name), and the guide's pressure-trace header and bare-name lookup work as the guide says."""

import re
import shlex
from pathlib import Path

import pytest
from cli import pistonslap

ROOT = Path(__file__).resolve().parents[2]
#: Files a documented command names, made in the scratch folder: a parameter file and a trace of the guide's form.
FILES = {
    "my_engine.toml": 'crank_speed = "3000 rpm"\nclearance = "60 um"\n',
    "my_trace.csv": (ROOT / "resources" / "full_load.csv").read_text(),
}


def documented(path):
    """The `.venv/bin/pistonslap demo|coupled ...` lines of the code blocks of `path`, comments cut."""
    blocks = re.findall(r"```sh\n(.*?)```", path.read_text(), flags=re.S)
    lines = [line.split("#")[0].strip() for block in blocks for line in block.splitlines()]
    return [line for line in lines if re.match(r"\.venv/bin/pistonslap (demo|coupled) ", line)]


COMMANDS = sorted({line for doc in ("README.md", "documentation/guide.md") for line in documented(ROOT / doc)})


def test_the_documents_hold_commands_to_run():
    assert len(COMMANDS) >= 5, COMMANDS


@pytest.mark.parametrize("line", COMMANDS)
def test_a_documented_command_runs_as_written(line, tmp_path):
    for name, text in FILES.items():
        (tmp_path / name).write_text(text)
    args = shlex.split(line)[1:]
    done = pistonslap(*args, cwd=tmp_path)
    assert done.returncode == 0, (line, done.stderr)
    if "--out" in args:
        out = tmp_path / args[args.index("--out") + 1]
        assert out.is_dir() and any(out.iterdir()), line
    else:
        assert "usage: pistonslap" in done.stdout, done.stdout
