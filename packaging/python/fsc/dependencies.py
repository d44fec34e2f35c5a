"""Dependencies of an FMU's initial unknowns, measured: in initialization mode, each known (input or
parameter) is perturbed in turn and the outputs and calculated parameters that change are noted.

    python -m fsc.dependencies target/fmu/DcMotor.fmu

prints, for each initial unknown, the knowns it reacted to at the FMU's start values. The tests
run the same measurement over many configurations and compare it with the `dependencies` that
modelDescription.xml declares under ModelStructure/InitialUnknowns.
"""
import sys
import tempfile
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from fmpy import extract, read_model_description

from .session import GETTERS, SETTERS, instantiate

# A change smaller than this (relative) is round-off, not a dependency.
ROUND_OFF = 1e-9

# The file a String known (a load table) is pointed at: a load varying over the crank angle.
TABLE = Path(tempfile.mkdtemp(prefix="fsc-dependencies-")) / "table.csv"
TABLE.write_text("0,-100\n180,-300\n")


def perturbations(variable, value):
    """The values a known is moved to, each as a list of alternatives of which the first the FMU
    accepts counts: every other item of a switch; one step of an integer, or else the far end of
    its range (a parameter that takes few values of its range, such as a table's period); 1 % of
    a real (into its range), or a millionth of its largest value if it is zero; a String (a file
    name) names a load table, or none if it named one."""
    if variable.type == "String":
        return [["" if value else str(TABLE)]]
    t = variable.declaredType
    if t is not None and t.max is not None:
        return [[k] for k in range(int(t.min), int(t.max) + 1) if k != value]
    if variable.type == "Integer":
        high = int(variable.max) if variable.max is not None else value + 1
        low = int(variable.min) if variable.min is not None else value - 1
        step = value + 1 if value < high else value - 1
        far = high if value - low < high - value else low
        return [[step] if far in (step, value) else [step, far]]
    if variable.type == "Boolean":
        return [[1 - value]]
    high = float(variable.max) if variable.max is not None else 1.0
    y = 1.01 * value if value != 0 else 1e-6 * high
    if y > high:
        y = 0.99 * value
    if variable.min is not None and y < float(variable.min):
        y = 0.5 * (value + float(variable.min))
    return [[y]]


def changed(a, b):
    return abs(a - b) > ROUND_OFF * (abs(a) + abs(b))


def measure(fmu, configurations, workers=2):
    """(unknown, known) name pairs where perturbing the known in initialization mode changes the
    unknown, over `configurations` (dicts of start values; one that the FMU rejects is skipped),
    shared among `workers` processes. Returns the pairs and the number of configurations
    measured."""
    shares = [configurations[i::workers] for i in range(workers)]
    with ProcessPoolExecutor(max_workers=workers) as pool:
        results = list(pool.map(measure_in_one_process, [fmu] * workers, shares))
    return set().union(*(pairs for pairs, _ in results)), sum(n for _, n in results)


def measure_in_one_process(fmu, configurations):
    """`measure` over `configurations`, in this process."""
    md = read_model_description(fmu)
    unzipdir = extract(fmu)
    by_name = {v.name: v for v in md.modelVariables}
    knowns = [v for v in md.modelVariables if v.causality in ("input", "parameter")]
    unknowns = [u.variable for u in md.initialUnknowns]

    def instance(configuration):
        # The measurement tries values that some configurations reject: their errors are expected
        # and stay in the package's logger.
        s = instantiate(unzipdir, md, "dependencies")
        s.setupExperiment(startTime=0.0)
        for name, value in configuration.items():
            v = by_name[name]
            getattr(s, SETTERS[v.type])([v.valueReference], [value])
        s.enterInitializationMode()
        return s

    def read(s):
        return {u.name: getattr(s, GETTERS[u.type])([u.valueReference])[0] for u in unknowns}

    pairs, measured = set(), 0
    for configuration in configurations:
        s = instance(configuration)
        try:
            before = read(s)
        except Exception:  # a configuration the FMU rejects (e.g. an explicit run's tolerance)
            s.freeInstance()
            continue
        measured += 1
        for k in knowns:
            x = getattr(s, GETTERS[k.type])([k.valueReference])[0]
            if isinstance(x, bytes):  # fmpy reads a String as bytes and sets it from a str
                x = x.decode()
            for alternatives in perturbations(k, x):
                for y in alternatives:
                    try:
                        getattr(s, SETTERS[k.type])([k.valueReference], [y])
                        after = read(s)
                    except Exception:  # a value this configuration rejects
                        after = None
                    # Start afresh rather than set the value back: a parameter left at its start
                    # value is not the same as one set to it (crank.initialSpeed).
                    s.freeInstance()
                    s = instance(configuration)
                    if after is not None:
                        pairs |= {(u, k.name) for u in after if changed(after[u], before[u])}
                        break
        s.freeInstance()
    return pairs, measured


def declared(fmu):
    """(unknown, known) name pairs that modelDescription.xml declares for the initial unknowns."""
    md = read_model_description(fmu)
    return {(u.variable.name, d.name) for u in md.initialUnknowns for d in (u.dependencies or [])}


if __name__ == "__main__":
    pairs, _ = measure(sys.argv[1], [{}])
    for unknown in sorted({u for u, _ in pairs}):
        print(unknown, ":", " ".join(sorted(k for u, k in pairs if u == unknown)))
