"""Random parameter sets through the FMU keep its promises (a fixed-seed sample of
fsc.parameter_space's study, small enough for CI), and the study's checks can fail."""
from fsc import parameter_space as ps


def test_a_fixed_seed_sample_keeps_every_promise(fmu):
    md = ps.read_model_description(fmu)
    records = ps.run_all(ps.sample(8, 8, 11, md), fmu, jobs=2, timeout=300, progress=False)
    assert len(records) == 16
    assert [(r["label"], r["violations"]) for r in records if r["violations"]] == []
    assert {r["outcome"] for r in records} <= {"rejected", "stopped", "ran"}
    names = [v.name for v in md.modelVariables]
    for r in records:
        if r["outcome"] != "ran":
            assert any(name in r["message"] for name in names), r
    assert sum(r["outcome"] == "ran" for r in records) >= 8


def test_the_checks_see_a_silent_domain_exit_and_a_drifting_balance():
    p = {"crank.length": 0.05, "rod.length": 0.12, "joint.clearance": 5e-4,
         "joint.journalRadius": 9.5e-3}
    row = {"slider.position": 0.15, "joint.penetration": 1e-3, "rod.midspanDeflection": 0.0,
           "crank.speed": 100.0}
    violations = []
    ps.check_row(row, p, 3, "", 1e-4, violations)
    assert violations == ["t = 0.0001 s: penetration out of bounds without a warning"]
    violations = []
    ps.check_row(row, p, 3, "the model left its domain: joint penetration 1e-3 m", 1e-4, violations)
    assert violations == []
    ps.check_row(dict(row, **{"crank.speed": float("nan")}), p, 3, "", 1e-4, violations)
    assert "non-finite" in violations[0]

    def energies(kinetic, drive):
        return dict({k: 0.0 for k in ps.BALANCE}, **{"energy.kinetic": kinetic,
                                                      "energy.driveWork": drive})
    closed = [energies(10.0, 0.0), energies(12.0, 2.0), energies(11.0, 1.0)]
    violations = []
    ps.check_balance(closed, 1e-3, violations)
    assert violations == []
    ps.check_balance(closed + [energies(12.0, 1.0)], 1e-3, violations)
    assert violations and "energy balance" in violations[0]

