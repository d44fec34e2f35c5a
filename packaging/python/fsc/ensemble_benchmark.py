"""Compares the speed of two builds of the FMU over an ensemble of runs.

A dry clearance joint makes benchmark B chaotic: a change that alters the last bit of any number
changes the impact sequence, and with it the number of steps, so one run cannot rank two builds.
This runs both FMUs alternately over 20 clearances (0.5 mm × (1 + 0.02 k), k = 0..19), ROUNDS
times, and prints each FMU's total wall time and evaluations and the ratio of wall time per
evaluation (B / A).

usage: python -m fsc.ensemble_benchmark A.fmu B.fmu [NAME=VALUE ...]   (start values added to every case)
"""
import sys
import time

from fmpy import extract, read_model_description, simulate_fmu

ROUNDS = 3


def main():
    fmus = sys.argv[1:3]
    extra = {name: int(value) if value.lstrip("-").isdigit() else float(value)
             for name, value in (a.split("=", 1) for a in sys.argv[3:])}
    loaded = [(extract(f), read_model_description(f)) for f in fmus]
    cases = [{"joint.clearance": 5e-4 * (1 + 0.02 * k), **extra} for k in range(20)]
    totals = [[0.0, 0, 0] for _ in fmus]
    for _ in range(ROUNDS):
        for case in cases:
            for total, (directory, md) in zip(totals, loaded):
                t0 = time.perf_counter()
                result = simulate_fmu(directory, model_description=md, start_values=case,
                                      output=["solver.evaluations", "solver.steps"])
                total[0] += time.perf_counter() - t0
                total[1] += int(result["solver.evaluations"][-1])
                total[2] += int(result["solver.steps"][-1])
    for name, (wall, evaluations, steps) in zip("AB", totals):
        print(f"{name}: wall {wall:.3f} s, evaluations {evaluations}, steps {steps}")
    (wa, ea, _), (wb, eb, _) = totals
    print(f"wall time B / A: {wb / wa:.4f}; per evaluation: {(wb / eb) / (wa / ea):.4f}")


if __name__ == "__main__":
    main()
