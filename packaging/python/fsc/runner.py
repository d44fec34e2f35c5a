"""One case of a study: the FMU through fmpy, metrics computed where it ran.

`run_case` is what Dask ships to the workers. The FMU arrives as bytes (through Dask, no shared
filesystem); each worker process unpacks it once per GUID and reuses the directory, the parsed
modelDescription and its FMU instances for every later case: an idle instance is reset
(`fmi2Reset`) instead of loaded and instantiated anew, as fmpy's `efficient_loops` example does
(one instance per thread that runs cases at the same time), and an instance whose case failed is
discarded.
"""
import atexit
import itertools
import os
import shutil
import tempfile
import time
import zipfile
from io import BytesIO

import numpy as np

from fmpy import read_model_description, simulate_fmu

from . import session

#: Outputs the metrics are computed from (those the FMU does not have are skipped).
METRIC_OUTPUTS = ["joint.force", "joint.forcePeak", "joint.contactOnsetsTotal", "slider.acceleration",
                  "slider.accelerationPeak", "rod.deformationEnergy", "energy.dissipated",
                  "solver.steps", "crankPin.forcePeak", "mainBearing.forcePeak", "guide.forcePeak",
                  "rod.stressPeak"]

_unpacked = {}   # GUID -> (directory, model description), per worker process
_idle = {}       # GUID -> FMU instances not running a case, per worker process
_names = itertools.count()


def _instance(directory, md):
    """An idle instance of the FMU, reset, or a new one with a name of its own (its logged errors
    are told apart by that name, also when cases run in parallel threads of one worker)."""
    idle = _idle.setdefault(md.guid, [])
    if idle:
        fmu = idle.pop()
        fmu.reset()
        return fmu
    return session.instantiate(directory, md, f"fsc-{os.getpid()}-{next(_names)}")


def unpacked(fmu_bytes: bytes, guid: str):
    """The FMU unpacked in this process (once per GUID) and its model description."""
    if guid not in _unpacked:
        directory = tempfile.mkdtemp(prefix=f"fsc-{os.getpid()}-")
        # Removed when the worker process ends (the instances use the library until then).
        atexit.register(shutil.rmtree, directory, True)
        with zipfile.ZipFile(BytesIO(fmu_bytes)) as z:
            z.extractall(directory)
        # The FMU's resources, where the cases' files go (the FMU looks there when instantiated).
        os.makedirs(os.path.join(directory, "resources"), exist_ok=True)
        md = read_model_description(directory)
        if md.guid != guid:
            raise ValueError(f"FMU GUID {md.guid}, expected {guid}")
        _unpacked[guid] = (directory, md, {v.name for v in md.modelVariables})
    return _unpacked[guid]


def metrics(result, start: float = 0.0) -> dict:
    """Metrics of one result (fmpy structured array) over the rows after `start` [s] (all rows at
    0): the peaks, the RMS and the largest energy of that window, the contact onsets and the
    dissipated energy in it. A row's peak-hold covers the interval that ends at it."""
    names = result.dtype.names
    window = result["time"] > start if start > 0 else np.ones(len(result), dtype=bool)
    first = max(int(np.argmax(window)) - 1, 0) if start > 0 else None
    col = (lambda n: result[n].astype(float)[window] if n in names else None)

    def change(name):
        total = result[name].astype(float)
        return total[-1] - (total[first] if first is not None else 0.0)

    def peak(name):
        return float(np.max(col(name))) if name in names else float("nan")

    force = col("joint.forcePeak") if "joint.forcePeak" in names else col("joint.force")
    accel = col("slider.acceleration")
    accel_peak = col("slider.accelerationPeak")
    return {
        "peak_joint_force": float(np.max(force)),
        "peak_crank_pin_force": peak("crankPin.forcePeak"),
        "peak_main_bearing_force": peak("mainBearing.forcePeak"),
        "peak_guide_force": peak("guide.forcePeak"),
        "peak_rod_stress": peak("rod.stressPeak"),
        "contact_onsets": int(change("joint.contactOnsetsTotal"))
        if "joint.contactOnsetsTotal" in names else -1,
        "slider_acceleration_rms": float(np.sqrt(np.mean(accel ** 2))),
        "slider_acceleration_peak": float(np.max(accel_peak if accel_peak is not None
                                                 else np.abs(accel))),
        "max_deformation_energy": float(np.max(col("rod.deformationEnergy"))),
        "energy_dissipated": float(change("energy.dissipated")),
        "solver_steps": int(result["solver.steps"][-1]),
    }


def input_signals(inputs: dict | None):
    """The input series {"time": [...], name: [...]} as fmpy's structured array, or None."""
    if not inputs:
        return None
    names = list(inputs)
    return np.array(list(zip(*(inputs[n] for n in names))), dtype=[(n, float) for n in names])


def run_case(fmu_bytes: bytes, guid: str, values: dict, stop_time: float,
             output_interval: float, series: list, metrics_start: float = 0.0,
             inputs: dict | None = None, files: dict | None = None):
    """Runs one case: (status, message, metrics, series columns or None), with the input series
    `inputs` (interpolated linearly to each output point and held over the interval that starts
    there) and `files` (name in the FMU's resources: bytes) written where the FMU finds them. Never raises for a failing case:
    its status is "error" and its message the FMU's logged error (or the exception)."""
    directory, md, have = unpacked(fmu_bytes, guid)
    for name, data in (files or {}).items():
        target = os.path.join(directory, "resources", name)
        if not os.path.exists(target):
            os.makedirs(os.path.dirname(target), exist_ok=True)
            with open(target + ".part", "wb") as f:
                f.write(data)
            os.replace(target + ".part", target)
    outputs = [n for n in dict.fromkeys(METRIC_OUTPUTS + list(series)) if n in have]
    start = time.perf_counter()
    session.install_logger()
    fmu = None
    try:
        fmu = _instance(directory, md)
        # fmpy interpolates the series at each communication point and holds the value over the
        # step (its set_input_derivatives sizes the derivative buffer for nine inputs only).
        result = simulate_fmu(directory, model_description=md, start_values=values,
                              stop_time=stop_time, output_interval=output_interval,
                              output=outputs, fmu_instance=fmu, input=input_signals(inputs))
    except Exception as e:   # noqa: BLE001 - a failing case is a row, never the end of the study
        message = "; ".join(session.errors(fmu.instanceName) if fmu else []) or str(e)
        if fmu is not None:
            session.forget(fmu.instanceName)
        if fmu is not None:
            try:
                fmu.freeInstance()
            except Exception:   # noqa: BLE001 - the instance is discarded either way
                pass
        return "error", message, None, None
    session.forget(fmu.instanceName)
    _idle[md.guid].append(fmu)
    wall = time.perf_counter() - start
    m = metrics(result, metrics_start)
    m["wall_time"] = wall
    kept = None
    if series:
        kept = {"time": result["time"].astype(float)}
        kept.update({n: result[n].astype(float) for n in series})
    return "ok", "", m, kept
