"""Whole-FMU benchmark through fmpy: simulate_fmu of the DefaultExperiment (two revolutions,
1e-4 s communication step) for each rod model and joint model. Prints a Markdown table of wall
time, real-time factor and speed-up of the reduced over the full rod (all measured in one run).

usage: benchmark.py FMU
"""
import sys
import time

from fmpy import read_model_description, simulate_fmu

CASES = [("rigid", 1, 0), ("full ANCF, 8 elements", 2, 0), ("Craig-Bampton m=2", 3, 2),
         ("Craig-Bampton m=4", 3, 4), ("Craig-Bampton m=8", 3, 8)]
JOINTS = [("dry", 2), ("lubricated", 3)]


def main(fmu: str) -> None:
    md = read_model_description(fmu)
    stop = float(md.defaultExperiment.stopTime)
    wall = {}
    for joint, joint_value in JOINTS:
        for name, formulation, modes in CASES:
            start_values = {"rod.formulation": formulation, "joint.model": joint_value,
                            "rod.nModes": modes}
            best = float("inf")
            for _ in range(3):
                t0 = time.perf_counter()
                simulate_fmu(fmu, start_values=start_values, output=["slider.acceleration"])
                best = min(best, time.perf_counter() - t0)
            wall[(joint, name)] = best
    print("| rod model | joint | wall time [s] | real-time factor | speed-up vs full |")
    print("|---|---|---|---|---|")
    for joint, _ in JOINTS:
        full = wall[(joint, "full ANCF, 8 elements")]
        for name, _, _ in CASES:
            w = wall[(joint, name)]
            print(f"| {name} | {joint} | {w:.3f} | {stop / w:.4f} | {full / w:.2f} |")


if __name__ == "__main__":
    main(sys.argv[1])
