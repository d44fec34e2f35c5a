"""A clearance joint's impacts judged as a chaotic system's must be: by ensembles of runs.

The first impact of a dry clearance joint is a smooth function of the settings, but the impacts
after it are chaotic: a change in the last bit of any number moves them, so two runs that differ in
the crank's initial angle by 1e-12 rad give different impact sequences, each as right as the other.
One run cannot be compared with another impact by impact. This compares distributions instead:

- an **ensemble** is `runs` runs at the same settings that differ only in the last bits: the
  crank's initial angle plus k·1e-12 rad, k = 0 … runs − 1 (not the tolerance: the internal steps
  end on the FMU's clock grid of 2⁻⁴⁰ s, which absorbs a change of the tolerance in its sixth
  digit);
- a run's **peaks** are the local maxima of `<joint>.forcePeak` (the joint force's largest value
  over each communication interval, every internal step and dense-output sample counted) above
  10 % of the run's first impact, the first local maximum after the joint's first contact onset;
- the **first impact**, before the motion forgets its start, is judged run by run: each tested
  run's against the converged ensemble's median, within `bound`;
- the **later peaks**, pooled over the ensemble, are judged by the mean of their upper decile
  (the peaks at or above their 90th percentile) and their largest, each within `bound` of the
  converged ensemble's (`STATISTICS`). These are statistics that two converged ensembles (rtol
  1e-7 and 1e-8) pass against each other; the 90th percentile itself does not always (where
  the distribution is thin a small shift of the fraction moves it far), nor do the median and
  the count of small rattles (docs/guide/validation.md);
- a verdict near the bound can be luck (the judged statistics' sampling noise is about 1 % per
  44-run ensemble): with `--families F` the tested ensemble is run F times, the f-th with the
  perturbations k·1e-12 rad, k = f·runs … (f + 1)·runs − 1, each judged against the same converged
  ensemble, and the check passes only if every family does.

    python -m fsc ensemble [NAME=VALUE ...] [--joint joint|crankPin|mainBearing] [--runs 44]
        [--rtol R] [--reference-rtol 1e-7] [--stop 0.024] [--interval 1e-5] [--bound 0.02]
        [--tested-only NAME=VALUE ...] [--families 1] [--workers N] [--out DIR] [--fmu PATH]

NAME=VALUE are start values of both ensembles (switches by item name: `crankPin.model=dry`);
`--tested-only` adds start values to the tested ensemble alone (a deliberate error, to see the
check fail). It writes `ensemble.md` (the table) and `ensemble.png` (the peaks' distributions)
into `--out`, with every run's peaks (`peaks.json`), and exits with 1 if a judged statistic is
outside its bound.
"""
import argparse
import json
import sys
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

#: Runs per ensemble: with 11 the judged statistics' sampling noise is about 1 % per ensemble
#: (bootstrap over the runs, the 4-mode rod's defaults), so that two converged ensembles differ by
#: more than 2 % one time in six; with 44 it is halved.
RUNS = 44
#: A peak counts from this fraction of the run's first impact.
THRESHOLD = 0.1
#: The perturbation of the crank's initial angle from one run of an ensemble to the next [rad].
PERTURBATION = 1e-12
def upper_decile_mean(p):
    """The mean of the peaks at or above the 90th percentile."""
    p = np.asarray(p, dtype=float)
    return float(np.mean(p[p >= np.percentile(p, 90)]))


#: The statistics of the later peaks that are judged: (name, function of the pooled peaks).
STATISTICS = (("upper-decile mean", upper_decile_mean),
              ("largest", lambda p: float(np.max(p))))
#: Reported beside them, not judged.
INFORMATION = (("90th percentile", lambda p: float(np.percentile(p, 90))),
               ("median", lambda p: float(np.median(p))))


def peaks(force_peak, onsets, threshold=THRESHOLD):
    """The first impact and the later peaks of one run: the local maxima of the per-interval
    force peaks `force_peak` above `threshold` times the first, which is the first local maximum
    at or after the first interval whose contact-onset count `onsets` is positive. (None, []) if
    the joint never touches."""
    p = np.asarray(force_peak, dtype=float)
    touched = np.flatnonzero(np.asarray(onsets) > 0)
    if len(touched) == 0 or len(p) < 3:
        return None, []
    inner = np.arange(1, len(p) - 1)
    maxima = inner[(p[inner] > p[inner - 1]) & (p[inner] >= p[inner + 1])]
    maxima = maxima[maxima >= touched[0] - 1]
    if len(maxima) == 0:
        return None, []
    first = p[maxima[0]]
    later = [float(p[i]) for i in maxima[1:] if p[i] > threshold * first]
    return float(first), later


def run_one(job):
    """One run of an ensemble: (first impact, later peaks, steps)."""
    from fmpy import simulate_fmu
    directory, model_description, start_values, joint, stop, interval = job
    names = [f"{joint}.forcePeak", f"{joint}.contactOnsetsTotal", "solver.steps"]
    result = simulate_fmu(directory, model_description=model_description,
                          start_values=start_values, stop_time=stop, output_interval=interval,
                          output=names)
    first, later = peaks(result[names[0]], result[names[1]])
    return first, later, int(result["solver.steps"][-1])


def ensemble(directory, model_description, start_values, rtol, runs, joint, stop, interval,
             workers=None, first=0):
    """The runs of one ensemble at `rtol`, the k-th with the crank's initial angle moved by
    k·PERTURBATION, k = first … first + runs − 1: a list of (first impact, later peaks, steps)."""
    angle = start_values.get("crank.initialAngle", 0.0)
    jobs = [(directory, model_description,
             {**start_values, "solver.relativeTolerance": rtol,
              "crank.initialAngle": angle + k * PERTURBATION},
             joint, stop, interval) for k in range(first, first + runs)]
    with ProcessPoolExecutor(max_workers=workers) as pool:
        return list(pool.map(run_one, jobs))


def pooled(runs):
    """The later peaks of every run of an ensemble, in one array."""
    return np.concatenate([np.asarray(r[1], dtype=float) for r in runs] + [np.zeros(0)])


def noise(tested, reference, f, draws=500, seed=0):
    """The sampling noise of the relative difference f(tested)/f(reference) − 1 of a statistic
    `f` of the pooled later peaks: the standard deviation over `draws` bootstrap resamples of
    each ensemble's runs (a run's peaks stay together: they are not independent)."""
    rng = np.random.default_rng(seed)

    def resampled(runs):
        return f(pooled([runs[i] for i in rng.integers(0, len(runs), len(runs))]))
    return float(np.std([resampled(tested) / resampled(reference) - 1 for _ in range(draws)]))


def compare(tested, reference, bound):
    """The rows of the comparison, (statistic, tested, reference, relative difference, its
    sampling noise or None, judged, within bound), and whether every judged one is within
    `bound`."""
    t, r = pooled(tested), pooled(reference)
    rows = []
    firsts = np.array([f for f, _, _ in tested], dtype=float)
    reference_first = float(np.median([f for f, _, _ in reference]))
    worst = firsts[np.argmax(np.abs(firsts - reference_first))]
    rows.append(("first impact, worst run", float(worst), reference_first,
                 worst / reference_first - 1, None, True))
    for name, f in STATISTICS:
        a, b = f(t), f(r)
        rows.append((f"later peaks, {name}", a, b, a / b - 1, noise(tested, reference, f), True))
    for name, f in INFORMATION:
        a, b = f(t), f(r)
        rows.append((f"later peaks, {name}", a, b, a / b - 1, noise(tested, reference, f),
                     False))
    a, b = len(t) / len(tested), len(r) / len(reference)
    rows.append(("later peaks per run", a, b, a / b - 1, None, False))
    a = float(np.mean([s for _, _, s in tested]))
    b = float(np.mean([s for _, _, s in reference]))
    rows.append(("internal steps per run", a, b, a / b - 1, None, False))
    rows = [(*row, (not row[5]) or abs(row[3]) <= bound) for row in rows]
    return rows, all(row[6] for row in rows)


def table(rows, settings, bound):
    """The comparison as a Markdown table, with the settings it was run with."""
    lines = [f"Ensembles: {settings}", "",
             "| statistic | tested | converged | difference | its noise (1σ, bootstrap) | judged "
             f"(within ±{100 * bound:g} %) |", "|---|---|---|---|---|---|"]
    for name, a, b, d, sigma, judged, ok in rows:
        verdict = ("yes" if ok else "**no**") if judged else "—"
        spread = "—" if sigma is None else f"{100 * sigma:.2f} %"
        lines.append(f"| {name} | {a:.6g} | {b:.6g} | {100 * d:+.2f} % | {spread} | {verdict} |")
    return "\n".join(lines) + "\n"


def families_table(families, bound):
    """The judged statistics of each further family of the tested ensemble against the converged
    one, as a Markdown table: `families` is a list of (first perturbation index, rows, passed)."""
    judged = [row[0] for row in families[0][1] if row[5]]
    lines = ["", "Further families of the tested ensemble, against the same converged ensemble:", "",
             "| perturbations k | " + " | ".join(judged) + f" | within ±{100 * bound:g} % |",
             "|---|" + "---|" * (len(judged) + 1)]
    for first, rows, ok in families:
        cells = [f"{100 * row[3]:+.2f} %" for row in rows if row[5]]
        lines.append(f"| {first} … | " + " | ".join(cells) + f" | {'yes' if ok else '**no**'} |")
    return "\n".join(lines) + "\n"


def picture(tested, reference, labels, path, joint):
    """The later peaks' empirical distribution functions of both ensembles, and each run's first
    impact, to `path`."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for runs, label, colour in ((reference, labels[1], "black"), (tested, labels[0], "tab:red")):
        p = np.sort(np.concatenate([np.asarray(r[1], dtype=float) for r in runs]))
        ax.step(p / 1e3, np.arange(1, len(p) + 1) / max(len(p), 1), where="post", color=colour,
                label=f"{label}: {len(p)} later peaks")
        for first, _, _ in runs:
            ax.axvline(first / 1e3, color=colour, lw=0.5, alpha=0.5)
    ax.set_xlabel(f"{joint} force peak [kN] (thin lines: each run's first impact)")
    ax.set_ylabel("fraction of the later peaks below")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def start_values(pairs, variables):
    """NAME=VALUE strings as start values, switches by item name or number."""
    from .study import StudyError, _check_value
    out = {}
    for pair in pairs:
        name, sep, text = pair.partition("=")
        if not sep:
            raise StudyError(f"{pair!r}: expected NAME=VALUE")
        value = text
        for convert in (int, float):
            try:
                value = convert(text)
                break
            except ValueError:
                pass
        if text in ("true", "false"):
            value = text == "true"
        v = variables.get(name)
        if v is not None and v.type == "Real" and isinstance(value, int):
            value = float(value)
        out[name] = _check_value("command line", name, value, variables)
    return out


def main(argv=None) -> int:
    from fmpy import extract, read_model_description

    from .study import StudyError
    parser = argparse.ArgumentParser(prog="python -m fsc ensemble")
    parser.add_argument("settings", nargs="*", help="NAME=VALUE start values of both ensembles")
    parser.add_argument("--joint", default="joint", choices=["joint", "crankPin", "mainBearing"])
    parser.add_argument("--runs", type=int, default=RUNS)
    parser.add_argument("--rtol", type=float, help="tolerance under test (default: the FMU's)")
    parser.add_argument("--reference-rtol", type=float, default=1e-7)
    parser.add_argument("--stop", type=float, default=0.024, help="stop time [s]")
    parser.add_argument("--interval", type=float, default=1e-5, help="communication step [s]")
    parser.add_argument("--bound", type=float, default=0.02)
    parser.add_argument("--tested-only", nargs="*", default=[],
                        help="NAME=VALUE start values of the tested ensemble alone")
    parser.add_argument("--families", type=int, default=1,
                        help="runs of the tested ensemble, each with its own perturbations")
    parser.add_argument("--workers", type=int)
    parser.add_argument("--out", default="target/ensemble")
    parser.add_argument("--fmu", default="target/fmu/FlexibleSliderCrank.fmu")
    args = parser.parse_args(argv)
    md = read_model_description(args.fmu)
    variables = {v.name: v for v in md.modelVariables}
    try:
        common = start_values(args.settings, variables)
        extra = start_values(args.tested_only, variables)
    except StudyError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    rtol = args.rtol or float(variables["solver.relativeTolerance"].start)
    directory = extract(args.fmu)
    window = (args.joint, args.stop, args.interval)
    tested, *others = [ensemble(directory, md, {**common, **extra}, rtol, args.runs, *window,
                                workers=args.workers, first=f * args.runs)
                       for f in range(max(args.families, 1))]
    reference = ensemble(directory, md, common, args.reference_rtol, args.runs, *window,
                         workers=args.workers)
    if any(r[0] is None for runs in [tested, reference, *others] for r in runs):
        print(f"error: {args.joint} never touches in some run", file=sys.stderr)
        return 2
    rows, ok = compare(tested, reference, args.bound)
    families = [((f + 1) * args.runs, *compare(runs, reference, args.bound))
                for f, runs in enumerate(others)]
    ok = ok and all(passed for _, _, passed in families)
    described = ", ".join(args.settings) or "the FMU's defaults"
    if args.tested_only:
        described += f"; tested ensemble only: {', '.join(args.tested_only)}"
    settings = (f"{described}; {args.joint}, {args.runs} runs each over {args.stop} s sampled "
                f"every {args.interval} s; tested rtol {rtol:g}, converged rtol "
                f"{args.reference_rtol:g} (the k-th run's initial crank angle + k·{PERTURBATION:g} "
                f"rad)")
    text = table(rows, settings, args.bound)
    if families:
        text += families_table(families, args.bound)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "ensemble.md").write_text(text)
    raw = {label: [{"first": f, "later": later, "steps": s} for f, later, s in runs]
           for label, runs in (("tested", tested), ("converged", reference))}
    (out / "peaks.json").write_text(json.dumps({"settings": settings, **raw}))
    picture(tested, reference, (f"rtol {rtol:g}", f"rtol {args.reference_rtol:g}"),
            out / "ensemble.png", args.joint)
    print(text)
    print(f"wrote {out / 'ensemble.md'} and {out / 'ensemble.png'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
