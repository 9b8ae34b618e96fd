"""Refusals of the `pistonslap` commands: arguments checked before any work, each refusal one line.

A command raises `Refusal` (or lets argparse's `Parser.error` raise it); `pistonslap` prints it as one line on
stderr and exits with status 2. Start values go through `check_start_values` first, which initializes the FMU
without stepping it, so a parameter the FMU refuses is reported with the FMU's own message before anything runs.
"""

import argparse
import math

import fmpy

#: fmi2Status of an error, and above it fatal.
_FMI_ERROR = 3
_logger = None


class Refusal(Exception):
    """Arguments a command cannot run with; the message says which and why, in one line."""


class Parser(argparse.ArgumentParser):
    """argparse whose usage errors are a `Refusal` (one line, exit 2) instead of usage text and a message."""

    def error(self, message):
        raise Refusal(f"{message} (see {self.prog} --help)")


def number(text, name, low=None, high=None, low_open=False, unit="", meaning=""):
    """`text` as a finite float within [low, high] (low excluded when `low_open`), or a `Refusal` naming `name`
    (`unit` the one `text` is in, `meaning` what the number is, for the message)."""
    try:
        value = float(text)
    except (TypeError, ValueError):
        raise Refusal(f"{name} = {text!r}: give a number") from None
    below = low is not None and (value <= low if low_open else value < low)
    if not math.isfinite(value) or below or (high is not None and value > high):
        bounds = [f"{'>' if low_open else '>='} {low:g}"] if low is not None else []
        bounds += [f"<= {high:g}"] if high is not None else []
        what = f"{meaning} must be" if meaning else "give"
        raise Refusal(
            f"{name} = {text:g}{unit}: {what} a finite number {' and '.join(bounds)}{unit}".rstrip()
            if isinstance(text, float)
            else f"{name} = {text}: {what} a finite number {' and '.join(bounds)}"
        )
    return value


def whole(text, name, low):
    """`text` as an int >= `low`, or a `Refusal` naming `name`."""
    try:
        value = int(text)
    except (TypeError, ValueError):
        raise Refusal(f"{name} = {text!r}: give a whole number >= {low}") from None
    if value < low:
        raise Refusal(f"{name} = {text}: give a whole number >= {low}")
    return value


def check_start_values(start_values, fmu, model_description=None, shown=str):
    """Initializes the FMU `fmu` (file or extracted folder) with `start_values` without stepping it; a `Refusal`
    carrying the FMU's error message, as `shown` words it (`settings.in_display_units`), when it refuses them."""
    global _logger
    errors = []

    def logger(_component, _instance, status, _category, message):
        if status >= _FMI_ERROR:
            errors.append(message.decode(errors="replace"))

    # fmpy hands the logger to one process-wide native proxy, which may call it after this returns: kept alive.
    _logger = logger
    md = model_description or fmpy.read_model_description(str(fmu))
    unknown = sorted(set(start_values) - {v.name for v in md.modelVariables})
    if unknown:
        raise Refusal(f"the FMU has no variable {', '.join(unknown)}")
    try:
        fmpy.simulate_fmu(
            str(fmu), model_description=md, start_values=dict(start_values), stop_time=0.0, output=[], logger=logger
        )
    except Exception as e:  # fmpy raises its own exception types; the FMU's log says why
        raise Refusal(f"the FMU refuses: {shown(errors[-1]) if errors else e}") from None
    if errors:
        raise Refusal(f"the FMU refuses: {shown(errors[-1])}")
