"""One FMU under fmpy, the way every tool of the package opens it: unpacked, instantiated with the
package's one logger, its variables set and got by name; an FMI 2.0 or an FMI 3.0 one.

fmpy's native logger proxy (which formats an FMU's variadic messages) keeps one Python logger in a
process-wide slot, so the package installs one logger per process, alive as long as the process,
and files each message under the name of the instance that logged it: `messages(name)`. Messages of
instances the package did not make go on to fmpy's default logger, which prints them, as they
would without the package. An FMI 3.0 instance has a logger of its own (its callback takes no
instance name), which files its messages the same way.
"""
import threading
from ctypes import byref

from fmpy import extract, read_model_description
from fmpy.fmi2 import (FMU2Slave, calloc, fmi2CallbackAllocateMemoryTYPE,
                       fmi2CallbackFreeMemoryTYPE, fmi2CallbackFunctions, fmi2CallbackLoggerTYPE,
                       free, printLogMessage)
from fmpy.fmi3 import FMU3Slave
from fmpy.logging import addLoggerProxy

#: (status, category, message) of every message since the instance of that name was made.
_MESSAGES: dict[str, list] = {}
#: Names of the instances the package made.
_OURS: set[str] = set()


def _text(value) -> str:
    return value.decode(errors="replace") if isinstance(value, bytes) else str(value)


def _log(env, instance, status, category, message):
    name = _text(instance)
    if name in _OURS:
        _MESSAGES.setdefault(name, []).append((status, _text(category), _text(message)))
    else:
        printLogMessage(env, instance, status, category, message)


_LOGGER = fmi2CallbackLoggerTYPE(_log)
_CALLBACKS = fmi2CallbackFunctions()
_CALLBACKS.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
_CALLBACKS.freeMemory = fmi2CallbackFreeMemoryTYPE(free)


_INSTALLING = threading.Lock()


def install_logger():
    """Points fmpy's logger proxy (the process-wide slot) at the package's logger; anything else
    in the process that passed its own logger to fmpy may have pointed it elsewhere.

    Threads may instantiate with `_CALLBACKS` while another installs: its logger is only ever the
    proxy (the slot is pointed through a scratch copy), never the Python logger itself, which
    would receive an FMU's messages unformatted ("%s")."""
    with _INSTALLING:
        scratch = fmi2CallbackFunctions()
        scratch.logger = _LOGGER
        addLoggerProxy(byref(scratch))
        _CALLBACKS.logger = scratch.logger


def messages(name: str) -> list:
    """The messages of the instance called `name` so far, as a list that grows as it logs."""
    return _MESSAGES.setdefault(name, [])


def errors(name: str) -> list:
    """The errors (discard, error, fatal) the instance called `name` logged so far."""
    return [text for status, _, text in messages(name) if status >= 2]


def forget(name: str):
    """Drops the messages of the instance called `name` (its case is over)."""
    _MESSAGES.pop(name, None)


def instantiate(unzipdir, md, name: str, logging_on: bool = False):
    """A new co-simulation instance called `name` of the FMU unpacked in `unzipdir` (with model
    description `md`), logging through the package's logger, its earlier messages forgotten: an
    FMU2Slave or, for an FMI 3.0 FMU, an FMU3Slave."""
    install_logger()
    _OURS.add(name)
    messages(name).clear()
    if md.fmiVersion.startswith("3."):
        fmu = FMU3Slave(guid=md.instantiationToken, unzipDirectory=unzipdir,
                        modelIdentifier=md.coSimulation.modelIdentifier, instanceName=name)

        def log(env, status, category, message):
            messages(name).append((status, _text(category), _text(message)))
        fmu.instantiate(loggingOn=logging_on, logMessage=log)
        return fmu
    fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzipdir,
                    modelIdentifier=md.coSimulation.modelIdentifier, instanceName=name)
    fmu.instantiate(callbacks=_CALLBACKS, loggingOn=logging_on)
    return fmu


#: The fmpy getter and setter of each variable type (FMI 2's and FMI 3's; an FMI 3 Enumeration is
#: exchanged as an Int64).
GETTERS = {"Real": "getReal", "Integer": "getInteger", "Boolean": "getBoolean",
           "String": "getString", "Float64": "getFloat64", "Int32": "getInt32",
           "Enumeration": "getInt64"}
SETTERS = {name: "s" + getter[1:] for name, getter in GETTERS.items()}
#: The Python type of each variable type's values.
PYTHON_TYPES = {"Real": float, "Float64": float, "Integer": int, "Int32": int, "Enumeration": int,
                "Boolean": bool}


class Session:
    """One instance of the FMU at `path`, set up to start at t = 0 (and stop at `stop_time`, if
    given), its variables by name."""

    def __init__(self, path, name, stop_time=None):
        self.md = read_model_description(str(path))
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        self.types = {v.name: v.type for v in self.md.modelVariables}
        self.fmu = instantiate(extract(str(path)), self.md, name)
        self.stop_time = stop_time
        self.fmi3 = self.md.fmiVersion.startswith("3.")
        if not self.fmi3:
            self.fmu.setupExperiment(startTime=0.0, stopTime=stop_time)

    def initialize(self):
        """Enters and exits initialization mode (FMI 3: with the start and stop time)."""
        if self.fmi3:
            self.fmu.enterInitializationMode(startTime=0.0, stopTime=self.stop_time)
        else:
            self.fmu.enterInitializationMode()
        self.fmu.exitInitializationMode()

    def set(self, values):
        """Sets {name: value}, each through the setter of its type."""
        for name, value in values.items():
            kind = self.types[name]
            value = PYTHON_TYPES.get(kind, str)(value)
            getattr(self.fmu, SETTERS[kind])([self.vr[name]], [value])

    def get(self, name):
        """The value of one variable."""
        return getattr(self.fmu, GETTERS[self.types[name]])([self.vr[name]])[0]

    def free(self):
        self.fmu.terminate()
        self.fmu.freeInstance()
