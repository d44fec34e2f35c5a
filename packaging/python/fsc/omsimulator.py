"""Records the FMI 3.0 FMUs that masters with a scalar FMI 3 import load — the slider-crank without
its section arrays and both without input derivatives (`target/fmu/fmi3/scalar/FlexibleSliderCrank.fmu`,
`target/fmu/fmi3/scalar/DcMotor.fmu`) — as OMSimulator's FMI 3 import runs them: their DefaultExperiment
(24 ms in 240 communication steps), the outputs of `RECORDED` at every communication point, as
OMSimulator writes them (12 significant digits), into `packaging/python/tests/data/`. The test
command compares fmpy's run of the freshly built FMUs with these records
(`tests/test_omsimulator.py`); a change of results shows there, and this script records them anew.

    python -m fsc.omsimulator OMSIMULATOR [--fmus DIR] [--out DIR]

OMSimulator is built from its sources (it has no binary in the package registries); its command line
is `OMSimulator FMU --mode=cs --stopTime=0.024 --intervals=240 --resultFile=FILE.csv`. It writes each
communication point twice (and the last three times, after a final step of length 0): the first
row of each point is the state the step reached.
"""
import argparse
import csv
import subprocess
import sys
import tempfile
from pathlib import Path

#: The outputs recorded of each FMU (a small set that spans the mechanism, the joint, the rod, the
#: energies and the integrator; the motor's every output).
RECORDED = {
    "FlexibleSliderCrank": [
        "crank.angle", "crank.speed", "crank.torque", "slider.position", "slider.velocity",
        "slider.acceleration", "joint.force", "joint.forcePeak", "joint.eccentricityX",
        "joint.eccentricityY", "joint.contactOnsetsTotal", "rod.midspanDeflection", "rod.stress",
        "rod.stressPeak", "crankPin.force", "mainBearing.force", "energy.kinetic",
        "energy.dissipated", "solver.steps",
    ],
    "DcMotor": ["shaft.torque", "motor.speed", "motor.current", "motor.voltage", "shaft.twist"],
}
#: Where each FMU is, under the packaging step's output directory.
FMUS = {"FlexibleSliderCrank": Path("fmi3/scalar/FlexibleSliderCrank.fmu"),
        "DcMotor": Path("fmi3/scalar/DcMotor.fmu")}
#: The records, beside the tests.
RECORDS = Path(__file__).resolve().parents[1] / "tests" / "data"
STOP, INTERVALS = 0.024, 240


def record_path(model: str, out: Path = RECORDS) -> Path:
    return out / f"omsimulator_{model}.csv"


def first_rows(result: Path) -> tuple[list, dict]:
    """OMSimulator's result file: its column names and, for each time, the first row written."""
    with open(result, newline="") as f:
        rows = list(csv.reader(f))
    header = [h.strip().strip('"') for h in rows[0]]
    first = {}
    for row in rows[1:]:
        row = [cell.strip() for cell in row]
        first.setdefault(row[0], row)
    return header, first


def run(omsimulator: str, fmu: Path, work: Path) -> Path:
    """Runs `fmu`'s DefaultExperiment in OMSimulator; returns its result file (an error or a warning
    in OMSimulator's log fails)."""
    result = work / f"{fmu.stem}.csv"
    done = subprocess.run([omsimulator, str(fmu.resolve()), "--mode=cs", f"--stopTime={STOP}",
                           f"--intervals={INTERVALS}", f"--resultFile={result}"],
                          capture_output=True, text=True, cwd=work)
    log = done.stdout + done.stderr
    if done.returncode != 0 or "error:" in log or "warning:" in log or not result.is_file():
        raise RuntimeError(f"OMSimulator failed on {fmu}:\n{log}")
    return result


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m fsc.omsimulator")
    parser.add_argument("omsimulator", help="the OMSimulator executable")
    parser.add_argument("--fmus", default="target/fmu", help="the packaging step's output")
    parser.add_argument("--out", default=str(RECORDS), help="where the records go")
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as work:
        for model, names in RECORDED.items():
            header, first = first_rows(run(args.omsimulator, Path(args.fmus) / FMUS[model],
                                           Path(work)))
            columns = [header.index(n) for n in names]
            path = record_path(model, Path(args.out))
            with open(path, "w", newline="") as f:
                out = csv.writer(f, lineterminator="\n")
                out.writerow(["time"] + names)
                for row in first.values():
                    out.writerow([row[0]] + [row[c] for c in columns])
            print(f"{model}: {len(first)} points of {len(names)} outputs -> {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
