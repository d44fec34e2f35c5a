"""Benchmark of the study tool (issue 10, acceptance 7): 32 cases (the 4-mode rod, dry joint,
4 clearances × 8 speeds, 24 ms each) run (a) serially with bare fmpy `simulate_fmu` calls on the
unpacked FMU, (b) with `fsc.sweep.run` on a running LocalCluster of 1 worker (the tool's overhead per case)
and (c) of 2 workers (the speed-up). The cluster's start-up, paid once per study, is printed apart.

usage: sweep_benchmark.py FMU
"""
import sys
import tempfile
import time
from pathlib import Path

from dask.distributed import Client, LocalCluster
from fmpy import extract, read_model_description, simulate_fmu

sys.path.insert(0, str(Path(__file__).resolve().parent))
from fsc import study as study_mod  # noqa: E402
from fsc.sweep import read_results, run  # noqa: E402

STUDY = """stop_time = 0.024
output_interval = 1e-4
[grid]
"joint.clearance" = [1e-4, 2e-4, 5e-4, 1e-3]
[grid.speed]
"drive.speed" = [200.0, 250.0, 300.0, 350.0, 400.0, 450.0, 500.0, 550.0]
"crank.initialSpeed" = [200.0, 250.0, 300.0, 350.0, 400.0, 450.0, 500.0, 550.0]
"""


def main(fmu):
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "bench.toml"
        path.write_text(f'fmu = "{Path(fmu).resolve()}"\n' + STUDY)
        study = study_mod.load(path)
        directory = extract(fmu)
        md = read_model_description(directory)
        t0 = time.perf_counter()
        for values in study.cases:
            simulate_fmu(directory, model_description=md, start_values=values,
                         stop_time=study.stop_time, output_interval=study.output_interval,
                         output=["joint.forcePeak"])
        bare = time.perf_counter() - t0
        times = {}
        for workers in (1, 2):
            # The cluster starts once per study (about 2 s here); timed apart.
            t0 = time.perf_counter()
            cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                   dashboard_address=None)
            client = Client(cluster)
            startup = time.perf_counter() - t0
            t0 = time.perf_counter()
            run(study, Path(tmp) / f"out{workers}", progress=False, client=client)
            times[workers] = time.perf_counter() - t0
            client.close()
            cluster.close()
            walls = read_results(Path(tmp) / f"out{workers}").column("wall_time").to_pylist()
            print(f"LocalCluster of {workers}: start-up {startup:.2f} s, simulate_fmu inside the "
                  f"workers {1e3 * sum(walls) / len(walls):.0f} ms per case")
        n = len(study.cases)
        print(f"| {n} cases | wall time [s] | per case [ms] |")
        print("|---|---|---|")
        print(f"| serial, bare simulate_fmu | {bare:.2f} | {1e3 * bare / n:.0f} |")
        print(f"| fsc sweep, LocalCluster 1 worker | {times[1]:.2f} | {1e3 * times[1] / n:.0f} |")
        print(f"| fsc sweep, LocalCluster 2 workers | {times[2]:.2f} | {1e3 * times[2] / n:.0f} |")
        print(f"\nspeed-up 2 workers vs serial bare: {bare / times[2]:.2f}; "
              f"tool overhead per case (1 worker vs bare): {1e3 * (times[1] - bare) / n:.0f} ms")


if __name__ == "__main__":
    main(sys.argv[1])
