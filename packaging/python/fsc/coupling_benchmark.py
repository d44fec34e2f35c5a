"""Cost of coupling: the FMU driven by a master that sets an input at every communication point,
against the same run with the input left alone.

The torque-driven crank (benchmark B, 24 ms) is run twice per communication step: "uncoupled",
drive.torque held at 0 for the whole run, and "coupled", drive.torque set at every communication
point to +-1e-9 N m alternately (a change the motion cannot see, which restarts the internal step
sequence as a coupled motor model does). Prints the integrator's right-hand-side evaluations of
both, their ratio, and those of the speed-driven crank (the DefaultExperiment's drive) at the same
communication step, against which the coupled run is also judged.

usage: python -m fsc.coupling_benchmark FMU
"""
import sys

from .session import Session

STOP = 0.024


def evaluations(fmu, step, coupled, mode=2):
    s = Session(fmu, "coupling", stop_time=STOP)
    s.set({"drive.mode": mode})
    s.initialize()
    n = round(STOP / step)
    for k in range(n):
        if coupled:
            s.set({"drive.torque": 1e-9 if k % 2 else -1e-9})
        s.fmu.doStep(k * step, step)
    count = s.get("solver.evaluations")
    s.free()
    return count


def main():
    fmu = sys.argv[1]
    print("| communication step [s] | uncoupled evaluations | coupled evaluations | coupled / uncoupled "
          "| speed-driven evaluations | coupled / speed-driven |")
    print("|---|---|---|---|---|---|")
    for step in (1e-4, 5e-5, 1e-5):
        free, coupled = evaluations(fmu, step, False), evaluations(fmu, step, True)
        speed = evaluations(fmu, step, False, mode=1)
        print(f"| {step:g} | {free} | {coupled} | {coupled / free:.2f} | {speed} | "
              f"{coupled / speed:.2f} |")


if __name__ == "__main__":
    main()
