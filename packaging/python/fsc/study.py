"""Study files: what to vary, what to keep, checked against the FMU's modelDescription before any run.

A study is a TOML file:

    fmu = "../target/fmu/FlexibleSliderCrank.fmu"   # relative to the study file (optional)
    stop_time = 0.024                               # default: the DefaultExperiment's
    output_interval = 1e-4                          # default: the DefaultExperiment's step
    metrics_start = 0.005                           # metrics over t > 5 ms (default 0: all)
    series = ["slider.acceleration"]                # time series to keep (optional)

    [fixed]                                         # start values of every case
    "rod.formulation" = 3

    [grid]                                          # full factorial product
    "joint.clearance" = [1e-4, 5e-4, 1e-3]
    [grid.speed]                                    # parameters that vary together (one axis)
    "crank.initialSpeed" = [104.72, 523.6]
    "drive.speed" = [104.72, 523.6]

    [[cases]]                                       # explicit cases (each combined with the grid)
    "rod.nModes" = 4

    [random]                                        # seeded samples (each combined with the grid)
    samples = 20
    seed = 1
    [random.uniform]
    "joint.friction" = [0.0, 0.2]

    [inputs]                                        # input series of every case (optional):
    time = [0.0, 0.01, 0.024]                       # a time column and a column per input,
    "drive.torque" = [0.0, 4.0, 4.0]                # interpolated linearly to each output point
                                                    # and held over the interval after it; or
                                                    # file = "inputs.csv" with a header row
                                                    # time,drive.torque,... instead

Switches (Integer parameters with named items, such as joint.model) take their item number or name.
A String parameter that names a file (slider.forceTable) takes its path relative to the study file:
the file is read when the study is loaded and travels with every case into the FMU's resources
(under a name that holds a hash of its content), so that workers need no shared filesystem. A case
is identified by a hash of its start values (a file's by its content), the input series, the FMU's
GUID, the stop time and the output interval.
"""
import csv
import hashlib
import itertools
import json
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from fmpy import read_model_description

#: Metrics computed for every case (see runner.metrics).
METRICS = ["peak_joint_force", "peak_crank_pin_force", "peak_main_bearing_force",
           "peak_guide_force", "peak_rod_stress", "contact_onsets", "slider_acceleration_rms",
           "slider_acceleration_peak", "max_deformation_energy", "energy_dissipated",
           "solver_steps", "wall_time"]


class StudyError(ValueError):
    """A study file that cannot run, with the entry it is about."""


@dataclass
class Study:
    """A checked study: the FMU, the experiment and the cases."""
    path: Path
    fmu: Path
    guid: str
    stop_time: float
    output_interval: float
    series: list
    #: Start of the window the metrics cover [s]: a start-up transient before it is left out.
    metrics_start: float
    swept: list                     # names of the parameters that vary (grid, then random)
    cases: list = field(default_factory=list)   # list of dict name -> value
    #: Input series of every case, {"time": [...], input name: [...]}, or None.
    inputs: dict | None = None
    #: Files the cases name (String parameters), by their name in the FMU's resources: the bytes.
    files: dict = field(default_factory=dict)

    def case_id(self, values: dict) -> str:
        experiment = {"values": values, "guid": self.guid, "stop_time": self.stop_time,
                      "output_interval": self.output_interval}
        if self.metrics_start:
            experiment["metrics_start"] = self.metrics_start
        if self.inputs:
            experiment["inputs"] = self.inputs
        key = json.dumps(experiment, sort_keys=True)
        return hashlib.sha256(key.encode()).hexdigest()[:16]


def _variables(md):
    return {v.name: v for v in md.modelVariables}


def switch_items(v) -> dict:
    """The items of a switch, {name: value}: an Integer of a declared type whose description ends
    by naming them ("... (1 = ideal, 2 = dry, 3 = lubricated)"); empty for other variables."""
    if v.type != "Integer" or v.declaredType is None:
        return {}
    return {name: int(value) for value, name in re.findall(r"(\d+) = (\w+)", v.description or "")}


def _check_value(where: str, name: str, value, variables: dict):
    """The value converted to the variable's type, or a StudyError naming the entry."""
    v = variables.get(name)
    if v is None:
        raise StudyError(f"{where}: unknown variable {name!r}")
    if v.causality not in ("parameter", "input") or v.variability == "constant":
        raise StudyError(f"{where}: {name} is an {v.causality}, not a parameter or input")
    items = switch_items(v)
    if items:
        if isinstance(value, str):
            if value not in items:
                raise StudyError(f"{where}: {name} = {value!r} is not one of {sorted(items)}")
            return items[value]
        if not isinstance(value, int) or isinstance(value, bool) or value not in items.values():
            raise StudyError(f"{where}: {name} = {value!r} must be one of {sorted(items)} "
                             f"or 1..{len(items)}")
        return value
    if v.type == "Integer":
        if not isinstance(value, int) or isinstance(value, bool):
            raise StudyError(f"{where}: {name} = {value!r} must be an integer")
    elif v.type == "Real":
        if not isinstance(value, (int, float)) or isinstance(value, bool):
            raise StudyError(f"{where}: {name} = {value!r} must be a number")
        value = float(value)
    elif v.type == "Boolean":
        if not isinstance(value, bool):
            raise StudyError(f"{where}: {name} = {value!r} must be true or false")
        return value
    elif v.type == "String":
        if not isinstance(value, str):
            raise StudyError(f"{where}: {name} = {value!r} must be a string (a file name)")
        return value
    lo = float(v.min) if v.min is not None else -np.inf
    hi = float(v.max) if v.max is not None else np.inf
    if not (np.isfinite(value) and lo <= value <= hi):
        unit = f" {v.unit}" if getattr(v, "unit", None) else ""
        raise StudyError(f"{where}: {name} = {value!r} is outside the allowed range "
                         f"[{v.min}, {v.max}]{unit}")
    return value


def _attach(where: str, name: str, value: str, base: Path, files: dict) -> str:
    """A file a String parameter names (relative to `base`), read into `files` under its name in
    the FMU's resources, `study-<hash of its content>/<its name>`; that name is the case's value.
    An empty value (no file) stays empty."""
    if not value:
        return value
    path = base / value
    try:
        data = path.read_bytes()
    except OSError as e:
        raise StudyError(f"{where}: {name} = {value!r}: cannot read {path} ({e.strerror})") from e
    resource = f"study-{hashlib.sha256(data).hexdigest()[:16]}/{path.name}"
    files[resource] = data
    return resource


def _input_series(spec: dict, base: Path, variables: dict) -> dict:
    """The [inputs] entry checked: a time column, non-decreasing, and columns of inputs of equal
    length, every value in its variable's range; from the entry itself or from its CSV `file`."""
    if "file" in spec:
        path = base / spec["file"]
        try:
            with open(path, newline="") as f:
                rows = [r for r in csv.reader(f) if r and not r[0].lstrip().startswith("#")]
        except OSError as e:
            raise StudyError(f"inputs.file: cannot read {path} ({e.strerror})") from e
        if len(rows) < 3:
            raise StudyError(f"inputs.file: {path} needs a header row and at least two rows")
        header = [h.strip() for h in rows[0]]
        try:
            values = [[float(x) for x in r] for r in rows[1:]]
        except ValueError as e:
            raise StudyError(f"inputs.file: {path}: {e}") from e
        if any(len(r) != len(header) for r in values):
            raise StudyError(f"inputs.file: {path}: every row needs {len(header)} values")
        columns = {h: [r[k] for r in values] for k, h in enumerate(header)}
    else:
        columns = dict(spec)
    if "time" not in columns:
        raise StudyError("inputs: needs a time column")
    lengths = {len(c) if isinstance(c, list) else 0 for c in columns.values()}
    if len(columns) < 2 or len(lengths) != 1 or min(lengths) < 2:
        raise StudyError("inputs: a time column and at least one input, equal-length lists of at "
                         "least two values")
    time = [float(t) for t in columns.pop("time")]
    if not all(np.isfinite(time)) or any(b < a for a, b in zip(time, time[1:])):
        raise StudyError("inputs: time must be finite and non-decreasing")
    series = {"time": time}
    for name, column in columns.items():
        v = variables.get(name)
        if v is None or v.causality != "input":
            raise StudyError(f"inputs: {name!r} is not an input of the FMU")
        series[name] = [_check_value(f"inputs.{name!r}[{k}]", name, x, variables)
                        for k, x in enumerate(column)]
    return series


def load(path, fmu=None) -> Study:
    """Reads and checks a study file; every entry is checked before any case runs."""
    path = Path(path)
    try:
        spec = tomllib.loads(path.read_text())
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise StudyError(f"{path}: {e}") from e
    known = {"fmu", "stop_time", "output_interval", "metrics_start", "series", "fixed", "grid",
             "cases", "random", "inputs"}
    for key in spec:
        if key not in known:
            raise StudyError(f"{path}: unknown entry {key!r} (known: {sorted(known)})")
    fmu_path = Path(fmu) if fmu else path.parent / spec.get("fmu", "")
    if not fmu_path.is_file():
        raise StudyError(f"{path}: FMU {fmu_path} not found")
    md = read_model_description(str(fmu_path))
    variables = _variables(md)
    ex = md.defaultExperiment
    stop_time = float(spec.get("stop_time", ex.stopTime if ex else 1.0))
    interval = float(spec.get("output_interval", ex.stepSize if ex else stop_time / 500))
    if not (stop_time > 0 and 0 < interval <= stop_time):
        raise StudyError(f"{path}: need 0 < output_interval <= stop_time, got {interval}, {stop_time}")
    metrics_start = float(spec.get("metrics_start", 0.0))
    if not 0 <= metrics_start < stop_time:
        raise StudyError(f"{path}: need 0 <= metrics_start < stop_time, got {metrics_start}")
    series = list(spec.get("series", []))
    for name in series:
        if name not in variables:
            raise StudyError(f"{path}: series: unknown variable {name!r}")

    fixed = {n: _check_value(f"fixed.{n!r}", n, x, variables)
             for n, x in spec.get("fixed", {}).items()}
    # Each grid axis is a list of cases (dicts): one parameter's values, or several parameters'
    # equal-length lists that vary together (a table: [grid.speed] "a" = [...], "b" = [...]).
    axes, swept = [], []
    for n, values in spec.get("grid", {}).items():
        linked = values if isinstance(values, dict) else {n: values}
        lengths = {len(v) if isinstance(v, list) else 0 for v in linked.values()}
        if 0 in lengths or len(lengths) != 1:
            raise StudyError(f"grid.{n!r}: must be a non-empty list, or a table of "
                             f"equal-length non-empty lists")
        checked = {m: [_check_value(f"grid.{n!r}.{m!r}[{k}]" if m != n else f"grid.{n!r}[{k}]",
                                    m, x, variables) for k, x in enumerate(v)]
                   for m, v in linked.items()}
        axes.append([dict(zip(checked, row)) for row in zip(*checked.values())])
        swept.append(next(iter(checked)))
    explicit = [{n: _check_value(f"cases[{k}].{n!r}", n, x, variables)
                 for n, x in case.items()} for k, case in enumerate(spec.get("cases", [{}]))]
    random_cases = [{}]
    if "random" in spec:
        r = spec["random"]
        samples, seed = int(r.get("samples", 10)), int(r.get("seed", 0))
        rng = np.random.default_rng(seed)
        bounds = {}
        for n, (lo, hi) in r.get("uniform", {}).items():
            _check_value(f"random.uniform.{n!r}[0]", n, lo, variables)
            _check_value(f"random.uniform.{n!r}[1]", n, hi, variables)
            bounds[n] = (float(lo), float(hi))
        random_cases = []
        for _ in range(samples):
            case = {}
            for n, (lo, hi) in bounds.items():
                x = rng.uniform(lo, hi)
                case[n] = int(round(x)) if variables[n].type == "Integer" else float(x)
            random_cases.append(case)
        swept += list(bounds)

    cases = []
    for combination in itertools.product(*axes):
        for extra in explicit:
            for sample in random_cases:
                case = dict(fixed)
                for axis_values in combination:
                    case.update(axis_values)
                case.update(extra)
                case.update(sample)
                cases.append(case)
    files = {}
    for case in cases:
        for n, x in case.items():
            if variables[n].type == "String":
                case[n] = _attach(n, n, x, path.parent, files)
    inputs = _input_series(spec["inputs"], path.parent, variables) if "inputs" in spec else None
    return Study(path=path, fmu=fmu_path, guid=md.guid, stop_time=stop_time,
                 output_interval=interval, series=series, metrics_start=metrics_start,
                 swept=swept, cases=cases, inputs=inputs, files=files)
