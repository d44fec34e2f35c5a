"""Whole-FMU benchmark through fmpy: simulate_fmu of the DefaultExperiment (two revolutions of
benchmark B at 5000 rpm, 1e-4 s communication step) for the rigid, reduced and full rods with the dry
and lubricated joints, all in one run. Prints a Markdown table of wall time (best of five rounds, each round
running every case once), the ratio to the rigid rod with the same joint, and the integrator's steps and
right-hand-side evaluations.

usage: python -m fsc.benchmark FMU [--quick | --real-time] [--baseline=OTHER_FMU] [NAME=VALUE ...]
(start values applied to every case)

--real-time runs only the cases of the real-time figures: the 4-mode rod with the dry joint undamped (the
DefaultExperiment), with rod.dampingRatio 1 % and 2 %, and with the lubricated joint.

With --baseline every case also runs with OTHER_FMU (another build) in the same rounds, right after the
FMU under test, and the table adds its best wall time and the ratio of the two (a case whose parameters
OTHER_FMU does not have runs only with the FMU under test).
"""
import sys
import time

from fmpy import read_model_description, simulate_fmu

RIGID, ANCF, CRAIG_BAMPTON = 1, 2, 3
DRY, LUBRICATED = 2, 3
IMPLICIT, EXPLICIT = 1, 2
SAMPLED = 2

# (label, joint, start values); the first case of each joint is its rigid reference. The sampled rods
# come last, so that --quick keeps its cases.
CASES = [
    ("rigid", DRY, {"rod.formulation": RIGID}),
    ("Craig-Bampton 4 modes, 8 elements", DRY, {}),
    ("Craig-Bampton 8 modes, 8 elements", DRY, {"rod.nModes": 8}),
    ("full ANCF, 8 elements", DRY, {"rod.formulation": ANCF}),
    ("Craig-Bampton 4 modes, 16 elements", DRY, {"rod.nElements": 16}),
    ("full ANCF, 16 elements", DRY, {"rod.formulation": ANCF, "rod.nElements": 16}),
    ("Craig-Bampton 4 modes, 32 elements", DRY, {"rod.nElements": 32}),
    ("full ANCF, 32 elements", DRY, {"rod.formulation": ANCF, "rod.nElements": 32}),
    ("rigid", LUBRICATED, {"rod.formulation": RIGID}),
    ("Craig-Bampton 4 modes, 8 elements", LUBRICATED, {}),
    ("full ANCF, 8 elements", LUBRICATED, {"rod.formulation": ANCF}),
    ("Craig-Bampton 4 modes, 8 elements, short film", LUBRICATED, {"joint.filmModel": 1}),
    ("Craig-Bampton 4 modes, 8 elements, sampled", DRY, {"rod.quadrature": SAMPLED}),
    ("Craig-Bampton 4 modes, 16 elements, sampled", DRY, {"rod.quadrature": SAMPLED, "rod.nElements": 16}),
    ("Craig-Bampton 4 modes, 32 elements, sampled", DRY, {"rod.quadrature": SAMPLED, "rod.nElements": 32}),
    ("Craig-Bampton 4 modes, 8 elements, rod.dampingRatio 1 %", DRY, {"rod.dampingRatio": 0.01}),
    ("Craig-Bampton 4 modes, 8 elements, rod.dampingRatio 2 %", DRY, {"rod.dampingRatio": 0.02}),
]
# The cases of --real-time, by index in CASES.
REAL_TIME = [1, 15, 16, 9]
JOINT_NAMES = {DRY: "dry", LUBRICATED: "lubricated"}
ROUNDS = 5


def run_once(fmu, start_values):
    t0 = time.perf_counter()
    result = simulate_fmu(fmu, start_values=start_values,
                          output=["solver.steps", "solver.evaluations"])
    wall = time.perf_counter() - t0
    return wall, int(result["solver.steps"][-1]), int(result["solver.evaluations"][-1])


def main(fmu: str, quick: bool, common: dict, baseline: str | None = None,
         real_time: bool = False) -> None:
    md = read_model_description(fmu)
    stop = float(md.defaultExperiment.stopTime)
    if real_time:
        cases = [CASES[i] for i in REAL_TIME]
    else:
        cases = CASES[:4] + CASES[8:10] + CASES[11:12] if quick else CASES
    builds = [fmu] if baseline is None else [fmu, baseline]
    # Round-robin: every round runs every case once (with each build), so a slow spell of the machine
    # hits all cases alike instead of one; each case keeps its best round.
    best = [[(float("inf"), 0, 0)] * len(cases) for _ in builds]
    # A case whose parameters a build does not have is not run with it.
    known = [{v.name for v in read_model_description(path).modelVariables} for path in builds]
    for _ in range(ROUNDS):
        for i, (_, joint, values) in enumerate(cases):
            for b, path in enumerate(builds):
                if set(values) <= known[b]:
                    best[b][i] = min(best[b][i], run_once(path, {"joint.model": joint, **common, **values}))
    extra = " baseline wall time [s] | ratio to baseline |" if baseline else ""
    reference = "ratio to the undamped rod" if real_time else "ratio to rigid"
    print(f"| rod model | joint | wall time [s] | {reference} | real-time factor | steps | evaluations |{extra}")
    print("|---|---|---|---|---|---|---|" + ("---|---|" if baseline else ""))
    rigid = {} if not real_time else {DRY: best[0][0][0], LUBRICATED: best[0][0][0]}
    for i, ((label, joint, _), (wall, steps, evaluations)) in enumerate(zip(cases, best[0])):
        rigid.setdefault(joint, wall)
        row = (f"| {label} | {JOINT_NAMES[joint]} | {wall:.3f} | {wall / rigid[joint]:.2f} | "
               f"{stop / wall:.3f} | {steps} | {evaluations} |")
        if baseline and best[1][i][1]:
            row += f" {best[1][i][0]:.3f} | {wall / best[1][i][0]:.2f} |"
        elif baseline:
            row += " – | – |"
        print(row, flush=True)


if __name__ == "__main__":
    flags = sys.argv[2:]
    settings = dict(a.split("=", 1) for a in flags if "=" in a and not a.startswith("--"))
    other = next((a.split("=", 1)[1] for a in flags if a.startswith("--baseline=")), None)
    main(sys.argv[1], "--quick" in flags, {k: float(v) for k, v in settings.items()}, other,
         "--real-time" in flags)
