"""The demo's summary describes the cycle its plots draw and says whether the run has settled: the change of the main
figures from the cycle before, a warning when they moved by more than 10 % or when no whole cycle precedes the one
drawn (the start-up)."""

import csv
import re

from cli import pistonslap

from pistonslap.cycle_figures import change


def demo(*args, cwd):
    done = pistonslap("demo", "--plots", "none", "--out", "out", *args, cwd=cwd)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_the_summary_counts_the_cycle_drawn_as_the_fmu_counts_it(tmp_path):
    """Drawn 0…720°, the cycle drawn is the FMU's own cycle (firing TDC to firing TDC): the summary's slaps and
    impacts, taken from the impact log within the drawn window, are the FMU's figures of that cycle in cycles.csv."""
    printed = demo("--crank-0-720", "--cycles", "3", cwd=tmp_path)
    with open(tmp_path / "out" / "cycles.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    fmu = {k.split(" [")[0]: float(v) for k, v in rows[-1].items()}
    expected = (
        f"The cycle drawn: {fmu['cycle_slap_events']:.0f} slaps (landings on the other wall): "
        f"{fmu['cycle_slaps_thrust']:.0f} on the major-thrust wall, {fmu['cycle_slap_energy_thrust'] * 1e3:.3g} mJ "
        f"(largest {fmu['cycle_max_slap_energy_thrust'] * 1e3:.3g} mJ); {fmu['cycle_slaps_antithrust']:.0f} on the "
        f"anti-thrust wall, {fmu['cycle_slap_energy_antithrust'] * 1e3:.3g} mJ (largest "
        f"{fmu['cycle_max_slap_energy_antithrust'] * 1e3:.3g} mJ). {fmu['cycle_impacts']:.0f} impacts (every bounce) "
        f"dissipated {fmu['cycle_impact_energy'] * 1e3:.3g} mJ"
    )
    assert fmu["cycle_slap_events"] > 0 and expected in printed, (expected, printed)


def test_a_settled_run_prints_the_change_from_the_cycle_before(tmp_path):
    printed = demo(cwd=tmp_path)
    assert "From the cycle before to the cycle drawn: slaps 6 → 6, largest major-thrust slap" in printed, printed
    assert "Warning" not in printed


def test_one_cycle_is_the_start_up_and_says_so(tmp_path):
    printed = demo("--cycles", "1", cwd=tmp_path)
    assert "Warning: the run holds no whole cycle before the one drawn" in printed, printed
    assert "From the cycle before" not in printed


def test_a_free_crank_still_speeding_up_has_not_settled(tmp_path):
    """A light free crank under the gas torque and no load speeds up from cycle to cycle: the impact energy grows by
    more than 10 % a cycle (measured: 190 → 213 mJ)."""
    printed = demo("--set", "crank_mode=2", "--set", "crank_inertia=0.05", cwd=tmp_path)
    moved = re.search(r"impact energy ([\d.]+) → ([\d.]+) mJ", printed)
    assert moved and float(moved.group(2)) > 1.1 * float(moved.group(1)), printed
    assert "Warning: not settled: the " in printed and "impact energy changed by more than 10%" in printed, printed


def test_small_energies_do_not_decide_the_settling():
    """An energy under 2 % of the cycle's impact energy may move by any share without a warning; a main one may not."""
    before = {
        "cycle_slap_events": 6,
        "cycle_max_slap_energy_thrust": 10e-3,
        "cycle_max_slap_energy_antithrust": 0.1e-3,
        "cycle_impact_energy": 80e-3,
    }
    tiny = dict(before, cycle_max_slap_energy_antithrust=0.2e-3)
    assert change(tiny, before)[1] == []
    assert "largest anti-thrust slap 0.1 → 0.2 mJ (+50.0 %)" in change(tiny, before)[0]
    assert change(dict(before, cycle_max_slap_energy_thrust=12e-3), before)[1] == ["largest major-thrust slap"]
    assert change(dict(before, cycle_slap_events=5), before)[1] == ["slaps"]
