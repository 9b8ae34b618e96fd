"""A progress line on stderr for a run that takes more than a few seconds: fmpy's `step_finished` callback.

`PISTONSLAP_PROGRESS_AFTER` (seconds, default 3) sets how long a run stays quiet; 0 shows every run's progress.
"""

import os
import sys
import time


def quiet_time():
    """Runs shorter than this (wall time, s) print no progress: `PISTONSLAP_PROGRESS_AFTER`, default 3."""
    return float(os.environ.get("PISTONSLAP_PROGRESS_AFTER", 3.0))


class Progress:
    """Prints `label: N % of the run, S s` on stderr every 10 % of the simulated time once the run has taken
    `quiet_for` seconds (default `quiet_time()`), on one line rewritten in place on a terminal, a line each
    otherwise; `done()` ends it with a line of its own."""

    def __init__(self, label, stop_time, quiet_for=None, stream=None):
        self.label, self.stop_time = label, stop_time
        self.quiet_for = quiet_time() if quiet_for is None else quiet_for
        self.stream = stream or sys.stderr
        self.started, self.next, self.printed = time.monotonic(), 0.1, False

    def __call__(self, now, _recorder=None):
        fraction = now / self.stop_time
        if fraction < self.next:
            return True
        self.next = (int(fraction * 10) + 1) / 10
        elapsed = time.monotonic() - self.started
        if elapsed >= self.quiet_for:
            line = f"{self.label}: {min(100 * fraction, 100):3.0f} % of the run, {elapsed:.0f} s"
            if self.stream.isatty():
                print(f"\r{line}", end="", file=self.stream, flush=True)
            else:
                print(line, file=self.stream, flush=True)
            self.printed = True
        return True

    def done(self):
        """Ends the progress (the run may stop before its stop time): a last line once any was printed."""
        if self.printed:
            line = f"{self.label}: done in {time.monotonic() - self.started:.0f} s"
            print(f"\r{line}" if self.stream.isatty() else line, file=self.stream, flush=True)
