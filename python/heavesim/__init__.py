"""heavesim from Python (docs/python.md).

    import heavesim
    r = heavesim.run("cases/drilling.yaml", set={"solver.t_end": 20})
    r.summary["compensator_efficiency"], r["joints/td_string/reaction_force"]
    r = heavesim.open("results/drilling.h5")

run() and check() call the same C++ functions as `heavesim run --quiet` and `heavesim
check`, in this process; open() reads any result file with h5py. Errors are exceptions
of the executable's exit-code classes: InputError (exit 2), NumericalFailure (exit 3,
with the partial result), Error (exit 1: a write that failed, a signal).
"""
import json
import os

from .result import Channel, Result

try:
    from . import _heavesim
except ImportError as _missing:  # the reader works without the compiled module
    _heavesim = None
    _import_error = _missing

__all__ = ["run", "check", "open", "Result", "Channel", "Error", "InputError", "NumericalFailure", "version"]

version = _heavesim.version if _heavesim is not None else None


class Error(Exception):
    """heavesim could not do what was asked (exit code 1 of the executable: an output that
    could not be written, a stop by signal). The message is the executable's."""


class InputError(Error, ValueError):
    """Bad input (exit code 2): the message names file:line:column, the key path, what was
    found and what was expected, as `heavesim check` prints it."""


class NumericalFailure(Error):
    """The integration failed (exit code 3). `result` is the partial Result (complete =
    False, samples up to the failure), `time` the failure time [s], `suggestion` the remedy."""

    def __init__(self, message, result=None):
        super().__init__(message)
        self.result = result
        attributes = result.attributes if result is not None else {}
        self.time = attributes.get("failure_time")
        self.suggestion = attributes.get("failure_suggestion")


def _compiled():
    if _heavesim is None:
        raise ImportError("heavesim's compiled module (_heavesim) is not built: build the project "
                          f"(scripts/build.sh) and put <build>/python on PYTHONPATH ({_import_error})")
    return _heavesim


def _value_text(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, (list, tuple, dict)):
        return json.dumps(value)  # a YAML flow collection
    return str(value)


def _overrides(settings):
    """{"solver.t_end": 20} or ["solver.t_end=20"] as the executable's --set lines."""
    if settings is None:
        return []
    if isinstance(settings, dict):
        return [f"{key}={_value_text(value)}" for key, value in settings.items()]
    if isinstance(settings, str):
        return [settings]
    return [str(line) for line in settings]


def _raise_for(code, message, result=None):
    message = message.strip()
    if message.startswith("heavesim: "):
        message = message[len("heavesim: "):]
    if code == 2:
        raise InputError(message)
    if code == 3:
        raise NumericalFailure(message, result)
    if "stopped by signal 2 " in message:
        raise KeyboardInterrupt(message)
    raise Error(message)


def run(case, set=None, output=None, csv=None, allow_large_runs=False):
    """Runs `case` (a path) with overrides `set` ({"key.path": value} or ["key.path=value"])
    and returns its Result. `output`: the result file (default results/<case name>.h5, as
    the executable); `csv`: a directory for <case name>.csv. Raises InputError,
    NumericalFailure (with .result) or Error."""
    code, path, message = _compiled().run(os.fspath(case), _overrides(set), os.fspath(output) if output else "",
                                          os.fspath(csv) if csv else "", bool(allow_large_runs))
    if code == 0:
        return Result(path)
    partial = None
    if code == 3 and path and os.path.exists(path):
        partial = Result(path)
    _raise_for(code, message, partial)


def check(case, set=None, allow_large_runs=False):
    """Loads and checks `case` without running it, as `heavesim check`; returns what that
    prints (the model, loops, run size). Raises InputError for bad input."""
    code, printed, message = _compiled().check(os.fspath(case), _overrides(set), bool(allow_large_runs))
    if code != 0:
        _raise_for(code, message)
    return printed


def open(path):  # noqa: A001 (heavesim.open, like h5py.File and io.open)
    """Opens a result file of any heavesim command (run, kinematics, equilibrium), also one
    still being written: see Result."""
    return Result(os.fspath(path))
