"""`python -m fsc sweep STUDY.toml [--out DIR] [--scheduler ADDRESS] [--workers N] [--fmu PATH]`"""
import argparse
import sys
from pathlib import Path

from .study import StudyError, load


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m fsc")
    sub = parser.add_subparsers(dest="command", required=True)
    sweep = sub.add_parser("sweep", help="run a parameter study on Dask")
    sweep.add_argument("study", help="study file (TOML)")
    sweep.add_argument("--out", help="output directory (default: target/studies/<study name>)")
    sweep.add_argument("--scheduler", help="address of an existing Dask scheduler")
    sweep.add_argument("--workers", type=int, help="LocalCluster worker processes (default: cores)")
    sweep.add_argument("--fmu", help="FMU to use instead of the study's")
    args = parser.parse_args(argv)
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


if __name__ == "__main__":
    sys.exit(main())
