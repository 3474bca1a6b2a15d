"""SIGINT and the stop signals held back around work an interrupt must not cut in two (a
library's import): shared by the command line and the audit, importing nothing heavy."""

from __future__ import annotations

import contextlib
from collections.abc import Iterator


def stop_signals() -> list:
    """The signals that end a run as Ctrl-C does, where the platform has them: SIGTERM
    (``kill``, a job scheduler's stop), SIGHUP (the terminal closed), SIGQUIT, SIGUSR1 and
    SIGUSR2 (whose default would end the process and leave its staged output behind)."""
    import signal

    names = ("SIGTERM", "SIGHUP", "SIGQUIT", "SIGUSR1", "SIGUSR2")
    return [getattr(signal, n) for n in names if hasattr(signal, n)]


@contextlib.contextmanager
def signals_held() -> Iterator[None]:
    """SIGINT and the stop signals held back inside the block and delivered at its end, to
    the handlers in force before it (main thread; elsewhere nothing is held).

    Held by Python handlers that only note the signal, not by the thread's signal mask: a
    mask holds a signal back from this thread only, and with MuJoCo's or the audit's
    threads running, the kernel hands it to one of them and Python raises it here at once.
    """
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return
    caught: list = []
    previous: dict = {}
    try:
        for sig in (signal.SIGINT, *stop_signals()):
            if signal.getsignal(sig) not in (signal.SIG_IGN, None):
                previous[sig] = signal.signal(sig, lambda signum, frame: caught.append(signum))
    except (ValueError, OSError):  # no signals here (an embedded interpreter)
        pass
    try:
        yield
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)
        for sig in dict.fromkeys(caught):
            signal.raise_signal(sig)
