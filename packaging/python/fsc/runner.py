"""One case of a study: the FMU through fmpy, metrics computed where it ran.

`run_case` is what Dask ships to the workers. The FMU arrives as bytes (through Dask, no shared
filesystem); each worker process unpacks it once per GUID and reuses the directory, the parsed
modelDescription and one FMU instance for every later case: the instance is reset between cases
(`fmi2Reset`) instead of loaded and instantiated anew, as fmpy's `efficient_loops` example does,
and is discarded after a failing case.
"""
import os
import tempfile
import time
import zipfile
from io import BytesIO

import numpy as np
from fmpy import read_model_description, simulate_fmu
from fmpy.simulation import instantiate_fmu

#: Outputs the metrics are computed from (those the FMU does not have are skipped).
METRIC_OUTPUTS = ["joint.force", "joint.forcePeak", "joint.contactOnsetsTotal", "slider.acceleration",
                  "slider.accelerationPeak", "rod.deformationEnergy", "energy.dissipated",
                  "solver.steps"]

_unpacked = {}   # GUID -> (directory, model description), per worker process
_instances = {}  # GUID -> FMU instance, reset between cases, per worker process
_messages = []   # errors the FMU logged during the current case


def _logger(_env, _instance, status, _category, message):
    if status >= 2:   # discard, error, fatal
        _messages.append(message.decode(errors="replace") if isinstance(message, bytes)
                         else str(message))


def unpacked(fmu_bytes: bytes, guid: str):
    """The FMU unpacked in this process (once per GUID) and its model description."""
    if guid not in _unpacked:
        directory = tempfile.mkdtemp(prefix=f"fsc-{os.getpid()}-")
        with zipfile.ZipFile(BytesIO(fmu_bytes)) as z:
            z.extractall(directory)
        md = read_model_description(directory)
        if md.guid != guid:
            raise ValueError(f"FMU GUID {md.guid}, expected {guid}")
        _unpacked[guid] = (directory, md, {v.name for v in md.modelVariables})
    return _unpacked[guid]


def metrics(result) -> dict:
    """Metrics of one result (fmpy structured array)."""
    names = result.dtype.names
    col = (lambda n: result[n].astype(float) if n in names else None)
    force = col("joint.forcePeak") if "joint.forcePeak" in names else col("joint.force")
    accel = col("slider.acceleration")
    accel_peak = col("slider.accelerationPeak")
    return {
        "peak_joint_force": float(np.max(force)),
        "contact_onsets": int(result["joint.contactOnsetsTotal"][-1])
        if "joint.contactOnsetsTotal" in names else -1,
        "slider_acceleration_rms": float(np.sqrt(np.mean(accel ** 2))),
        "slider_acceleration_peak": float(np.max(accel_peak if accel_peak is not None
                                                 else np.abs(accel))),
        "max_deformation_energy": float(np.max(col("rod.deformationEnergy"))),
        "energy_dissipated": float(col("energy.dissipated")[-1]),
        "solver_steps": int(result["solver.steps"][-1]),
    }


def run_case(fmu_bytes: bytes, guid: str, values: dict, stop_time: float,
             output_interval: float, series: list):
    """Runs one case: (status, message, metrics, series columns or None). Never raises for a
    failing case: its status is "error" and its message the FMU's logged error (or the
    exception)."""
    directory, md, have = unpacked(fmu_bytes, guid)
    outputs = [n for n in dict.fromkeys(METRIC_OUTPUTS + list(series)) if n in have]
    _messages.clear()
    start = time.perf_counter()
    fmu = _instances.pop(guid, None)
    try:
        if fmu is None:
            fmu = instantiate_fmu(directory, md, logger=_logger)
        else:
            fmu.reset()
        result = simulate_fmu(directory, model_description=md, start_values=values,
                              stop_time=stop_time, output_interval=output_interval,
                              output=outputs, fmu_instance=fmu)
    except Exception as e:   # noqa: BLE001 - a failing case is a row, never the end of the study
        message = "; ".join(_messages) or str(e)
        if fmu is not None:
            try:
                fmu.freeInstance()
            except Exception:   # noqa: BLE001 - the instance is discarded either way
                pass
        return "error", message, None, None
    _instances[guid] = fmu
    wall = time.perf_counter() - start
    m = metrics(result)
    m["wall_time"] = wall
    kept = None
    if series:
        kept = {"time": result["time"].astype(float)}
        kept.update({n: result[n].astype(float) for n in series})
    return "ok", "", m, kept
