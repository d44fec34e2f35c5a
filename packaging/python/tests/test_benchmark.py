"""Tests of the whole-FMU benchmark's real-time cases (`python -m fsc.benchmark FMU --real-time`)."""
from fsc import benchmark


def test_the_real_time_cases_are_the_four_of_the_figures():
    """The undamped, 1 %- and 2 %-damped 4-mode rod on the dry joint, and the lubricated one."""
    cases = [benchmark.CASES[i] for i in benchmark.REAL_TIME]
    assert [(joint, values) for _, joint, values in cases] == [
        (benchmark.DRY, {}),
        (benchmark.DRY, {"rod.dampingRatio": 0.01}),
        (benchmark.DRY, {"rod.dampingRatio": 0.02}),
        (benchmark.LUBRICATED, {}),
    ]


def test_the_real_time_table_has_a_row_per_case(fmu, capsys, monkeypatch):
    """One round prints the four rows, each with its real-time factor (simulated ÷ wall time) and the
    damped rods taking fewer steps than the undamped one, the time ratio read against the undamped
    rod."""
    monkeypatch.setattr(benchmark, "ROUNDS", 1)
    benchmark.main(fmu, False, {}, None, real_time=True)
    lines = capsys.readouterr().out.strip().splitlines()
    assert "ratio to the undamped rod" in lines[0]
    rows = [[cell.strip() for cell in line.strip("|").split("|")] for line in lines[2:]]
    assert len(rows) == 4
    wall = [float(row[2]) for row in rows]
    factors = [float(row[4]) for row in rows]
    steps = [int(row[5]) for row in rows]
    for w, f in zip(wall, factors):
        # both printed to three decimals
        assert abs(f * w - 0.024) <= 5e-4 * (f + w) + 1e-9
    assert float(rows[0][3]) == 1.0
    assert steps[1] < steps[0] and steps[2] < steps[0]
