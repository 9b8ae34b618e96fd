"""The thesis's quantities of a variant-2 run and its response class (periodic, transient chaos, chaos), from the
FMU's impact log: shared by the thesis analysis and the parameter sweeps."""

from dataclasses import dataclass, field

import numpy as np

#: xi = r/l, alpha = m/M, beta = J_r/(M l^2) of the thesis's Ford engine (section 4.1).
XI, ALPHA, BETA = 0.3030, 1.9, 0.4719
CRANK_CYCLE = 2 * np.pi


@dataclass
class Run:
    """One simulated case, in thesis units: every impact and sliding start of `cycles` crank cycles."""

    lam: float
    rho: float
    e: float
    forcing: int
    cycles: int
    #: per impact: crank cycle index, crank angle mod 2*pi, wall (+1 upper, -1 lower), psi' before the
    #: impact, relative approach rate |psi' - psi_wall'|, location x = axial position / l in [1 - xi, 1 + xi]
    cycle: np.ndarray = field(repr=False)
    theta: np.ndarray = field(repr=False)
    wall: np.ndarray = field(repr=False)
    rate: np.ndarray = field(repr=False)
    approach: np.ndarray = field(repr=False)
    location: np.ndarray = field(repr=False)
    #: crank cycle index of every sliding start
    slide_cycle: np.ndarray = field(repr=False)

    def window(self, first_cycle):
        """Mask of the impacts from crank cycle `first_cycle` on (the statistics after the transient)."""
        return self.cycle >= first_cycle


def impacts_from_log(events, rho, start=0.0, xi=XI, length=1.0, speed=1.0):
    """Thesis quantities of the impact-log rows of a run (crank angle `start` at time 0, prescribed crank speed
    `speed` in rad/s, rod `length` in m, clearance `rho` and crank ratio `xi` relative to it); thesis units
    (l = 1, Omega = 1) by default."""
    impacts = events[events["kind"] == "impact"]
    theta = start + speed * impacts["time"]  # crank angle, accumulated
    big = np.sqrt(1 - xi**2 * np.sin(theta) ** 2)
    wall = np.where(impacts["corner"] == 1, 1, -1)  # the upper wall is corner 1's (x = -D/2)
    approach = impacts["normal_velocity_before"] / (length * big * speed)
    # psi_max' = rho xi^2 sin cos / Lambda^3; psi_min' = -psi_max'; approach is toward the wall
    wall_rate = rho * xi**2 * np.sin(theta) * np.cos(theta) / big**3
    rate = wall * (wall_rate + approach)
    slides = events[events["kind"] == "slide"]
    return dict(
        cycle=np.floor(theta / CRANK_CYCLE).astype(int),
        theta=np.mod(theta, CRANK_CYCLE),
        wall=wall,
        rate=rate,
        approach=approach,
        location=impacts["position"] / length,
        slide_cycle=np.floor((start + speed * slides["time"]) / CRANK_CYCLE).astype(int),
    )


def roller_run(events, values, cycles):
    """The `Run` of a variant-2 run of `cycles` crank cycles at any scale, from its FMU start values `values`
    (every parameter the roller reads, by name) and its impact log: the thesis's quantities, l and Omega
    divided out."""
    length = values["rod_length"]
    rho = (values["bore"] - values["piston_diameter"]) / (2 * length)
    quantities = impacts_from_log(
        events, rho, values["crank_angle_start"], values["crank_radius"] / length, length, values["crank_speed"]
    )
    lam = values["damping_crank_pin"] / (values["piston_mass"] * length**2 * values["crank_speed"])
    return Run(lam=lam, rho=rho, e=values["restitution"], forcing=values["roller_forcing"], cycles=cycles, **quantities)


@dataclass
class Response:
    """The steady response by recurrence of the impacts: `kind` is 'periodic', 'transient chaos' or 'chaos';
    `period` in crank cycles and `settled` (first crank cycle of the recurring pattern) when it recurs."""

    kind: str
    period: int = 0
    settled: int = 0

    def __str__(self):
        if self.kind == "chaos":
            return "chaos"
        return f"{self.kind} (period {self.period}, settled at cycle {self.settled})"


def _cycle_patterns(run):
    """Per crank cycle: the impacts as an array of (wall, theta, psi') rows, in order."""
    order = np.argsort(run.cycle, kind="stable")
    rows = np.column_stack([run.wall, run.theta, run.rate])[order]
    bounds = np.searchsorted(run.cycle[order], np.arange(run.cycles + 1))
    return [rows[bounds[k] : bounds[k + 1]] for k in range(run.cycles)]


#: Crank cycles of chaos after which a response that becomes periodic counts as transient chaos. The thesis
#: calls it so when chaos lasts "well beyond what would be typically considered as transient" (its 30 cycles)
#: and sees it as a background in the impact profile of the 1500 cycles after them; chaos over less than
#: about 5 % of those (75 cycles) leaves none. The start (psi = psi' = 0 at theta = 0) is ours, not the
#: thesis's, and transients of 20-140 cycles come and go with the starting crank angle.
CHAOTIC_TRANSIENT = 100
#: Longest period looked for (crank cycles), and the periods a recurrence must last to count.
MAX_PERIOD, MIN_REPEATS = 16, 10
#: Crank cycles a run needs for `classify` to tell all three responses apart at every period up to MAX_PERIOD:
#: the transient allowed, then MIN_REPEATS + 1 periods.
CLASSIFIABLE_CYCLES = CHAOTIC_TRANSIENT + MAX_PERIOD * (MIN_REPEATS + 1)


def classify(
    run, settle_limit=CHAOTIC_TRANSIENT, max_period=MAX_PERIOD, tolerance=1e-3, coarse=0.05, min_repeats=MIN_REPEATS
):
    """Classifies the response by the recurrence of each crank cycle's impacts (the points of the Poincare
    section and their lower-wall counterparts): cycle k recurs with period p when cycle k + p has the same
    walls in the same order, at crank angles (rad) and rates (in units of rho) within a tolerance.

    The smallest p whose recurrence within `tolerance` holds from some cycle to the end, for at least
    `min_repeats` periods, makes the response periodic. It settled where the recurrence within `coarse`
    begins: a regular approach to the orbit is already close to it then, a chaotic transient is not. It is
    'periodic' if it settled within `settle_limit` cycles, else 'transient chaos'."""
    patterns = _cycle_patterns(run)
    n = len(patterns)
    # crank angle in rad, rates relative to the clearance rho (psi' is of order rho)
    scale = np.array([1.0, run.rho])

    def recurs_from(p, tol):
        def same(a, b):
            return a.shape == b.shape and (
                a.size == 0 or (np.array_equal(a[:, 0], b[:, 0]) and (np.abs(a[:, 1:] - b[:, 1:]) / scale).max() < tol)
            )

        k = n - p - 1
        while k >= 0 and same(patterns[k], patterns[k + p]):
            k -= 1
        return k + 1

    best = None
    for p in range(1, max_period + 1):
        settled = recurs_from(p, tolerance)
        if n - settled >= p * (min_repeats + 1) and (best is None or settled < best[1]):
            best = (p, settled)
    if best is None:
        return Response("chaos")
    period = best[0]
    settled = recurs_from(period, coarse)
    return Response("periodic" if settled <= settle_limit else "transient chaos", period, settled)
