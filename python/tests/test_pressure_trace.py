"""Measured pressure traces (`pressure_source = 3`): the shipped examples found by bare name in the FMU's
resources, the trace against the same pressure fed as the `gas_pressure` input, and every bad file refused at
fmi2ExitInitializationMode with the file, the line and the fault."""

import numpy as np
import pytest
from fmpy.fmi1 import FMICallException

from pistonslap.fmu import input_signals, simulate

from harness import FMI_ERROR, Instance

OMEGA = 125.66  # rad/s, the default crank speed
RESOURCES = ["full_load.csv", "motored.csv"]


def trace_of(unpacked_fmu, name):
    """(angle [deg], absolute pressure [bar]) of a shipped trace, read here independently of the FMU."""
    unzipdir, _ = unpacked_fmu
    data = np.loadtxt(f"{unzipdir}/resources/{name}", delimiter=",", skiprows=1)
    return data[:, 0], data[:, 1]


def test_the_motored_trace_is_found_by_bare_name_and_acts_less_the_crankcase_pressure(fmu_file, unpacked_fmu):
    """The motored example: 45.83 bar at firing TDC (sampled exactly there), 1 bar over exhaust and intake."""
    angle, bar = trace_of(unpacked_fmu, "motored.csv")
    h = 2 * np.pi / OMEGA / 3600  # 0.1° of crank angle: TDC and BDC are communication points
    result = simulate(
        stop_time=7200 * h,
        output_interval=h,
        output=["crank_angle", "gas_pressure_acting"],
        start_values={"pressure_source": 3, "pressure_trace": "motored.csv", "crankcase_pressure": 1e5},
    )
    theta, p = np.degrees(result["crank_angle"]), result["gas_pressure_acting"]
    tdc = np.argmin(np.abs(theta - 720))
    assert p[tdc] == pytest.approx(bar[angle == 0][0] * 1e5 - 1e5, rel=1e-9)
    assert np.max(p) == pytest.approx(44.825e5, rel=1e-4)
    gas_exchange = (theta > 180.5) & (theta < 539.5)
    np.testing.assert_allclose(p[gas_exchange], 0.0, atol=1e-6)


def test_the_trace_drives_the_piston_as_the_same_pressure_fed_as_an_input(fmu_file, unpacked_fmu):
    """Two cycles at fine steps (2e-5 s, 0.014° of crank angle): the full-load trace, and the same trace interpolated
    here (linearly, periodically) and held over each step as `gas_pressure`. The impacts agree in number and in energy
    (measured: 190 impacts both, energies 0.13438 and 0.13428 J).
    """
    angle, bar = trace_of(unpacked_fmu, "full_load.csv")
    h, stop = 2e-5, 0.2
    t = np.arange(0, stop + h / 2, h)
    fed = (np.interp(np.degrees(OMEGA * t), angle, bar, period=720) - 1) * 1e5
    outputs = ["crank_angle", "impact_count", "impact_energy_total", "gas_pressure_acting"]
    from_trace = simulate(
        stop_time=stop,
        output_interval=h,
        output=outputs,
        start_values={"pressure_source": 3, "pressure_trace": "full_load.csv"},
    )
    from_input = simulate(
        stop_time=stop,
        output_interval=h,
        output=outputs,
        input=input_signals(t, gas_pressure=fed),
        start_values={"pressure_source": 1},
    )
    assert from_trace["impact_count"][-1] > 50
    assert abs(int(from_trace["impact_count"][-1]) - int(from_input["impact_count"][-1])) <= 2
    assert from_trace["impact_energy_total"][-1] == pytest.approx(from_input["impact_energy_total"][-1], rel=0.005)
    # the trace's value at each communication point against the input fed from there: linear against monotone cubic
    # interpolation of 0.5° samples differ by p''·(0.25°)²/2 at most, ≈ 1300 Pa near the peak
    np.testing.assert_allclose(from_trace["gas_pressure_acting"][:-1], fed[: len(from_trace) - 1], rtol=0, atol=2000)


BAD_TRACES = {
    "non-numeric": (
        "angle [deg],p [bar] absolute\n-360,1\n-355,one\n",
        'line 3: pressure "one" is not a finite number',
    ),
    "columns": ("angle [deg],p [bar] absolute\n-360,1\n-355;1\n", "line 3: 1 columns, expected 2"),
    "non-increasing": (
        "angle [deg],p [bar] absolute\n-360,1\n-355,1\n-356,1\n",
        "line 4: crank angle -356° does not increase",
    ),
    "negative": ("angle [deg],p [bar] absolute\n-360,1\n-355,-0.2\n", "line 3: absolute pressure -0.2 is negative"),
    "short": (
        "angle [deg],p [bar] absolute\n" + "".join(f"{a},1\n" for a in range(-360, 0, 5)),
        "line 73: the angles span 355°",
    ),
    "long": (
        "angle [deg],p [bar] absolute\n" + "".join(f"{a},1\n" for a in range(-360, 371, 5)),
        "line 148: the angles span 730°",
    ),
    "no header": ("-360,1\n-355,1\n", "line 1: holds numbers, not a header"),
    "no unit": ("angle [deg],p\n-360,1\n", 'line 1: the pressure column "p" names no unit'),
    "neither absolute nor gauge": ("angle [deg],p [bar]\n-360,1\n", "say whether the pressure is absolute or gauge"),
    "empty": ("angle [deg],p [bar] absolute\n", "no samples after the header row"),
}


@pytest.mark.parametrize("case", [*sorted(BAD_TRACES), "missing", "not UTF-8", "a directory"])
def test_a_bad_trace_is_refused_at_exit_initialization_naming_file_line_and_fault(unpacked_fmu, tmp_path, case):
    path = tmp_path / "trace.csv"
    if case in BAD_TRACES:
        text, expected = BAD_TRACES[case]
        path.write_text(text)
    elif case == "not UTF-8":
        path.write_bytes(b"angle [deg],p [bar] absolute\n-360,1\xff\n")
        expected = "cannot be read: stream did not contain valid UTF-8"
    elif case == "a directory":
        path.mkdir()
        expected = "cannot be read"
    else:
        expected = "cannot be read: No such file or directory"
    with Instance(unpacked_fmu) as s:
        s.slave.setupExperiment(startTime=0.0)
        s.set(pressure_source=3, pressure_trace=str(path))
        s.slave.enterInitializationMode()
        with pytest.raises(FMICallException):
            s.slave.exitInitializationMode()
        errors = s.messages(FMI_ERROR)
        assert any(f'pressure_trace "{path}"' in m and expected in m for m in errors), errors


def test_a_trace_as_users_keep_it(unpacked_fmu, tmp_path, monkeypatch):
    """The shipped full-load trace written in Pa with a [Pa] header, gauge in [psig], and under the shipped name in
    the working directory (looked up there before the FMU's resources): the same pressure acts as from the
    shipped file; a copy at twice the pressure in the working directory is the one used."""
    angle, bar = trace_of(unpacked_fmu, "full_load.csv")
    monkeypatch.chdir(tmp_path)

    def acting(name):
        return simulate(
            stop_time=0.1,
            output_interval=1e-3,
            output=["gas_pressure_acting"],
            start_values={"pressure_source": 3, "pressure_trace": name},
        )["gas_pressure_acting"]

    shipped = acting("full_load.csv")
    for name, header, values in (
        ("pa.csv", "cylinder pressure [Pa] absolute", bar * 1e5),
        ("psig.csv", "cylinder pressure [psig]", (bar - 1) * 1e5 / 6894.757293168361),
    ):
        rows = "".join(f"{a:.17g},{p:.17g}\n" for a, p in zip(angle, values, strict=True))
        (tmp_path / name).write_text(f"crank angle [deg],{header}\n{rows}")
        np.testing.assert_allclose(acting(name), shipped, rtol=1e-12, atol=1e-6)
    (tmp_path / "full_load.csv").write_text(
        "crank angle [deg],cylinder pressure [bar] absolute\n"
        + "".join(f"{a:.17g},{2 * p:.17g}\n" for a, p in zip(angle, bar, strict=True))
    )
    np.testing.assert_allclose(acting("full_load.csv"), 2 * shipped + 1e5, rtol=1e-12, atol=1e-6)
