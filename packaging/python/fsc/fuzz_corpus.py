"""The fuzz corpus kept in the repository: at most a fixed number of inputs per target, chosen
greedily by the coverage features libFuzzer recorded for each (its merge control file).

libFuzzer's set-cover merge keeps the smallest set that covers *every* feature, hundreds of inputs
for the call-sequence targets; most of them add one rare feature each. The kept corpus trades those
for a bounded size: each step takes the input that adds the most features not yet covered (the
smaller on a tie), until the limit or until no input adds any. The run reports the fraction of the
features the kept inputs cover.

    python -m fsc.fuzz_corpus CONTROL_FILE DESTINATION [--limit N]
"""

from __future__ import annotations

import argparse
import os
import shutil
import sys


def read_control_file(path: str) -> dict[str, set[int]]:
    """The features of every input a merge control file lists, by the input's path.

    The file holds the number of inputs, the number in the first corpus, one path per input, then
    for every input executed a `STARTED i size` line followed by `FT i f1 f2 ...` (its features) and
    `COV i c1 c2 ...` (its coverage)."""
    with open(path, encoding="utf-8") as control:
        lines = control.read().splitlines()
    count = int(lines[0])
    paths = lines[2 : 2 + count]
    features: dict[str, set[int]] = {}
    for line in lines[2 + count :]:
        fields = line.split()
        if fields and fields[0] == "FT":
            features[paths[int(fields[1])]] = {int(f) for f in fields[2:]}
    return features


def select(features: dict[str, set[int]], limit: int, size=os.path.getsize) -> list[str]:
    """At most `limit` inputs, each adding the most features not yet covered (the smaller input,
    then the earlier path, on a tie); stops when no input adds a feature."""
    covered: set[int] = set()
    chosen: list[str] = []
    remaining = dict(features)
    while remaining and len(chosen) < limit:
        best = max(remaining, key=lambda p: (len(remaining[p] - covered), -size(p), p))
        if not remaining[best] - covered:
            break
        covered |= remaining.pop(best)
        chosen.append(best)
    return chosen


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("control_file")
    parser.add_argument("destination", help="directory the chosen inputs replace")
    parser.add_argument("--limit", type=int, default=33)
    args = parser.parse_args(argv)
    features = read_control_file(args.control_file)
    features = {p: f for p, f in features.items() if os.path.exists(p)}
    chosen = select(features, args.limit)
    every = set().union(*features.values()) if features else set()
    kept = set().union(*(features[p] for p in chosen)) if chosen else set()
    staging = args.destination.rstrip("/") + ".new"
    shutil.rmtree(staging, ignore_errors=True)
    os.makedirs(staging)
    for path in chosen:
        shutil.copy(path, os.path.join(staging, os.path.basename(path)))
    shutil.rmtree(args.destination, ignore_errors=True)
    os.rename(staging, args.destination)
    share = len(kept) / len(every) if every else 1.0
    print(
        f"{args.destination}: {len(chosen)} of {len(features)} inputs kept, "
        f"{len(kept)} of {len(every)} features ({share:.1%})"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
