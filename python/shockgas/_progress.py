"""Progress of long computations: a caller's callback, a tqdm bar, or a line on stderr.

The compiled core calls ``progress(stage, fraction, time)`` on the calling thread
(never from a worker thread), at most every 50 ms: ``stage`` names the part
running ("particles", "continuum/<solver>"), ``fraction`` is the share of that
stage done in [0, 1] and ``time`` the simulated time reached.
"""

import sys


class _Bars:
    """One tqdm bar per stage (tqdm: https://tqdm.github.io)."""

    def __init__(self, tqdm):
        self._tqdm = tqdm
        self._bar = None
        self._stage = None

    def __call__(self, stage, fraction, time):
        if stage != self._stage:
            self.close()
            self._bar = self._tqdm(total=100, desc=stage, leave=False,
                                   bar_format="{desc}: {percentage:3.0f}%|{bar}| {elapsed}<{remaining}{postfix}")
            self._stage = stage
        self._bar.n = round(100 * min(max(fraction, 0.0), 1.0), 1)
        self._bar.set_postfix_str(f"t = {time:.4g}", refresh=False)
        self._bar.refresh()

    def close(self):
        if self._bar is not None:
            self._bar.close()
        self._bar = None


class _Line:
    """A redrawn line on stderr, where tqdm is not installed."""

    def __init__(self):
        self._drawn = False

    def __call__(self, stage, fraction, time):
        sys.stderr.write(f"\r{stage}: {100 * fraction:5.1f}%  t = {time:.4g}   ")
        sys.stderr.flush()
        self._drawn = True

    def close(self):
        if self._drawn:
            sys.stderr.write("\n")
        self._drawn = False


class Progress:
    """The progress argument of shockgas's long functions, as a context manager.

    None or False: nothing shown. True: a tqdm bar per stage where tqdm is
    installed, else a line on stderr. A callable: called as
    ``progress(stage, fraction, time)``.
    """

    def __init__(self, progress):
        self.callback = None
        self._display = None
        if progress is True:
            try:
                from tqdm.auto import tqdm
                self._display = _Bars(tqdm)
            except ImportError:
                self._display = _Line()
            self.callback = self._display
        elif callable(progress):
            self.callback = progress
        elif progress not in (None, False):
            raise TypeError("progress: None, True or a callable progress(stage, fraction, time)")

    def __enter__(self):
        return self.callback

    def __exit__(self, *exc):
        if self._display is not None:
            self._display.close()
        return False
