"""Benchmark of the study tool: 32 cases (the 4-mode rod, dry joint,
4 clearances × 8 speeds, 24 ms each) run (a) serially with bare fmpy `simulate_fmu` calls on the
unpacked FMU, (b) with `fsc.sweep.run` on a running LocalCluster of 1 worker (the tool's overhead per case)
and (c) of 2 workers (the speed-up), in round-robin rounds (best round each). The clusters'
start-up, paid once per study, is printed apart.

usage: python -m fsc.sweep_benchmark FMU
"""
import sys
import tempfile
import time
from pathlib import Path

from dask.distributed import Client, LocalCluster
from fmpy import extract, read_model_description, simulate_fmu

from fsc import study as study_mod
from fsc.sweep import read_results, run

STUDY = """stop_time = 0.024
output_interval = 1e-4
[grid]
"joint.clearance" = [1e-4, 2e-4, 5e-4, 1e-3]
[grid.speed]
"drive.speed" = [200.0, 250.0, 300.0, 350.0, 400.0, 450.0, 500.0, 550.0]
"crank.initialSpeed" = [200.0, 250.0, 300.0, 350.0, 400.0, 450.0, 500.0, 550.0]
"""


ROUNDS = 3


def main(fmu):
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "bench.toml"
        path.write_text(f'fmu = "{Path(fmu).resolve()}"\n' + STUDY)
        study = study_mod.load(path)
        directory = extract(fmu)
        md = read_model_description(directory)
        n = len(study.cases)
        clients = {}
        for workers in (1, 2):
            # Each cluster starts once (about 0.5 s here), timed apart and outside the rounds.
            t0 = time.perf_counter()
            cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                   dashboard_address=None)
            clients[workers] = (Client(cluster), cluster)
            print(f"LocalCluster of {workers}: start-up {time.perf_counter() - t0:.2f} s")
        # Round-robin: every round runs the serial loop and both clusters once, so that a slow
        # spell of this shared machine hits all three alike; each keeps its best round.
        rounds = []
        for r in range(ROUNDS):
            t0 = time.perf_counter()
            for values in study.cases:
                simulate_fmu(directory, model_description=md, start_values=values,
                             stop_time=study.stop_time, output_interval=study.output_interval,
                             output=["joint.forcePeak"])
            times = {0: time.perf_counter() - t0}
            for workers, (client, _) in clients.items():
                out = Path(tmp) / f"out{workers}-{r}"
                t0 = time.perf_counter()
                run(study, out, progress=False, client=client)
                times[workers] = time.perf_counter() - t0
                walls = read_results(out).column("wall_time").to_pylist()
                times[f"inside{workers}"] = sum(walls) / len(walls)
            rounds.append(times)
            print(f"round {r + 1}: serial {times[0]:.2f} s, 1 worker {times[1]:.2f} s, "
                  f"2 workers {times[2]:.2f} s (speed-up {times[0] / times[2]:.2f}); "
                  f"simulate_fmu inside the workers {1e3 * times['inside1']:.0f} / "
                  f"{1e3 * times['inside2']:.0f} ms per case")
        for client, cluster in clients.values():
            client.close()
            cluster.close()
        best = {k: min(t[k] for t in rounds) for k in (0, 1, 2)}
        print(f"\n| {n} cases, best of {ROUNDS} rounds | wall time [s] | per case [ms] |")
        print("|---|---|---|")
        print(f"| serial, bare simulate_fmu | {best[0]:.2f} | {1e3 * best[0] / n:.0f} |")
        print(f"| fsc sweep, LocalCluster 1 worker | {best[1]:.2f} | {1e3 * best[1] / n:.0f} |")
        print(f"| fsc sweep, LocalCluster 2 workers | {best[2]:.2f} | {1e3 * best[2] / n:.0f} |")
        print(f"\nspeed-up 2 workers vs serial bare: {best[0] / best[2]:.2f}; vs 1 worker: "
              f"{best[1] / best[2]:.2f}; tool overhead per case (1 worker vs bare): "
              f"{1e3 * (best[1] - best[0]) / n:.0f} ms")


if __name__ == "__main__":
    main(sys.argv[1])
