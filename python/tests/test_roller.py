"""Farahanchi's roller slider crank (model_variant 2) through the FMU, with roller_forcing = 1 (f as printed,
which produced the thesis's results): the thesis's statements that do not depend on chaos details, and the
analysis tools on data whose answer is known."""

import numpy as np
import pytest

from pistonslap import analysis
from pistonslap.fmu import simulate


def steady(run, first_cycle=30):
    return run.window(first_cycle)


def test_sliding_on_the_upper_wall_never_releases_at_high_damping(fmu_file):
    """Fig 2.9: at lambda = 0.35 the upper wall holds the roller over the whole cycle; with e = 0 the roller
    comes to slide there and never leaves, pressed by a positive force."""
    values = analysis.thesis_start_values(0.35, 0.01, 0.0)
    result = simulate(
        stop_time=6 * np.pi,
        output_interval=0.05,
        start_values=values,
        output=["contact_state_1", "contact_state_3", "contact_force_1", "piston_lateral"],
    )
    later = result["time"] > 2 * np.pi
    assert np.all(result["contact_state_1"][later] == 1)
    assert np.all(result["contact_state_3"][later] == 0)
    assert np.all(result["contact_force_1"][later] > 0)
    assert np.allclose(result["piston_lateral"][later], -0.01, atol=1e-12)


def test_thesis_periodic_case_is_periodic(fmu_file):
    """Section 4.3: (lambda, rho, e) = (0.05, 0.015, 0.9) is periodic (Figs 4.10, 4.18)."""
    run = analysis.simulate_case(0.05, 0.015, 0.9, cycles=200, progress=False)
    response = analysis.classify(run)
    assert response.kind == "periodic", response


def test_no_lower_wall_impacts_at_high_damping(fmu_file):
    """Section 4.4: at lambda = 0.25 there are no impacts on the lower wall in steady state."""
    run = analysis.simulate_case(0.25, 0.015, 0.9, cycles=100, progress=False)
    mask = steady(run)
    assert mask.sum() > 100
    assert np.all(run.wall[mask] == 1)


def test_lower_restitution_gives_periodic_sliding(fmu_file):
    """Section 4.4: at (lambda, rho) = (0.05, 0.02), e = 0.5 gives a periodic response with sliding."""
    run = analysis.simulate_case(0.05, 0.02, 0.5, cycles=200, progress=False)
    assert analysis.classify(run).kind == "periodic"
    assert (run.slide_cycle >= 30).sum() >= 100


def test_impact_velocities_grow_with_the_clearance(fmu_file):
    """Section 4.3: the average impact velocity grows with rho (upper wall, lambda = 0.05, e = 0.9)."""
    means = []
    for rho in (0.01, 0.015, 0.02):
        run = analysis.simulate_case(0.05, rho, 0.9, cycles=200, progress=False)
        upper = steady(run) & (run.wall == 1)
        means.append(np.abs(run.rate[upper]).mean())
    assert means[0] < means[1] < means[2], means


def test_impact_log_gives_eq_2_17(fmu_file):
    """The log's normal speeds are the thesis's relative rates times l Lambda Omega: after an impact the rate
    relative to the moving wall is -e times the one before (eq 2.17), and every Poincare point lies on
    the section of eq 3.4."""
    e = 0.7
    run = analysis.simulate_case(0.1, 0.02, e, cycles=20, progress=False)
    assert len(run.rate) > 20
    theta, rate = analysis.poincare_points(run, 0)
    assert np.all(rate > 0) and np.all((theta >= 0) & (theta < 2 * np.pi))
    assert np.all(run.approach > 0)
    # x = axial position / l stays in the domain of eq 3.6
    assert np.all((run.location > 1 - analysis.XI - 1e-3) & (run.location < 1 + analysis.XI + 1e-3))


def synthetic_run(cycles, pattern):
    """A Run whose impacts in cycle k are pattern(k): [(wall, theta, rate)]."""
    rows = [(k, w, th, r) for k in range(cycles) for w, th, r in pattern(k)]
    k, w, th, r = (np.array(c) for c in zip(*rows, strict=True))
    return analysis.Run(
        lam=0.1,
        rho=0.01,
        e=0.9,
        forcing=1,
        cycles=cycles,
        cycle=k.astype(int),
        theta=th,
        wall=w.astype(int),
        rate=r,
        approach=np.abs(r),
        location=np.ones_like(r),
        slide_cycle=np.array([], dtype=int),
    )


def test_classifier_on_known_sequences():
    """Period 2 from the start; period 1 after 150 irregular cycles; never recurring."""
    rng = np.random.default_rng(1)
    period_two = synthetic_run(300, lambda k: [(1, 1.0 + 0.5 * (k % 2), 0.02), (-1, 4.0, -0.01)])
    assert (analysis.classify(period_two).kind, analysis.classify(period_two).period) == ("periodic", 2)
    noise = rng.uniform(0, 2 * np.pi, 300)
    settles = synthetic_run(300, lambda k: [(1, noise[k] if k < 150 else 2.0, 0.02)])
    response = analysis.classify(settles)
    assert (response.kind, response.period, response.settled) == ("transient chaos", 1, 150)
    chaos = synthetic_run(300, lambda k: [(1, noise[k], 0.02)])
    assert analysis.classify(chaos).kind == "chaos"


def test_profile_and_spectra_follow_eqs_3_6_and_3_7():
    """Sums of |psi'| per bin over the total number of impacts; upper positive, lower negative."""
    run = synthetic_run(40, lambda k: [(1, 0.5, 0.02), (-1, 3.5, -0.01)])
    run.location = np.where(run.wall == 1, 1.2, 0.8)
    edges, upper, lower = analysis.impact_profile(run, first_cycle=10, bins=10)
    assert upper.sum() == pytest.approx(0.02 * 30 / 60) and lower.sum() == pytest.approx(-0.01 * 30 / 60)
    assert upper[np.searchsorted(edges, 1.2) - 1] == pytest.approx(0.01)
    _, s_upper, s_lower = analysis.impact_spectra(run, first_cycle=10, bins=12)
    assert s_upper[0] == pytest.approx(0.01) and s_lower[6] == pytest.approx(0.005)


def test_crank_train_in_the_roller_limit_matches_the_roller(fmu_file):
    """Variant 1 with a short piston, centred pin, uniform rod, no gravity, gas force or pin
    damping gives the impact sequence of variant 2 (roller_forcing = 2) on the same wall, corner 1's at
    x = -D/2, without mirroring; the differences shrink with the clearance."""
    differences = []
    for clearance in (20e-6, 160e-6):
        crank_train, roller = analysis.cross_check(clearance)
        assert len(crank_train) == len(roller) >= 8
        assert np.all(crank_train["kind"] == roller["kind"])
        impacts = roller["kind"] == "impact"
        speed = np.abs(
            crank_train["normal_velocity_before"][impacts] / roller["normal_velocity_before"][impacts] - 1
        ).max()
        angle = np.abs(crank_train["time"] - roller["time"]).max() * 125.66
        assert speed < 2e-3 and angle < 1e-3
        differences.append(speed)
    assert differences[0] < differences[1] / 4
