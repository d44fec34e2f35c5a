"""Tests of the parameter-study tool (`python -m fsc sweep`) on the packaged FMU."""
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import psutil
import pytest

from fsc import study as study_mod
from fsc.runner import run_case
from fsc.sweep import read_results, run

ROOT = Path(__file__).resolve().parents[3]
FMU = ROOT / "target" / "fmu" / "FlexibleSliderCrank.fmu"
PYTHON = sys.executable


def write_study(tmp_path, body, name="study.toml"):
    path = tmp_path / name
    path.write_text(f'fmu = "{FMU}"\n' + body)
    return path


SMALL = """stop_time = 0.004
output_interval = 1e-4
series = ["slider.position"]
[fixed]
"rod.formulation" = "rigid"
[grid]
"joint.clearance" = [2e-4, 5e-4]
[grid.speed]
"drive.speed" = [300.0, 523.6]
"crank.initialSpeed" = [300.0, 523.6]
"""


def rows_by_case(out):
    rows = read_results(out).to_pylist()
    for r in rows:
        r.pop("wall_time")
    return {r["case_id"]: r for r in rows}


def serial(study):
    """The cases run one by one in this process (no Dask)."""
    fmu = study.fmu.read_bytes()
    return {study.case_id(v): run_case(fmu, study.guid, v, study.stop_time, study.output_interval,
                                       study.series, study.metrics_start, study.inputs,
                                       study.files)
            for v in study.cases}


def test_local_cluster_equals_serial_runs(tmp_path):
    """A 2×2 study on a LocalCluster with 2 workers gives, case by case, bit for bit
    the metrics and kept series of the same cases run serially through fmpy in this process."""
    study = study_mod.load(write_study(tmp_path, SMALL))
    assert len(study.cases) == 4
    assert run(study, tmp_path / "out", workers=2, progress=False) == 4
    rows = rows_by_case(tmp_path / "out")
    for case_id, (status, _, metrics, series) in serial(study).items():
        row = rows[case_id]
        assert status == row["status"] == "ok"
        for name, value in metrics.items():
            if name != "wall_time":
                assert row[name] == value, name
        import pyarrow.parquet as pq
        kept = pq.read_table(tmp_path / "out" / "series" / f"case={case_id}").to_pydict()
        assert kept["slider.position"] == list(series["slider.position"])


def test_the_unpacked_fmu_is_removed_when_the_worker_ends(tmp_path):
    """A worker process unpacks the FMU once into a temporary directory and removes it when it
    exits."""
    code = f"""
from fsc import study as study_mod
from fsc.runner import run_case
study = study_mod.load({str(write_study(tmp_path, SMALL))!r})
run_case(study.fmu.read_bytes(), study.guid, dict(study.cases[0]), study.stop_time,
         study.output_interval, study.series)
from fsc.runner import _unpacked
print(next(iter(_unpacked.values()))[0])
"""
    out = subprocess.run([PYTHON, "-c", code], capture_output=True, text=True, check=True)
    directory = Path(out.stdout.strip().splitlines()[-1])
    assert directory.name.startswith("fsc-")
    assert not directory.exists()


def test_reused_instance_equals_fresh_simulate_fmu(tmp_path):
    """The runner resets one FMU instance per worker between cases (fmpy's efficient loop): every
    case, also one after a failing case and after a change of rod model, gives bit for bit the
    outputs of a fresh `simulate_fmu` call on the .fmu file (a case that leaves a parameter at
    its default after one that set it checks that the reset restores the defaults)."""
    from fmpy import simulate_fmu
    from fsc.runner import METRIC_OUTPUTS, metrics
    study = study_mod.load(write_study(tmp_path, SMALL))
    fmu = study.fmu.read_bytes()
    cases = [dict(study.cases[0]), {"joint.clearance": 4e-4}, {"joint.clearance": 0.0},
             dict(study.cases[3]),
             {**study.cases[1], "rod.formulation": 3}, dict(study.cases[0])]
    for values in cases:
        status, message, got, series = run_case(fmu, study.guid, values, study.stop_time,
                                                study.output_interval, study.series)
        if values.get("joint.clearance") == 0.0:
            assert status == "error" and "joint.clearance = 0" in message
            continue
        fresh = simulate_fmu(str(FMU), start_values=values, stop_time=study.stop_time,
                             output_interval=study.output_interval,
                             output=METRIC_OUTPUTS + study.series)
        expected = metrics(fresh)
        assert status == "ok"
        got.pop("wall_time")
        assert got == expected, values
        assert list(series["slider.position"]) == list(fresh["slider.position"])


def test_cases_in_parallel_threads_keep_their_own_instance_and_messages(tmp_path):
    """A worker of an existing cluster may run several cases at once in threads: each takes an idle
    instance of its own (or a new one), so failing and good cases running together keep their own
    results and error messages."""
    from concurrent.futures import ThreadPoolExecutor
    study = study_mod.load(write_study(tmp_path, SMALL))
    fmu = study.fmu.read_bytes()
    expected = serial(study)
    cases = [v for v in study.cases for _ in range(2)] + [{"joint.clearance": 0.0}] * 4

    def one(values):
        return values, run_case(fmu, study.guid, values, study.stop_time, study.output_interval,
                                study.series)

    with ThreadPoolExecutor(max_workers=4) as pool:
        for values, (status, message, metrics, _) in pool.map(one, cases):
            if values["joint.clearance"] == 0.0:
                assert status == "error" and "joint.clearance = 0" in message, message
            else:
                reference = expected[study.case_id(values)][2]
                assert status == "ok" and message == ""
                assert metrics["peak_joint_force"] == reference["peak_joint_force"]
                assert metrics["solver_steps"] == reference["solver_steps"]


def test_messages_stay_formatted_while_threads_install_the_logger(tmp_path):
    """Threads instantiating while others install the package's logger: every error message is
    the FMU's formatted text, never the raw format string ("%s") of an instance that caught the
    callbacks between the logger's installation steps."""
    from concurrent.futures import ThreadPoolExecutor
    study = study_mod.load(write_study(tmp_path, SMALL))
    fmu = study.fmu.read_bytes()

    def one(_):
        return run_case(fmu, study.guid, {"joint.clearance": 0.0}, study.stop_time,
                        study.output_interval, study.series)[:2]

    with ThreadPoolExecutor(max_workers=8) as pool:
        outcomes = list(pool.map(one, range(64)))
    assert all(status == "error" and "joint.clearance = 0" in message
               for status, message in outcomes), outcomes


def test_failing_case_is_a_row(tmp_path):
    """Clearance 0 with the dry joint is an error row with the FMU's message; the
    other cases are correct."""
    body = SMALL.replace("[2e-4, 5e-4]", "[0.0, 5e-4]")
    study = study_mod.load(write_study(tmp_path, body))
    run(study, tmp_path / "out", workers=2, progress=False)
    rows = rows_by_case(tmp_path / "out")
    reference = serial(study)
    for case_id, row in rows.items():
        status, message, metrics, _ = reference[case_id]
        assert row["status"] == status
        if json.loads(row["parameters"])["joint.clearance"] == 0.0:
            assert status == "error"
            assert "joint.clearance = 0" in row["message"] and "joint.model = dry" in row["message"]
        else:
            assert status == "ok" and row["peak_joint_force"] == metrics["peak_joint_force"]


def test_interrupted_study_resumes(tmp_path):
    """Finished cases are not run again, and the final dataset equals an
    uninterrupted run's."""
    study = study_mod.load(write_study(tmp_path, SMALL))
    out = tmp_path / "out"
    assert run(study, out, workers=2, progress=False) == 4
    complete = rows_by_case(out)
    # An interruption after two cases: their files exist, the other two do not.
    for path in sorted((out / "results").glob("*.parquet"))[:2]:
        path.unlink()
    assert run(study, out, workers=2, progress=False) == 2
    assert run(study, out, workers=2, progress=False) == 0
    assert rows_by_case(out) == complete


@pytest.mark.parametrize("entry, expected", [
    ('[grid]\n"joint.clearence" = [1e-4]\n', "grid.'joint.clearence'[0]: unknown variable"),
    ('[grid]\n"joint.clearance" = [1e-4, 2.0]\n',
     "grid.'joint.clearance'[1]: joint.clearance = 2.0 is outside the allowed range [0.0, 0.1]"),
    ('[fixed]\n"rod.nModes" = 2.5\n', "fixed.'rod.nModes': rod.nModes = 2.5 must be an integer"),
    ('[fixed]\n"joint.model" = "greased"\n', "fixed.'joint.model': joint.model = 'greased' is not one of"),
    ('[fixed]\n"joint.force" = 1.0\n', "joint.force is an output"),
    ('[fixed]\n"slider.forceTable" = "no_such.csv"\n',
     "slider.forceTable = 'no_such.csv': cannot read"),
    ('[fixed]\n"slider.forceTable" = 3\n', "must be a string (a file name)"),
    ('[inputs]\ntime = [0.0, 1.0]\n"crank.length" = [0.05, 0.05]\n',
     "inputs: 'crank.length' is not an input"),
    ('[inputs]\ntime = [1.0, 0.0]\n"drive.torque" = [0.0, 1.0]\n', "non-decreasing"),
    ('[inputs]\ntime = [0.0, 1.0]\n"drive.torque" = [0.0, 1e9]\n',
     "inputs.'drive.torque'[1]: drive.torque = 1000000000.0 is outside"),
])
def test_bad_study_fails_before_any_run(tmp_path, entry, expected):
    """An unknown variable, an out-of-range value or a wrong type fails before any
    run, naming the entry (and the range)."""
    path = write_study(tmp_path, "stop_time = 0.001\n" + entry)
    with pytest.raises(study_mod.StudyError, match=None) as e:
        study_mod.load(path)
    assert expected in str(e.value), str(e.value)
    cli = subprocess.run([PYTHON, "-m", "fsc", "sweep", str(path), "--out", str(tmp_path / "o")],
                         cwd=tmp_path, capture_output=True, text=True)
    assert cli.returncode == 2 and expected in cli.stderr
    assert not (tmp_path / "o").exists()


def test_killed_worker_does_not_lose_cases(tmp_path):
    """Killing one worker process in the middle of a study still completes every
    case, with the results of an undisturbed run."""
    body = SMALL.replace("stop_time = 0.004", "stop_time = 0.012").replace(
        "[2e-4, 5e-4]", "[1e-4, 2e-4, 3e-4, 5e-4]")
    study = study_mod.load(write_study(tmp_path, body))
    killed = []

    def kill_one(_case_id, _status):
        if not killed:
            workers = [p for p in psutil.Process().children(recursive=True)
                       if "python" in p.name().lower()]
            victim = workers[0]
            killed.append(victim.pid)
            os.kill(victim.pid, signal.SIGKILL)

    assert run(study, tmp_path / "out", workers=2, progress=False, on_result=kill_one) == 8
    assert killed
    rows = rows_by_case(tmp_path / "out")
    assert len(rows) == 8
    for case_id, (status, _, metrics, _) in serial(study).items():
        assert rows[case_id]["status"] == status == "ok"
        assert rows[case_id]["peak_joint_force"] == metrics["peak_joint_force"]


def test_existing_scheduler(tmp_path):
    """`--scheduler` runs the study on a separately started `dask scheduler` and
    `dask worker` (with this package on their path; the FMU reaches them through Dask)."""
    port = 8786 + os.getpid() % 1000
    address = f"tcp://127.0.0.1:{port}"
    env = dict(os.environ)
    dask = [str(Path(PYTHON).parent / "dask")]
    scheduler = subprocess.Popen(dask + ["scheduler", "--host", "127.0.0.1", "--port", str(port),
                                         "--no-dashboard"], env=env, cwd=tmp_path,
                                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    worker = subprocess.Popen(dask + ["worker", address, "--nthreads", "1", "--no-dashboard"],
                              env=env, cwd=tmp_path, stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL)
    try:
        from dask.distributed import Client
        deadline = time.time() + 60
        while True:
            try:
                with Client(address, timeout=5) as c:
                    c.wait_for_workers(1, timeout=30)
                break
            except OSError:
                if time.time() > deadline:
                    raise
                time.sleep(0.5)
        path = write_study(tmp_path, SMALL)
        cli = subprocess.run([PYTHON, "-m", "fsc", "sweep", str(path), "--out",
                              str(tmp_path / "out"), "--scheduler", address],
                             cwd=tmp_path, capture_output=True, text=True,
                             timeout=300)
        assert cli.returncode == 0, cli.stderr
        study = study_mod.load(path)
        rows = rows_by_case(tmp_path / "out")
        for case_id, (status, _, metrics, _) in serial(study).items():
            assert rows[case_id]["peak_joint_force"] == metrics["peak_joint_force"]
    finally:
        for p in (worker, scheduler):
            p.terminate()
            p.wait(timeout=30)


def test_metrics_leave_out_a_start_window():
    """With metrics_start the metrics cover only the rows after it: a start-up peak before it does
    not count, and the onsets and dissipated energy are those of the window."""
    import numpy as np

    from fsc.runner import metrics

    names = ["time", "joint.force", "joint.forcePeak", "joint.contactOnsetsTotal",
             "slider.acceleration", "slider.accelerationPeak", "rod.deformationEnergy",
             "energy.dissipated", "solver.steps", "crankPin.forcePeak", "rod.stressPeak"]
    rows = [(0.000, 0, 0, 0, 0, 0, 0.0, 0.0, 0, 0, 0),
            (0.001, 900, 6000, 1, 5, 50, 0.2, 1.0, 10, 6500, 9e7),
            (0.002, 800, 950, 2, 4, 40, 0.1, 1.5, 20, 1000, 2e7),
            (0.003, 700, 900, 3, 3, 30, 0.1, 2.5, 30, 980, 1e7)]
    result = np.array(rows, dtype=[(n, float) for n in names])
    everything, window = metrics(result), metrics(result, start=0.0015)
    assert everything["peak_joint_force"] == 6000 and window["peak_joint_force"] == 950
    assert everything["peak_crank_pin_force"] == 6500 and window["peak_crank_pin_force"] == 1000
    assert window["peak_rod_stress"] == 2e7
    assert np.isnan(window["peak_main_bearing_force"])
    assert everything["contact_onsets"] == 3 and window["contact_onsets"] == 2
    assert everything["energy_dissipated"] == 2.5 and window["energy_dissipated"] == 1.5
    assert window["max_deformation_energy"] == 0.1


def half_turn_table(degrees, low, high):
    """The FMU's monotone periodic interpolant of the two-point table (0°, low), (180°, high): its
    slopes vanish at both points (the secants change sign), so on each half turn it is the cubic
    Hermite step low + (3s² − 2s³)(high − low), s the fraction of the half turn."""
    a = np.mod(degrees, 360.0)
    s = np.where(a < 180.0, a, a - 180.0) / 180.0
    step = 3 * s ** 2 - 2 * s ** 3
    return np.where(a < 180.0, low + step * (high - low), high + step * (low - high))


def test_a_study_with_load_tables_and_an_input_series(tmp_path):
    """A study sweeps two load tables (files next to the study, shipped to the workers in the
    FMU's resources) under an input series: slider.force ramps from 0 to −200 N and the crank is
    driven by drive.torque. On a LocalCluster worker each case's slider.appliedForce is, at every
    output point, the table at crank.angle (the interpolant computed here independently) plus the
    ramp's value where the interval began (an input is held over the interval), equal to the
    serial run bit for bit; the file's content names the case, and the report labels the tables by
    name."""
    (tmp_path / "gas.csv").write_text("angle,force\n0,-100\n180,-500\n")
    (tmp_path / "light.csv").write_text("0,-20\n180,-60\n")
    body = """stop_time = 0.004
output_interval = 1e-4
series = ["slider.appliedForce", "crank.angle"]
[fixed]
"rod.formulation" = "rigid"
"drive.mode" = "torque"
[grid]
"slider.forceTable" = ["gas.csv", "light.csv"]
[inputs]
time = [0.0, 0.004]
"slider.force" = [0.0, -200.0]
"drive.torque" = [1.0, 1.0]
"""
    study = study_mod.load(write_study(tmp_path, body))
    assert len(study.cases) == 2 and len(study.files) == 2
    assert run(study, tmp_path / "out", workers=1, progress=False) == 2
    import pyarrow.parquet as pq
    tables = {"gas.csv": (-100.0, -500.0), "light.csv": (-20.0, -60.0)}
    for case_id, (status, message, _, series) in serial(study).items():
        assert status == "ok", message
        kept = pq.read_table(tmp_path / "out" / "series" / f"case={case_id}").to_pydict()
        assert kept["slider.appliedForce"] == list(series["slider.appliedForce"])
        name = next(v for v in study.cases if study.case_id(v) == case_id)["slider.forceTable"]
        low, high = tables[name.rsplit("/", 1)[-1]]
        ramp = -200.0 * np.maximum(series["time"] - 1e-4, 0.0) / 0.004
        expected = ramp + half_turn_table(np.degrees(series["crank.angle"]), low, high)
        assert np.max(np.abs(series["slider.appliedForce"] - expected)) < 1e-9 * 700
    # Another content under the same file name is another case.
    (tmp_path / "gas.csv").write_text("angle,force\n0,-100\n180,-501\n")
    changed = study_mod.load(study.path)
    assert changed.case_id(changed.cases[0]) != study.case_id(study.cases[0])
    assert changed.case_id(changed.cases[1]) == study.case_id(study.cases[1])
    from fsc.sweep import report
    report(study, tmp_path / "out")
    assert (tmp_path / "out" / "peak_joint_force.png").is_file()
