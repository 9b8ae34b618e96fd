"""A whole engine in one process (`pistonslap coupled --cylinders N`): the instances share no state (each cylinder's
record bit for bit that of its pair run alone at the same phase), the firing order phases them on one crank, the
firing order's refusals, and the command's table and files."""

import numpy as np
import pytest
from cli import pistonslap

from pistonslap.cylinders import RECORDED, fitted_step, start_values
from pistonslap.firing_order import firing_order, phases, start_angles
from pistonslap.fmu import from_firing_tdc
from pistonslap.master import run_cylinders
from pistonslap.refusal import Refusal

STEP = 1e-3  # s: 7.2° at the engine's default 1200 rpm
SPAN = 0.12  # s: 864°, each cylinder past its first firing TDC and the pressure peak after it


@pytest.fixture(scope="module")
def three():
    """Three cylinders, firing order 1-3-2, in one process."""
    order = (1, 3, 2)
    return order, run_cylinders(SPAN, STEP, start_values(order, {}, {}), recorded=RECORDED)


def test_each_cylinder_is_bit_identical_to_its_pair_run_alone(three):
    order, records = three
    for cylinder, values in zip(records, start_values(order, {}, {}), strict=True):
        (alone,) = run_cylinders(SPAN, STEP, [values], recorded=RECORDED)
        assert cylinder.dtype == alone.dtype
        for name in cylinder.dtype.names:
            np.testing.assert_array_equal(cylinder[name], alone[name], err_msg=name)
    # The cylinders differ (they are phased), so equal records above are not an artefact of one shared instance.
    assert not np.array_equal(records[0]["piston_lateral"], records[1]["piston_lateral"])
    assert min(r["impact_count"][-1] for r in records) > 0


def test_the_firing_order_phases_the_cylinders_on_one_crank(three):
    order, records = three
    interval = 4 * np.pi / len(order)
    first = records[0]["engine_crank_angle"]

    def peak(record):
        """Cylinder 1's crank angle at the cylinder's pressure peak in the half turn after its first firing TDC."""
        after = (from_firing_tdc(record["engine_crank_angle"], 0) < np.pi) & (first < 4 * np.pi)
        return first[after][np.argmax(record["gas_pressure"][after])]

    for k, (record, start) in enumerate(zip(records, start_angles(order), strict=True), start=1):
        place = order.index(k)
        # Cylinder k starts where it fires its place in the firing order times 240° after cylinder 1: at 720° less
        # that (in its first cycle), 0 for cylinder 1; both FMUs' cranks then turn with cylinder 1's.
        assert start == (4 * np.pi - place * interval if place else 0.0)
        for angle in ("engine_crank_angle", "crank_angle"):
            np.testing.assert_allclose(record[angle], first + start, rtol=0, atol=1e-9)
        # Its pressure peaks that much later on cylinder 1's crank, to within a step.
        assert peak(record) - peak(records[0]) == pytest.approx(place * interval, abs=STEP * 125.66 + 1e-9)


def test_phases_and_default_firing_orders():
    assert np.degrees(phases((1, 3, 4, 2))) == pytest.approx([0, 540, 180, 360])
    assert firing_order("4") == (1, 3, 4, 2)
    assert firing_order("6") == (1, 5, 3, 6, 2, 4)
    assert firing_order(None, "1-2-4-5-3") == (1, 2, 4, 5, 3)
    assert firing_order("1") == (1,)


@pytest.mark.parametrize(
    "cylinders, order, words",
    [
        ("-1", None, ["--cylinders = -1", ">= 1"]),
        ("two", None, ["--cylinders = 'two'"]),
        ("8", None, ["give --firing-order too"]),
        (None, "1-3-3-2", ["each of the 4 cylinders 1 to 4 once"]),
        ("4", "1-3-4", ["each of the 4 cylinders"]),
        (None, "1 3 4 2", ["separated by '-'"]),
        (None, "3-4-2-1", ["start with cylinder 1"]),
    ],
)
def test_a_bad_count_or_order_is_refused(cylinders, order, words):
    with pytest.raises(Refusal) as refused:
        firing_order(cylinders, order)
    for word in words:
        assert word in str(refused.value), (word, str(refused.value))


def test_the_command_prints_the_table_and_writes_each_cylinder_and_the_engine(tmp_path):
    done = pistonslap("coupled", "--cylinders", "2", "--cycles", "3", "--out", "out", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert "2 cylinders, firing order 1-2" in done.stdout, done.stdout
    lines = done.stdout.splitlines()
    header = next(k for k, line in enumerate(lines) if "skirt FMEP" in line)
    assert [line.split()[0] for line in lines[header + 2 : header + 6]] == ["1", "2", "engine", "wrote"], done.stdout
    written = {p.name for p in (tmp_path / "out").iterdir()}
    assert written == {
        "cylinder_1.csv",
        "cylinder_2.csv",
        "cylinder_1_landing_log.csv",
        "cylinder_2_landing_log.csv",
        "engine.csv",
        "side_forces.png",
    }, written
    summary = np.genfromtxt(tmp_path / "out" / "engine.csv", delimiter=",", names=True)
    assert list(summary["cylinder_1"]) == [1, 2, 0]
    assert list(summary["fires_after_cylinder_1_deg"][:2]) == [0, 360]
    impacts = summary["impacts_per_cycle_1cycle"]
    assert impacts[2] == impacts[0] + impacts[1] > 0
    energy = summary["landing_energy_thrust_J"]
    assert energy[2] == np.nanmax(energy[:2]) > 0


def test_the_default_step_divides_the_firing_interval():
    speed = 2000 * np.pi / 30
    step = fitted_step(0.0006, firing_order("6"), speed)  # 7.2° → 120° / 17 steps
    assert np.degrees(step * speed) == pytest.approx(120 / 17)
    # 1 ms at the default 125.66 rad/s is 180° / 25.0008: 25 steps, 0.03 ‰ longer
    assert fitted_step(0.001, firing_order("4"), 125.66) == pytest.approx(np.radians(180 / 25) / 125.66)
    assert fitted_step(0.001, firing_order("1"), 125.66) == pytest.approx(np.radians(720 / 100) / 125.66)
