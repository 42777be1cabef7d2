"""A stand-in for the progress bar that presses Ctrl-C: tests of runs interrupted part way."""


class InterruptAfter:
    """A progress bar whose update raises KeyboardInterrupt once past ``after`` seconds of
    simulated time (a Ctrl-C between two steps or restarts of the integrator)."""

    def __init__(self, after):
        self.done, self.after = 0.0, after

    def __call__(self, *args, **kwargs):
        return self

    def update(self, dt):
        self.done += dt
        if self.done > self.after:
            raise KeyboardInterrupt

    def close(self):
        pass
