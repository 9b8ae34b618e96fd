"""`pistonslap coupled` as a user types it: EngineCycle's presets run at their default step, PistonSlap's presets,
parameter files and --set (the lubricated skirt too) reach PistonSlap, what the engine drives is refused, the
summary opens with the operating point, and the synchronisation check is drawn only when asked for."""

import pytest
from cli import pistonslap

from pistonslap.engine_cycle_presets import PRESETS


def coupled(*args, cwd):
    return pistonslap("coupled", "--cycles", "3", "--out", "out", *args, cwd=cwd)


@pytest.mark.parametrize("engine", PRESETS)
def test_every_engine_preset_runs_at_the_default_step(engine, tmp_path):
    done = coupled("--engine", engine, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    first = done.stdout.splitlines()[0]
    assert first.startswith(f"engine {engine} at 2000 rpm; piston PistonSlap defaults: clearance 80 µm"), first
    assert "steps of 0.0006 s" in done.stdout, done.stdout  # 7.2° at 2000 rpm
    written = {p.name for p in (tmp_path / "out").iterdir()}
    assert written == {"coupled.csv", "pressure_and_impacts.png", "impact_log.csv"}, written


def test_the_synchronisation_check_is_drawn_when_asked_for(tmp_path):
    done = coupled("--synchronisation", cwd=tmp_path)
    assert done.returncode == 0 and (tmp_path / "out" / "crank_angles.png").stat().st_size > 1000, done.stderr


def test_a_piston_preset_on_oil_from_set_and_params(tmp_path):
    (tmp_path / "piston.toml").write_text('clearance = "60 um"\nrestitution = 0.3\n')
    done = coupled("--piston", "lu2018-diesel", "--params", "piston.toml", "--set", "skirt_model=2", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    first = done.stdout.splitlines()[0]
    assert "piston lu2018-diesel: clearance 60 µm, e = 0.3, lubricated skirt" in first, first


@pytest.mark.parametrize(
    "args, words",
    [
        (["--set", "crank_speed=3000rpm"], ["crank_speed", "the engine drives"]),
        (["--set", "crank_angle_start=1"], ["crank_angle_start", "the engine drives"]),
        (["--set", "restitution=2"], ["restitution = 2", "maximum 1"]),
        (["--set", "bore=80.1mm", "--set", "clearance=40um"], ["bore and clearance"]),
        (["--set", "rod_length=0.03"], ["the FMU refuses", "rod_length"]),
        (["--piston", "nosuch"], ["--piston", "nosuch"]),
    ],
)
def test_a_bad_value_is_refused_in_one_line_before_the_run(args, words, tmp_path):
    done = coupled(*args, cwd=tmp_path)
    assert done.returncode == 2 and len(done.stderr.splitlines()) == 1, done.stderr
    for word in words:
        assert word in done.stderr, (word, done.stderr)
    assert not (tmp_path / "out").exists()
