"""`python -m fsc sweep STUDY.toml [--out DIR] [--scheduler ADDRESS] [--workers N] [--fmu PATH]`
`python -m fsc bearing-report MACHINE.toml [--out DIR] [--cycles N] [--fmu PATH]`
`python -m fsc ensemble [NAME=VALUE ...] [--joint J] [--runs N] [--rtol R] ...` (`fsc.ensemble`)"""
import argparse
import sys
from pathlib import Path

from .study import StudyError, load


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ["ensemble"]:
        from .ensemble import main as ensemble
        return ensemble(argv[1:])
    parser = argparse.ArgumentParser(prog="python -m fsc")
    sub = parser.add_subparsers(dest="command", required=True)
    sweep = sub.add_parser("sweep", help="run a parameter study on Dask")
    sweep.add_argument("study", help="study file (TOML)")
    sweep.add_argument("--out", help="output directory (default: target/studies/<study name>)")
    sweep.add_argument("--scheduler", help="address of an existing Dask scheduler")
    sweep.add_argument("--workers", type=int, help="LocalCluster worker processes (default: cores)")
    sweep.add_argument("--fmu", help="FMU to use instead of the study's")
    report = sub.add_parser("bearing-report",
                            help="a machine's bearings over its load cycle: pictures and results")
    report.add_argument("machine", help="machine file (TOML)")
    report.add_argument("--out", help="output directory (default: target/bearing-report/<machine>)")
    report.add_argument("--cycles", type=int, help="load cycles to run (default: the file's, or 3)")
    report.add_argument("--fmu", help="FMU to use instead of the machine file's")
    sub.add_parser("ensemble", help="a clearance joint's impacts judged by ensembles of runs "
                                    "(python -m fsc ensemble --help)")
    args = parser.parse_args(argv)
    if args.command == "bearing-report":
        return bearing_report(args)
    from .sweep import report, run
    try:
        study = load(args.study, fmu=args.fmu)
    except StudyError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    out = Path(args.out or Path("target/studies") / Path(args.study).stem)
    ran = run(study, out, scheduler=args.scheduler, workers=args.workers)
    print(f"{len(study.cases)} cases, {ran} run now, {len(study.cases) - ran} already done")
    print(report(study, out))
    print(f"results: {out}/results (Parquet), plots and summary.txt in {out}")
    return 0


def bearing_report(args) -> int:
    from . import bearing_report as b
    try:
        machine = b.load(args.machine, fmu=args.fmu, cycles=args.cycles)
        data = b.run(machine)
        page = b.write(machine, data, Path(args.out or Path("target/bearing-report") / machine.name))
    except StudyError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    print(f"wrote {page}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
