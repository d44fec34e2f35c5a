"""Random parameter sets through the FMU: does every set the modelDescription accepts
give a physical answer in bounded time, or a clear error?

    python -m fsc.parameter_space [--near 200] [--ranges 200] [--seed 2026]
                                               [--jobs 2] [--fmu PATH] [--json FILE]
    python -m fsc.parameter_space --listed      # the documented edge cases

Each case runs through fmpy in its own process (a crash of the FMU would be seen as a dead
process, not end the study), with logging on, a 0.1 ms communication step and 4 ms of simulated
time. Two samples:

- near: every positive Real parameter is its default times a log-uniform factor in [1/4, 4];
  rod.nElements and rod.nModes likewise (rounded); the rod formulation, joint model, contact law
  and drive mode are drawn uniformly; drive.speed follows crank.initialSpeed.
- ranges: the defaults with three variables (parameters or inputs) drawn across their declared
  ranges: log-uniform where the range spans decades, with a random sign for ranges around zero;
  switches and booleans uniformly.

Each case ends as `rejected` (an error before the first step: the message must name a variable),
`stopped` (fmi2Discard/fmi2Error during the run, with a message) or `ran`, with or without
validity warnings. A case violates the FMU's promises if the process dies, if it does not end
within --timeout seconds, if an output is not finite, if the energy balance of the outputs
(docs/guide/variables.md, "Outputs") drifts by more than 10 x solver.integrationTolerance (the tolerance
the model is integrated at) of the largest energy term,
or if an output leaves a validity-monitor bound without a warning having been logged. The exit
code is the number of violations (0: all promises held).
"""
import argparse
import json
import math
import multiprocessing
import os
import random
import sys
import tempfile
import time
from pathlib import Path

from fmpy import extract, read_model_description

from . import session

#: The packaging step's FMU, from a clone's root (`--fmu PATH` names another).
FMU = Path("target") / "fmu" / "FlexibleSliderCrank.fmu"
STOP_TIME = 4e-3
STEP = 1e-4

#: The energy account of docs/guide/variables.md, "Outputs": sign of each term.
BALANCE = {"energy.kinetic": 1, "rod.deformationEnergy": 1, "energy.contact": 1,
           "energy.gravity": 1, "energy.dissipated": 1, "energy.materialDamping": 1,
           "energy.driveWork": -1, "energy.sliderWork": -1}
#: Validity-monitor bounds (src/simulation/validity.rs), with the word their warning contains.
#: The clearance joints of the crank besides the rod-slider joint.
CRANK_JOINTS = ["crankPin", "mainBearing"]
MONITORS = {"penetration": 0.01, "deflection": 0.05, "crank speed": 1.01e4, "slider position": 0.01}

#: The documented edge cases, each with the variables it changes (and a longer run where whole
#: revolutions are timed).
LISTED = [
    ("joint.friction = 1", {"joint.friction": 1.0}, 24e-3),
    ("joint.friction = 0.3", {"joint.friction": 0.3}, 24e-3),
    ("joint.friction = 0.1", {"joint.friction": 0.1}, 24e-3),
    ("rod.stiffnessDamping = 1 s", {"rod.stiffnessDamping": 1.0}, 4e-3),
    ("lubricated, joint.clearance = 1e-5 m", {"joint.model": 3, "joint.clearance": 1e-5}, 4e-3),
    ("rod.nElements = 64, rod.nModes = 126", {"rod.nElements": 64, "rod.nModes": 126}, 24e-3),
    ("drive.speed = 1e4 rad/s", {"crank.initialSpeed": 1e4, "drive.speed": 1e4}, 4e-3),
    ("drive.torque = 1e6 N m", {"drive.mode": 2, "drive.torque": 1e6}, 4e-3),
    ("slider.force = 1e7 N", {"slider.force": 1e7}, 4e-3),
    ("joint.journalRadius = 1e-5 m", {"joint.journalRadius": 1e-5}, 4e-3),
    ("dry, joint.clearance = 0", {"joint.clearance": 0.0}, 4e-3),
    ("lubricated, joint.clearance = 0", {"joint.model": 3, "joint.clearance": 0.0}, 4e-3),
    ("lubricated, joint.clearance = 1e-9 m", {"joint.model": 3, "joint.clearance": 1e-9}, 4e-3),
]


def variables(md):
    """Parameters and inputs of the model description by name."""
    return {v.name: v for v in md.modelVariables if v.causality in ("parameter", "input")}


def _number(v, text):
    return None if text in (None, "") else (float(text) if v.type == "Real" else int(text))


def near_default(rng, md):
    """Defaults times log-uniform factors in [1/4, 4] (see the module docs)."""
    values = {}
    for name, v in variables(md).items():
        if v.declaredType is not None and name in ("rod.formulation", "joint.model",
                                                    "joint.contactLaw", "drive.mode"):
            values[name] = rng.randint(1, int(v.declaredType.max))
        elif v.type == "Real" and v.causality == "parameter" and float(v.start) > 0:
            lo, hi = _number(v, v.min), _number(v, v.max)
            value = float(v.start) * 4 ** rng.uniform(-1, 1)
            values[name] = min(max(value, lo if lo is not None else value),
                               hi if hi is not None else value)
        elif name in ("rod.nElements", "rod.nModes"):
            values[name] = max(1, round(int(v.start) * 4 ** rng.uniform(-1, 1)))
    values["drive.speed"] = values["crank.initialSpeed"]
    return values


def across_ranges(rng, md, count=3):
    """The defaults with `count` variables drawn across their declared ranges."""
    values = {}
    for name in rng.sample(sorted(variables(md)), count):
        v = variables(md)[name]
        if v.type == "Integer" and v.declaredType is not None:  # a switch
            values[name] = rng.randint(1, int(v.declaredType.max))
        elif v.type == "Boolean":
            values[name] = rng.random() < 0.5
        else:
            lo, hi = _number(v, v.min), _number(v, v.max)
            if lo > 0 and hi / lo >= 100:
                x = math.exp(rng.uniform(math.log(lo), math.log(hi)))
            elif lo < 0 < hi and hi / 1e6 > 0:
                # A random sign and a magnitude log-uniform over six decades below the bound.
                x = math.copysign(math.exp(rng.uniform(math.log(hi * 1e-6), math.log(hi))),
                                  rng.random() - 0.5)
                x = min(max(x, lo), hi)
            else:
                x = rng.uniform(lo, hi)
            values[name] = round(x) if v.type == "Integer" else x
    return values


def run_case(unzipdir, md, values, stop_time, queue):
    """Runs one case in this (child) process and puts its record on `queue`."""
    messages = session.messages("case")
    vars_ = {v.name: v for v in md.modelVariables}
    outputs = [v for v in md.modelVariables if v.causality == "output" and v.type == "Real"]
    reals = ["joint.journalRadius", "rod.length", "crank.length", "joint.clearance",
             "solver.integrationTolerance"]
    reals += [f"{joint}.{name}" for joint in CRANK_JOINTS for name in ("journalRadius", "clearance")]
    record = {"values": values, "outcome": "ran", "message": "", "warnings": [],
              "violations": [], "max_step_wall": 0.0, "time_reached": 0.0, "wall": 0.0}
    start = time.perf_counter()
    stage = "setup"
    fmu = None
    try:
        fmu = session.instantiate(unzipdir, md, "case", logging_on=True)
        fmu.setupExperiment(startTime=0.0, stopTime=stop_time)
        fmu.enterInitializationMode()
        for name, value in values.items():
            v = vars_[name]
            if v.type == "Real":
                fmu.setReal([v.valueReference], [value])
            elif v.type == "Boolean":
                fmu.setBoolean([v.valueReference], [value])
            else:
                fmu.setInteger([v.valueReference], [int(value)])
        fmu.exitInitializationMode()
        p = dict(zip(reals, fmu.getReal([vars_[n].valueReference for n in reals])))
        formulation = fmu.getInteger([vars_["rod.formulation"].valueReference])[0]
        for joint in CRANK_JOINTS:
            p[f"{joint}.model"] = fmu.getInteger([vars_[f"{joint}.model"].valueReference])[0]
        stage = "run"
        rows = []
        t = 0.0
        while t < stop_time - 1e-12:
            step_start = time.perf_counter()
            fmu.doStep(currentCommunicationPoint=t, communicationStepSize=STEP)
            record["max_step_wall"] = max(record["max_step_wall"],
                                          time.perf_counter() - step_start)
            t += STEP
            record["time_reached"] = t
            row = dict(zip([v.name for v in outputs],
                           fmu.getReal([v.valueReference for v in outputs])))
            rows.append(row)
            warned = " ".join(m for s, _, m in messages if s == 1)
            check_row(row, p, formulation, warned, t, record["violations"])
        check_balance(rows, p["solver.integrationTolerance"], record["violations"])
    except Exception as e:  # noqa: BLE001 - an FMU error is an outcome, recorded with its message
        record["outcome"] = "rejected" if stage == "setup" else "stopped"
        errors = [m for s, _, m in messages if s >= 2]
        record["message"] = " | ".join(errors) or str(e)
        if not errors:
            record["violations"].append(f"{stage}: {e} without a logged message")
    record["wall"] = time.perf_counter() - start
    record["warnings"] = [m for s, _, m in messages if s == 1]
    if fmu is not None:
        try:
            fmu.terminate()
        except Exception:  # noqa: BLE001 - a failed instance may refuse fmi2Terminate
            pass
        fmu.freeInstance()
    queue.put(record)


def check_row(row, p, formulation, warned, t, violations):
    """Non-finite outputs, and validity-monitor exits without a warning, at one point."""
    bad = [k for k, x in row.items() if not math.isfinite(x)]
    if bad:
        violations.append(f"t = {t:.4g} s: non-finite {bad}")
        return
    # A worn crank pin or main bearing (model 2 or 3) lengthens the stroke by its clearance too.
    worn = [joint for joint in CRANK_JOINTS if p.get(f"{joint}.model", 1) != 1]
    r_c, l = p["crank.length"], p["rod.length"]
    c = p["joint.clearance"] + sum(p[f"{joint}.clearance"] for joint in worn)
    x = row["slider.position"]
    penetration = max([row["joint.penetration"] / p["joint.journalRadius"]]
                      + [row[f"{joint}.penetration"] / p[f"{joint}.journalRadius"] for joint in worn])
    exits = {
        "penetration": penetration > MONITORS["penetration"],
        "deflection": formulation != 1
        and abs(row["rod.midspanDeflection"]) > MONITORS["deflection"] * l,
        "crank speed": abs(row["crank.speed"]) > MONITORS["crank speed"],
        "slider position": max((l - r_c - c) - x, x - (l + r_c + c))
        > MONITORS["slider position"] * r_c,
    }
    for cause, left in exits.items():
        if left and cause not in warned:
            violations.append(f"t = {t:.4g} s: {cause} out of bounds without a warning")


def balance_residual(rows):
    """Largest drift of the outputs' energy balance, relative to the largest energy term."""
    totals = [sum(sign * row[k] for k, sign in BALANCE.items()) for row in rows]
    scale = max(max(abs(row[k]) for k in BALANCE) for row in rows)
    return max(abs(x - totals[0]) for x in totals) / scale if scale > 0 else 0.0


def check_balance(rows, rtol, violations):
    if rows:
        residual = balance_residual(rows)
        if residual > 10 * rtol:
            violations.append(f"energy balance residual {residual:.2e} > 10 x rtol {rtol:.1e}")


def run_all(cases, fmu_path=FMU, jobs=2, timeout=600.0, progress=True):
    """Runs (label, values, stop_time) cases, `jobs` processes at a time; returns records."""
    unzipdir = extract(str(fmu_path), unzipdir=tempfile.mkdtemp(prefix="fsc-space-"))
    md = read_model_description(unzipdir)
    context = multiprocessing.get_context("fork")
    records, running, pending = [], [], list(enumerate(cases))
    while pending or running:
        while pending and len(running) < jobs:
            index, (label, values, stop_time) = pending.pop(0)
            queue = context.Queue()
            process = context.Process(target=run_case,
                                      args=(unzipdir, md, values, stop_time, queue))
            process.start()
            running.append((index, label, process, queue, time.perf_counter()))
        time.sleep(0.01)
        for item in list(running):
            index, label, process, queue, started = item
            record = None
            if not queue.empty():
                record = queue.get()
                process.join()
            elif not process.is_alive():
                record = {"values": cases[index][1], "outcome": "crashed", "message": "",
                          "warnings": [], "violations": [f"process died ({process.exitcode})"],
                          "max_step_wall": 0.0, "time_reached": 0.0, "wall": 0.0}
            elif time.perf_counter() - started > timeout:
                process.kill()
                process.join()
                record = {"values": cases[index][1], "outcome": "timeout", "message": "",
                          "warnings": [], "violations": [f"no answer within {timeout} s"],
                          "max_step_wall": timeout, "time_reached": 0.0, "wall": timeout}
            if record is not None:
                running.remove(item)
                record.update(index=index, label=label)
                records.append(record)
                if progress:
                    print(f"[{len(records)}/{len(cases)}] {label}: {record['outcome']}"
                          f"{' +warnings' if record['warnings'] else ''}, "
                          f"{record['wall']:.2f} s (largest doStep {record['max_step_wall']:.2f} s)"
                          + (f" VIOLATION {record['violations']}" if record["violations"] else ""),
                          flush=True)
    return sorted(records, key=lambda r: r["index"])


def sample(near, ranges, seed, md):
    rng = random.Random(seed)
    cases = [(f"near {i}", near_default(rng, md), STOP_TIME) for i in range(near)]
    cases += [(f"ranges {i}", across_ranges(rng, md), STOP_TIME) for i in range(ranges)]
    return cases


def summary(records, title, names):
    """A text summary: outcome split, violations, timing; `names`: the model's variable names."""
    def split(rs):
        counts = {"rejected": 0, "stopped": 0, "ran with warnings": 0, "ran clean": 0,
                  "crashed": 0, "timeout": 0}
        for r in rs:
            key = r["outcome"]
            if key == "ran":
                key = "ran with warnings" if r["warnings"] else "ran clean"
            counts[key] += 1
        return counts
    lines = [f"## {title}"]
    for group in sorted({r["label"].split()[0] for r in records}):
        rs = [r for r in records if r["label"].split()[0] == group]
        walls = sorted(r["max_step_wall"] for r in rs)
        lines.append(f"{group}: {len(rs)} cases, {split(rs)}, violations "
                     f"{sum(bool(r['violations']) for r in rs)}, largest doStep wall "
                     f"{walls[-1]:.2f} s (median {walls[len(walls) // 2]:.3f} s), total wall "
                     f"{sum(r['wall'] for r in rs):.0f} s")
    errors = [r for r in records if r["outcome"] in ("rejected", "stopped")]
    named = sum(any(name in r["message"] for name in names) for r in errors)
    lines.append(f"errors whose message names a model variable: {named} of {len(errors)}")
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--near", type=int, default=200)
    parser.add_argument("--ranges", type=int, default=200)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--timeout", type=float, default=600.0)
    parser.add_argument("--fmu", default=str(FMU))
    parser.add_argument("--json", help="write every case's record to this file")
    parser.add_argument("--listed", action="store_true", help="run the documented edge cases")
    args = parser.parse_args(argv)
    md = read_model_description(args.fmu)
    if args.listed:
        cases = [(f"listed: {label}", values, stop) for label, values, stop in LISTED]
        records = run_all(cases, args.fmu, jobs=1, timeout=args.timeout)
        for r in records:
            print(f"- {r['label'][8:]}: {r['outcome']} at t = {r['time_reached']:.4g} s, largest "
                  f"doStep {r['max_step_wall']:.3f} s; {r['message'] or '; '.join(r['warnings'])}")
    else:
        records = run_all(sample(args.near, args.ranges, args.seed, md), args.fmu,
                          jobs=args.jobs, timeout=args.timeout)
    print(summary(records, f"{len(records)} cases, seed {args.seed}",
                  [v.name for v in md.modelVariables]))
    if args.json:
        Path(args.json).write_text(json.dumps(records, indent=1, default=str))
    violations = [r for r in records if r["violations"]]
    for r in violations:
        print(f"VIOLATION {r['label']}: {r['violations']} values {r['values']}")
    return len(violations)


if __name__ == "__main__":
    sys.exit(min(main(), 255))
