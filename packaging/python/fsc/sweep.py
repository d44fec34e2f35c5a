"""Runs a study on Dask: every case through fmpy on a worker, results to Parquet as they complete.

- Scheduler: an embedded LocalCluster (one single-threaded worker process per core) or an existing
  Dask cluster (`scheduler` = its address), whose workers need fmpy, numpy and this package
  importable (the `fsc` package installed); the FMU itself reaches them through Dask.
- Results: `OUT/results/` is a Parquet dataset with one file per finished case (parameters, metrics,
  status, message, case id). A re-run skips the cases whose file exists, so an interrupted study
  resumes. Kept time series go to `OUT/series/case=<id>/`.
- At the end: `OUT/summary.txt` and a PNG per metric over the swept parameters.
"""
import json
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq
from dask.distributed import Client, LocalCluster, as_completed
from tqdm import tqdm

from . import study as study_mod
from .runner import run_case


def finished_ids(out: Path) -> set:
    """Case ids already in the results dataset."""
    results = out / "results"
    return {p.stem for p in results.glob("*.parquet")} if results.is_dir() else set()


def write_row(out: Path, study, case_id: str, values: dict, status: str, message: str,
              metrics: dict | None, series: dict | None):
    """One finished case: its row (atomically: written then renamed) and its series."""
    row = {"case_id": case_id, "status": status, "message": message,
           "parameters": json.dumps(values, sort_keys=True)}
    for name, value in values.items():
        row[name] = value if isinstance(value, str) else float(value)
    for name in study_mod.METRICS:
        row[name] = float((metrics or {}).get(name, np.nan))
    table = pa.Table.from_pylist([row])
    results = out / "results"
    results.mkdir(parents=True, exist_ok=True)
    tmp = results / f".{case_id}.tmp"
    pq.write_table(table, tmp)
    tmp.rename(results / f"{case_id}.parquet")
    if series:
        directory = out / "series" / f"case={case_id}"
        directory.mkdir(parents=True, exist_ok=True)
        pq.write_table(pa.table(series), directory / "part-0.parquet")


def read_results(out: Path):
    """The results dataset as a pyarrow Table (one row per finished case)."""
    files = sorted((out / "results").glob("*.parquet"))
    if not files:
        return pa.table({})
    return pa.concat_tables([pq.read_table(f) for f in files], promote_options="default")


def run(study, out, scheduler=None, workers=None, progress=True, on_result=None, client=None):
    """Runs every case of `study` not finished yet in `out`; returns the number of cases run.
    Uses `client` if given, else connects to `scheduler`, else starts a LocalCluster of `workers`
    processes (default: one per core) for this call."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    done = finished_ids(out)
    todo = {}
    for values in study.cases:
        case_id = study.case_id(values)
        if case_id not in done:
            todo[case_id] = values
    if not todo:
        return 0
    cluster, own_client = None, client is None
    if client is not None:
        pass
    elif scheduler:
        client = Client(scheduler)
    else:
        import os
        n = workers or os.cpu_count() or 1
        cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        client = Client(cluster)
    try:
        fmu = client.scatter(study.fmu.read_bytes(), broadcast=True)
        futures = {}
        for case_id, values in todo.items():
            f = client.submit(run_case, fmu, study.guid, values, study.stop_time,
                              study.output_interval, study.series, study.metrics_start,
                              study.inputs, study.files, key=f"case-{case_id}", pure=False)
            futures[f] = case_id
        bar = tqdm(total=len(futures), disable=not progress, unit="case")
        for future in as_completed(futures):
            case_id = futures[future]
            try:
                status, message, metrics, series = future.result()
            except Exception as e:   # noqa: BLE001 - the task itself failed (e.g. killed twice)
                status, message, metrics, series = "error", f"task failed: {e}", None, None
            write_row(out, study, case_id, todo[case_id], status, message, metrics, series)
            bar.update(1)
            if on_result:
                on_result(case_id, status)
        bar.close()
    finally:
        if own_client:
            client.close()
        if cluster:
            cluster.close()
    return len(todo)


def _label(value) -> str:
    """A swept value as a tick label: a number to 3 digits, a file by its name."""
    return value.rsplit("/", 1)[-1] if isinstance(value, str) else f"{value:.3g}"


def report(study, out):
    """Summary text and plots of every metric over the swept parameters."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = Path(out)
    rows = read_results(out).to_pylist()
    ok = [r for r in rows if r["status"] == "ok"]
    lines = [f"study {study.path}: {len(rows)} cases, {len(ok)} ok, {len(rows) - len(ok)} error"]
    for r in rows:
        if r["status"] != "ok":
            lines.append(f"  error {r['case_id']} {r['parameters']}: {r['message']}")
    for metric in study_mod.METRICS:
        values = np.array([r[metric] for r in ok], dtype=float)
        if values.size:
            lines.append(f"  {metric}: min {values.min():.4g}, median {np.median(values):.4g}, "
                         f"max {values.max():.4g}")
    (out / "summary.txt").write_text("\n".join(lines) + "\n")
    swept = study.swept
    for metric in study_mod.METRICS:
        fig, ax = plt.subplots(figsize=(6, 4.5))
        if len(swept) == 2 and ok:
            xs = sorted({r[swept[0]] for r in ok})
            ys = sorted({r[swept[1]] for r in ok})
            grid = np.full((len(ys), len(xs)), np.nan)
            for r in ok:
                grid[ys.index(r[swept[1]]), xs.index(r[swept[0]])] = r[metric]
            im = ax.imshow(grid, origin="lower", aspect="auto", cmap="viridis")
            ax.set_xticks(range(len(xs)), [_label(x) for x in xs])
            ax.set_yticks(range(len(ys)), [_label(y) for y in ys])
            ax.set(xlabel=swept[0], ylabel=swept[1])
            fig.colorbar(im, ax=ax, label=metric)
        elif len(swept) == 1 and ok:
            pts = sorted((r[swept[0]], r[metric]) for r in ok)
            ax.plot(*zip(*pts), "o-")
            ax.set(xlabel=swept[0], ylabel=metric)
        else:
            ax.hist([r[metric] for r in ok], bins=20)
            ax.set(xlabel=metric, ylabel="cases")
        ax.set_title(metric)
        fig.tight_layout()
        fig.savefig(out / f"{metric}.png", dpi=100)
        plt.close(fig)
    return "\n".join(lines)
