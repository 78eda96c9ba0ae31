"""The one exception family for user-facing failures.

The CLI maps ``InputError`` to exit code 2 and ``TaskFailed`` to exit code 1 and prints the
message on one line, never a traceback.
"""

from __future__ import annotations


class RealsimError(Exception):
    """Base class of every error meant for the user: the message says what and what to do."""

    exit_code: int = 2


class InputError(RealsimError):
    """Bad input or usage: missing, empty, corrupt or unsupported files, impossible options."""

    exit_code = 2


class TaskFailed(RealsimError):
    """A commanded task ran but did not reach its goal."""

    exit_code = 1


class SimulationDiverged(RealsimError):
    """The physics blew up (non-finite or runaway state): stopped with a message, never a hang."""

    exit_code = 3
