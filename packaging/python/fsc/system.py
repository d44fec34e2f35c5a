"""The motor-crank system (target/fmu/MotorCrank.ssp, target/fmu/motor-crank/) run by a plain fmpy
master, and the coupling error of its communication step.

The master is a Jacobi loop: after initialization, and after every step, each FMU's outputs are
read and set as the other's inputs (motor shaft.torque -> crank drive.torque, crank crank.speed ->
motor shaft.speed); both FMUs then step from the same point. This is what libcosim's fixed-step
algorithm does, so the two give the same bits. As a Gauss-Seidel loop (`coupling="gauss-seidel"`)
the motor steps first and the crank then gets the motor's new shaft torque.

Inputs between communication points are
- "held": constant (zero-order hold),
- "order 1" / "order 2": polynomials whose derivatives the master estimates from the last two or
  three exchanged values and passes with fmi2SetRealInputDerivatives,
- "extrapolated": first derivatives the other FMU computes itself (fmi2GetRealOutputDerivatives:
  the crank's angular acceleration for the motor, the rate of the shaft torque for the crank).

usage: python -m fsc.system [--fmus DIR] [--plot FILE | --stability]
                      prints the coupling-error table of the user guide (docs/guide/systems.md): crank speed at 1 ms against a
                      run with a 2.5e-6 s communication step and second-order inputs, at
                      communication steps 1e-4, 5e-5 and 1e-5 s, the crank integrated at
                      solver.relativeTolerance 1e-6 (so that the table shows the coupling error,
                      not the crank's integration error) and at its default; with --plot, also
                      plots the system's 24 ms run (communication step 1e-4 s, held inputs) to FILE;
                      with --stability, prints instead the table of the largest stable communication
                      step: 0.2 s with held inputs, Jacobi and Gauss-Seidel, at steps from 1e-4 to
                      3e-3 s
"""
import math
import sys
from pathlib import Path

from .session import Session

#: The folder of both FMUs: the packaging step's `target/fmu`, from a clone's root (`--fmus DIR`
#: names another).
FMU_DIR = Path("target") / "fmu"
CRANK = "FlexibleSliderCrank.fmu"
MOTOR = "DcMotor.fmu"
# The crank's and the motor's parameters in the system (as bound in the SSP and the OSP file).
CRANK_PARAMETERS = {"drive.mode": 2, "crank.inertia": 0.02}
MOTOR_PARAMETERS = {"shaft.loadInertia": 0.0205}
SCHEMES = ("held", "order 1", "order 2", "extrapolated")


def run(step, stop, scheme="held", outputs=("crank.speed",), zero_start=False, crank_parameters=None,
        coupling="jacobi", fmi3=False):
    """The system over [0, stop] with communication step `step`: a list of (t, {name: value}) per
    communication point, names from both FMUs (crank's first). `zero_start` sets every
    connection to 0 before the first step instead of exchanging the initial outputs (the scheme of
    fmpy's simulate_ssp); `crank_parameters` are set on top of the system's; `coupling` is
    "jacobi" or "gauss-seidel" (held inputs only: the motor steps first); `fmi3` runs the FMI 3.0
    FMUs (`fmi3/` beside the FMI 2.0 ones; FMI 3 has no input derivatives: held inputs only)."""
    if fmi3 and scheme != "held":
        raise ValueError(f"scheme {scheme!r}: FMI 3.0 has no input derivatives")
    folder = FMU_DIR / "fmi3" if fmi3 else FMU_DIR
    motor, crank = Session(folder / MOTOR, "motor"), Session(folder / CRANK, "crank")
    crank.set({**CRANK_PARAMETERS, **(crank_parameters or {})})
    motor.set(MOTOR_PARAMETERS)
    for s in (motor, crank):
        s.initialize()
    torques, speeds = [], []
    rows, n = [], round(stop / step)
    for k in range(n):
        t = k * step
        if coupling == "gauss-seidel":
            motor.set({"shaft.speed": crank.get("crank.speed")})
            motor.fmu.doStep(t, step)
            crank.set({"drive.torque": motor.get("shaft.torque")})
            crank.fmu.doStep(t, step)
            rows.append(((k + 1) * step, read(outputs, crank, motor)))
            continue
        if zero_start and k == 0:
            torque = speed = 0.0
        else:
            torque, speed = motor.get("shaft.torque"), crank.get("crank.speed")
        torques.append(torque)
        speeds.append(speed)
        crank.set({"drive.torque": torque})
        motor.set({"shaft.speed": speed})
        if scheme == "extrapolated":
            rate = motor.fmu.getRealOutputDerivatives([motor.vr["shaft.torque"]], [1])[0]
            acceleration = crank.fmu.getRealOutputDerivatives([crank.vr["crank.speed"]], [1])[0]
            crank.fmu.setRealInputDerivatives([crank.vr["drive.torque"]], [1], [rate])
            motor.fmu.setRealInputDerivatives([motor.vr["shaft.speed"]], [1], [acceleration])
        elif scheme in ("order 1", "order 2"):
            for slave, name, history in ((crank, "drive.torque", torques),
                                         (motor, "shaft.speed", speeds)):
                for order, value in enumerate(differences(history, step, scheme), start=1):
                    slave.fmu.setRealInputDerivatives([slave.vr[name]], [order], [value])
        crank.fmu.doStep(t, step)
        motor.fmu.doStep(t, step)
        rows.append(((k + 1) * step, read(outputs, crank, motor)))
    motor.free()
    crank.free()
    return rows


def read(outputs, crank, motor):
    """{name: value} of `outputs`, each from the FMU that has it (the crank's first), or from the
    component a name such as "dcMotor/solver.warnings" names (the system's component names)."""
    components = {"sliderCrank": crank, "dcMotor": motor}

    def value(name):
        component, _, variable = name.rpartition("/")
        if component:
            return components[component].get(variable)
        return (crank if name in crank.vr else motor).get(name)
    return {name: value(name) for name in outputs}


#: Communication steps of the stability table [s], and the bounds of a stable run over 0.2 s: the
#: crank speed within 10 % of its 5000 rpm start, the motor current within 100 A (the 1e-4 s run:
#: 524 rad/s ± 6, −8…57 A).
STABILITY_STEPS = (1e-4, 2e-4, 3e-4, 4e-4, 5e-4, 7e-4, 1e-3, 1.5e-3, 2e-3, 2.5e-3, 3e-3)
STABLE_SPEED, STABLE_CURRENT = 0.1, 100.0


def stability(steps=STABILITY_STEPS, stop=0.2):
    """{coupling: {step: (crank-speed range, largest |motor.current|, stable)}} over `stop` with
    held inputs (a run an FMU stops, diverged, is unstable)."""
    table = {}
    for coupling in ("jacobi", "gauss-seidel"):
        table[coupling] = {}
        for h in steps:
            try:
                rows = run(h, stop, outputs=("crank.speed", "motor.current"), coupling=coupling)
            except Exception:  # noqa: BLE001 - a diverged coupling may stop an FMU: unstable
                table[coupling][h] = ((math.nan, math.nan), math.nan, False)
                continue
            speeds = [v["crank.speed"] for _, v in rows]
            current = max(abs(v["motor.current"]) for _, v in rows)
            start = 5000 * 2 * math.pi / 60
            stable = (all(math.isfinite(s) and abs(s / start - 1) <= STABLE_SPEED for s in speeds)
                      and current <= STABLE_CURRENT)
            table[coupling][h] = ((min(speeds), max(speeds)), current, stable)
    return table


def differences(history, step, scheme):
    """First (and for order 2 second) derivative at the last sample, by backward differences."""
    if scheme == "order 1" and len(history) >= 2:
        return [(history[-1] - history[-2]) / step]
    if scheme == "order 2" and len(history) >= 3:
        first = (3 * history[-1] - 4 * history[-2] + history[-3]) / (2 * step)
        second = (history[-1] - 2 * history[-2] + history[-3]) / step ** 2
        return [first, second]
    return []


def speed_at(step, time, scheme, crank_parameters=None):
    """crank.speed at `time`."""
    rows = run(step, time, scheme, crank_parameters=crank_parameters)
    return rows[-1][1]["crank.speed"]


def coupling_errors(steps=(1e-4, 5e-5, 1e-5), time=1e-3, reference_step=2.5e-6, tolerance=1e-6):
    """{step: {scheme: |crank.speed(time) − reference|}} and the reference value (second-order
    inputs at `reference_step`), the crank at solver.relativeTolerance `tolerance` (None: its
    default)."""
    crank = None if tolerance is None else {"solver.relativeTolerance": tolerance}
    reference = speed_at(reference_step, time, "order 2", crank)
    return reference, {h: {s: abs(speed_at(h, time, s, crank) - reference) for s in SCHEMES}
                       for h in steps}


def plot(path):
    """Crank speed, motor current and shaft torque, and joint.forcePeak over the system's run."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = ("crank.speed", "joint.forcePeak", "motor.current", "shaft.torque", "motor.speed")
    rows = run(1e-4, 0.024, outputs=names)
    t = [1e3 * r[0] for r in rows]
    series = {n: [r[1][n] for r in rows] for n in names}
    fig, axes = plt.subplots(3, 1, figsize=(9, 8), sharex=True)
    axes[0].plot(t, series["crank.speed"], label="crank.speed")
    axes[0].plot(t, series["motor.speed"], label="motor.speed")
    axes[0].set_ylabel("speed [rad/s]")
    axes[0].legend()
    axes[1].plot(t, series["motor.current"], label="motor.current [A]")
    axes[1].plot(t, series["shaft.torque"], label="shaft.torque [N m]")
    axes[1].legend()
    axes[2].plot(t, [f / 1e3 for f in series["joint.forcePeak"]], drawstyle="steps-pre")
    axes[2].set_ylabel("joint.forcePeak [kN]")
    axes[2].set_xlabel("time [ms]")
    fig.suptitle("DC motor with PI speed control driving the slider-crank (5000 rpm, dry clearance joint)")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    speeds = series["crank.speed"]
    print(f"crank speed {min(speeds):.1f}..{max(speeds):.1f} rad/s, motor current "
          f"{min(series['motor.current']):.1f}..{max(series['motor.current']):.1f} A, largest "
          f"joint.forcePeak {max(series['joint.forcePeak']):.0f} N; wrote {path}")


def main():
    global FMU_DIR
    if sys.argv[1:2] == ["--fmus"]:
        FMU_DIR = Path(sys.argv[2])
        del sys.argv[1:3]
    if sys.argv[1:2] == ["--stability"]:
        print("| communication step [s] | Jacobi: crank speed [rad/s] | max current [A] | "
              "Gauss-Seidel: crank speed [rad/s] | max current [A] |")
        print("|---|---|---|---|---|")
        table = stability()
        for h in STABILITY_STEPS:
            cells = []
            for coupling in ("jacobi", "gauss-seidel"):
                (low, high), current, stable = table[coupling][h]
                if math.isnan(current):
                    cells += ["diverged: an FMU stopped", "–"]
                else:
                    mark = "" if stable else " (unstable)"
                    cells += [f"{low:.0f}…{high:.0f}{mark}", f"{current:.0f}"]
            print(f"| {h:g} | " + " | ".join(cells) + " |")
        return 0
    if sys.argv[1:2] == ["--plot"]:
        plot(sys.argv[2])
    for tolerance in (1e-6, None):
        reference, errors = coupling_errors(tolerance=tolerance)
        setting = "default" if tolerance is None else f"{tolerance:g}"
        print(f"crank solver.relativeTolerance {setting}; reference crank.speed at 1 ms "
              f"(2.5e-6 s, order 2): {reference:.9f} rad/s\n")
        print("| communication step [s] | " + " | ".join(SCHEMES) + " | held / order 1 |")
        print("|---|" + "---|" * (len(SCHEMES) + 1))
        for h, e in errors.items():
            cells = " | ".join(f"{e[s]:.2e}" for s in SCHEMES)
            print(f"| {h:g} | {cells} | {e['held'] / e['order 1']:.1f} |")
        print()


if __name__ == "__main__":
    sys.exit(main())
