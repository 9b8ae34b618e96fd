"""The cylinders of a whole engine (`pistonslap coupled --cylinders N --firing-order 1-3-4-2`): the firing order as
the command takes it, and each cylinder's phase on the one crank.

A four-stroke engine of N cylinders fires evenly, every 720°/N: the cylinder at position p of the firing order
(p = 0 for cylinder 1, which leads it) reaches its firing TDC p · 720°/N after cylinder 1. Each cylinder's crank
angle is its own, firing TDC at 0 mod 4π (DESIGN.md section 3): at the start, where cylinder 1 is at its firing
TDC (0), cylinder k is at 720° − p · 720°/N, in its first cycle, so that every cylinder's n-th cycle ends at its
crank angle n · 720° as the per-cycle figures (`tables.cycle_metrics`) count them. EngineCycle's and PistonSlap's
`crank_angle_start` both take it (`start_angles`).
"""

import numpy as np

from .fmu import CYCLE
from .refusal import Refusal, whole

#: The firing order taken when --cylinders is given without one: the common even-firing orders of in-line engines
#: (twin 1-2, three 1-2-3, four 1-3-4-2, five 1-2-4-5-3, six 1-5-3-6-2-4). V engines have no one common order, and
#: other counts none either: for those the command asks for --firing-order.
DEFAULT_ORDERS = {1: (1,), 2: (1, 2), 3: (1, 2, 3), 4: (1, 3, 4, 2), 5: (1, 2, 4, 5, 3), 6: (1, 5, 3, 6, 2, 4)}


def firing_order(cylinders=None, order=None):
    """The firing order, a tuple of cylinder numbers starting with 1, from the command's `--cylinders` and
    `--firing-order` texts (either may be None: the count is the order's length, the order the count's
    `DEFAULT_ORDERS` entry), or a `Refusal` saying what to give."""
    count = None if cylinders is None else whole(cylinders, "--cylinders", 1)
    if order is None:
        if count not in DEFAULT_ORDERS:
            known = ", ".join(f"{n}: {'-'.join(map(str, o))}" for n, o in DEFAULT_ORDERS.items())
            raise Refusal(
                f"--cylinders = {count}: give --firing-order too (defaults for in-line engines only, {known})"
            )
        return DEFAULT_ORDERS[count]
    parts = order.split("-")
    numbers = [int(p) for p in parts if p.strip().isdigit()]
    size = count or len(parts)
    if len(numbers) != len(parts) or sorted(numbers) != list(range(1, size + 1)):
        raise Refusal(
            f"--firing-order = {order!r}: give each of the {size} cylinders 1 to {size} once, separated by '-' "
            f"(e.g. {'-'.join(map(str, DEFAULT_ORDERS.get(size, range(1, size + 1))))})"
        )
    if numbers[0] != 1:
        raise Refusal(f"--firing-order = {order!r}: start with cylinder 1, the one the others' phases are taken from")
    return tuple(numbers)


def start_angles(order):
    """Each cylinder's crank angle at the start, rad, by cylinder number: 4π less its phase, 0 for cylinder 1."""
    phase = phases(order)
    return np.where(phase > 0, CYCLE - phase, 0.0)


def phases(order):
    """Each cylinder's phase behind cylinder 1, rad, by cylinder number (1, 2, ...): where it fires in the order
    times the firing interval 4π/N."""
    return np.array([order.index(k) for k in range(1, len(order) + 1)]) * CYCLE / len(order)
