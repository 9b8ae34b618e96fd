"""A progress line on stderr for a run that takes more than a few seconds: fmpy's `step_finished` callback."""

import sys
import time

#: Runs shorter than this (wall time, s) print no progress.
QUIET_FOR = 3.0


class Progress:
    """Prints `label: N % of the run, S s` on stderr every 10 % of the simulated time once the run has taken
    `quiet_for` seconds, on one line rewritten in place on a terminal, a line each otherwise; `done()` ends it."""

    def __init__(self, label, stop_time, quiet_for=QUIET_FOR, stream=None):
        self.label, self.stop_time, self.quiet_for = label, stop_time, quiet_for
        self.stream = stream or sys.stderr
        self.started, self.next, self.printed = time.monotonic(), 0.1, False

    def __call__(self, now, _recorder=None):
        fraction = now / self.stop_time
        if fraction < self.next:
            return True
        self.next = (int(fraction * 10) + 1) / 10
        elapsed = time.monotonic() - self.started
        if elapsed >= self.quiet_for:
            end = "" if self.stream.isatty() else "\n"
            line = f"{self.label}: {min(100 * fraction, 100):3.0f} % of the run, {elapsed:.0f} s"
            print(f"\r{line}", end=end, file=self.stream, flush=True)
            self.printed = True
        return True

    def done(self):
        """Ends a line rewritten in place."""
        if self.printed and self.stream.isatty():
            print(file=self.stream, flush=True)
