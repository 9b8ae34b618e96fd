"""Firing TDC of a supplied pressure trace: detected as the TDC nearest the peak or stated, reported, and a trace
counted from another TDC handed to the FMU shifted so that it runs exactly as the same cycle counted from firing TDC.
"""

from pathlib import Path

import numpy as np
import pytest
from cli import pistonslap

from pistonslap.fmu import simulate
from pistonslap.refusal import Refusal
from pistonslap.trace_file import load
from pistonslap.trace_tdc import detect_firing_tdc, place_firing_tdc

RESOURCES = Path(__file__).resolve().parents[2] / "resources"


def moved(tmp_path, name, by):
    """The shipped trace `name` with every angle moved by `by` degrees (firing TDC then at `by`)."""
    header, *rows = (RESOURCES / name).read_text().splitlines()
    cells = [row.split(",", 1) for row in rows]
    path = tmp_path / f"{Path(name).stem}_at_{by:g}.csv"
    path.write_text(header + "\n" + "".join(f"{float(a) + by!r},{p}\n" for a, p in cells))
    return path


def test_firing_tdc_is_the_tdc_nearest_the_peak():
    """The full-load example peaks 11° after firing TDC, the motored one at it (the README of resources/)."""
    for name, peak in (("full_load.csv", 11.0), ("motored.csv", 0.0)):
        trace = load(RESOURCES / name)
        angles, pressures = trace.angles, trace.pressures
        assert detect_firing_tdc(angles, pressures) == (0.0, peak)
        assert detect_firing_tdc(angles + 360, pressures) == (360.0, peak + 360)
        assert detect_firing_tdc(angles - 360, pressures) == (-360.0, peak - 360)


def test_a_trace_from_the_gas_exchange_tdc_runs_as_the_same_cycle_from_firing_tdc(tmp_path):
    """Counted 0–720° with firing TDC at 360°, the full-load trace is detected, reported and shifted back: the FMU's
    form of it holds the original's angles exactly, and the FMU's impacts over 50 ms at 3000 rpm are the original's
    bit for bit."""
    trace = load(moved(tmp_path, "full_load.csv", 360))
    shift, said = place_firing_tdc(trace)
    assert "peak at 371°, firing TDC at 360° (detected" in said and "shifted by -360°" in said, said
    shifted = tmp_path / "shifted.csv"
    shifted.write_text(trace.for_fmu(shift))
    assert shifted.read_text() == load(RESOURCES / "full_load.csv").for_fmu()
    outputs = ["impact_count", "impact_energy_total", "piston_lateral"]
    runs = [
        simulate(
            stop_time=0.05,
            output_interval=1e-4,
            output=outputs,
            start_values={"pressure_source": 3, "pressure_trace": str(path), "crank_speed": 100 * np.pi},
        )
        for path in (shifted, RESOURCES / "full_load.csv")
    ]
    assert runs[0]["impact_count"][-1] > 0
    for name in outputs:
        np.testing.assert_array_equal(runs[0][name], runs[1][name])


def test_a_trace_counted_from_firing_tdc_is_used_as_it_is():
    shift, said = place_firing_tdc(load(RESOURCES / "motored.csv"))
    assert shift == 0 and "firing TDC at 0°" in said and "shifted" not in said


def test_a_stated_firing_tdc_wins_over_the_peak(tmp_path):
    """A trace with firing TDC at its 90° (peak at 101°, 101° from the nearest TDC, 0°) is refused unless firing TDC
    is stated; stated, it is shifted by it."""
    trace = load(moved(tmp_path, "full_load.csv", 90))
    with pytest.raises(Refusal, match=r"peak pressure lies at 101°, 101° from the nearest TDC \(0°\).*--firing-tdc"):
        place_firing_tdc(trace)
    shift, said = place_firing_tdc(trace, stated=90)
    assert "firing TDC at 90° (stated)" in said and shift == -90


def test_the_demo_refuses_a_trace_whose_firing_tdc_cannot_be_told_in_one_line(tmp_path):
    path = moved(tmp_path, "full_load.csv", 90)
    done = pistonslap("demo", "--pressure-trace", path, "--out", tmp_path / "out", cwd=None)
    assert done.returncode == 2 and len(done.stderr.splitlines()) == 1, done.stderr
    assert "--pressure-trace" in done.stderr and "--firing-tdc" in done.stderr, done.stderr
