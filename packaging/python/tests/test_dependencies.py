"""The FMU's declared dependencies and directional derivatives against measurement through fmpy:
each output's direct feedthrough from the inputs, each initial unknown's dependencies on parameters
and start values, and fmi2GetDirectionalDerivative against the master's own central differences, 2 ms
into benchmark B in every drive x joint x rod model."""
import numpy as np
import pytest
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave

from fsc import dependencies
from test_fmu import FORMULATIONS, JOINTS


def every_model_at_2ms(fmu):
    """For every drive x joint x rod model, and with every joint lubricated and heated (a heat
    balance): (model, instance) 2 ms into benchmark B (20 steps of 1e-4 s). The caller frees the
    instance."""
    md = read_model_description(fmu)
    unzipdir = extract(fmu)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    heat_balance = (JOINTS["lubricated"], 2)
    joints = [(joint, 1) for joint in JOINTS.values()] + [heat_balance]
    # with a heat balance, every joint lubricated, heated and fed through a hole
    every_joint = ("joint", "crankPin", "mainBearing")
    for drive in (1, 2):
        for joint, thermal in joints:
            for formulation in (FORMULATIONS["rigid"], FORMULATIONS["craigBampton"]):
                s = FMU2Slave(guid=md.guid, unzipDirectory=unzipdir,
                              modelIdentifier=md.coSimulation.modelIdentifier, instanceName="at2ms")
                s.instantiate()
                s.setupExperiment(startTime=0.0)
                s.setInteger([vr["drive.mode"], vr["rod.formulation"]], [drive, formulation])
                for name in every_joint if thermal == 2 else ("joint",):
                    s.setInteger([vr[f"{name}.model"], vr[f"{name}.thermalModel"],
                                  vr[f"{name}.feed"]], [joint, thermal, HOLE if thermal == 2 else 1])
                s.enterInitializationMode()
                s.exitInitializationMode()
                t = 0.0
                for _ in range(20):
                    s.doStep(t, 1e-4)
                    t += 1e-4
                yield (drive, joint, formulation, thermal), s


#: The `<joint>.feed` item of a feed hole.
HOLE = 2


def feedthrough_measured(fmu):
    """(output, input) pairs where setting the input changes the output at once, before a step:
    over every drive x joint x rod model, 2 ms into benchmark B."""
    md = read_model_description(fmu)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    inputs = [v.name for v in md.modelVariables if v.causality == "input"]
    outputs = [v for v in md.modelVariables if v.causality == "output"]
    getters = {"Real": "getReal", "Integer": "getInteger", "Boolean": "getBoolean"}
    pairs = set()
    for model, s in every_model_at_2ms(fmu):
        def read():
            return {o.name: getattr(s, getters[o.type])([o.valueReference])[0] for o in outputs}
        before = read()
        for u in inputs:
            x = s.getReal([vr[u]])[0]
            s.setReal([vr[u]], [1.01 * x + 1.0])
            after = read()
            pairs |= {(o, u) for o in after if after[o] != before[o]}
            s.setReal([vr[u]], [x])
            assert read() == before, (model, u)
        s.terminate()
        s.freeInstance()
    return pairs


PEAKS = {"joint.forcePeak": "joint.force", "slider.accelerationPeak": "slider.acceleration",
         "rod.deformationEnergyPeak": "rod.deformationEnergy", "crankPin.forcePeak": "crankPin.force",
         "mainBearing.forcePeak": "mainBearing.force", "guide.forcePeak": "guide.force",
         "rod.stressPeak": "rod.stress", "rod.stressMaxPeak": "rod.stressMax",
         "rod.stressMinPeak": "rod.stressMin"}
#: Peak-holds of a signed value (its largest or smallest, not its largest magnitude).
SIGNED_PEAKS = {"rod.stressMaxPeak", "rod.stressMinPeak"}


def test_declared_output_dependencies_are_the_measured_ones(fmu):
    """ModelStructure/Outputs declares, for each output, exactly the inputs it reacts to without a
    step (direct feedthrough); the states (crank angle and speed, slider position, ...) list none. A
    peak-hold output declares those of the output whose extreme it holds (a perturbation may leave
    the held value in place)."""
    md = read_model_description(fmu)
    declared = {(u.variable.name, d.name) for u in md.outputs for d in (u.dependencies or [])}
    assert all(u.dependencies is not None for u in md.outputs)
    measured = feedthrough_measured(fmu)
    measured = {(o, u) for o, u in measured if o not in PEAKS} | {
        (peak, u) for peak, held in PEAKS.items() for o, u in measured if o == held}
    assert declared == measured


def test_directional_derivatives_agree_with_central_differences(fmu):
    """fmi2GetDirectionalDerivative (fmpy's getDirectionalDerivative) gives ∂y/∂u of every Real
    output with respect to every input, 2 ms into benchmark B, in every drive x joint x rod
    model: within 1e-6 of the master's own central differences (step 3e-4 max(1, |u|)), beyond
    those differences' round-off 16 eps |y| / h (measured on a line of 41 input values: the rod's
    stresses deviate from their straight line by up to 15 eps |y|, as their bending moment sums
    moments of the pin force and the rod's inertia up to F l, larger than itself; other outputs
    6 eps |y|; the mid-span bending moment's own round-off scales with F l, not |y|); exactly
    zero where no feedthrough is declared. A peak-hold output is compared where the master's
    differences stay on one side of its kink."""
    md = read_model_description(fmu)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    inputs = [v.name for v in md.modelVariables if v.causality == "input"]
    outputs = [v.name for v in md.modelVariables if v.causality == "output" and v.type == "Real"]
    feedthrough = {(u.variable.name, d.name) for u in md.outputs for d in (u.dependencies or [])}
    ov = [vr[o] for o in outputs]
    at = {o: i for i, o in enumerate(outputs)}
    eps = np.finfo(float).eps
    compared = straddled = 0
    for model, s in every_model_at_2ms(fmu):
        y = np.array(s.getReal(ov))
        # The round-off of each output: of its own size, but for the mid-span bending moment, a
        # sum of moments of the pin force and of the rod's inertia much larger than itself (up to
        # F l: measured, 2.8e-13 N m on a moment of 0.96 N m with F l about 2 kN m).
        scale = np.abs(y)
        scale[at["rod.bendingMomentMidspan"]] = max(
            scale[at["rod.bendingMomentMidspan"]],
            abs(y[at["crankPin.force"]]) * s.getReal([vr["rod.length"]])[0])
        for u in inputs:
            derivative = np.array(s.getDirectionalDerivative(ov, [vr[u]], [1.0]))
            # Linear in the seed.
            assert np.array_equal(
                np.array(s.getDirectionalDerivative(ov, [vr[u]], [-2.0])), -2.0 * derivative)
            x = s.getReal([vr[u]])[0]
            h = 3e-4 * max(1.0, abs(x))
            s.setReal([vr[u]], [x + h])
            plus = np.array(s.getReal(ov))
            s.setReal([vr[u]], [x - h])
            minus = np.array(s.getReal(ov))
            s.setReal([vr[u]], [x])
            difference = (plus - minus) / (2.0 * h)
            bound = 1e-6 * np.abs(difference) + 16.0 * eps * scale / h
            for o, d, c, b in zip(outputs, derivative, difference, bound):
                if o in PEAKS:
                    # Differences across a kink of max(held, |value|) average both sides:
                    # compare where the same side and the same sign of the value hold at x - h,
                    # x and x + h.
                    i, k = at[o], at[PEAKS[o]]
                    held = (lambda z: z[k]) if o in SIGNED_PEAKS else (lambda z: abs(z[k]))
                    sides = {(bool(z[i] == held(z)), np.sign(z[k])) for z in (minus, y, plus)}
                    if len(sides) > 1:
                        straddled += 1
                        continue
                if (o, u) in feedthrough:
                    assert abs(d - c) <= b, (model, o, u, d, c)
                    compared += 1
                else:
                    assert d == 0.0 and c == 0.0, (model, o, u, d, c)
        s.terminate()
        with pytest.raises(Exception):  # a parameter is no input: an error
            s.getDirectionalDerivative(ov, [vr["crank.length"]], [1.0])
        s.freeInstance()
    assert compared > 500 and straddled < compared / 10, (compared, straddled)


def start_configurations(n=160, seed=7):
    """Start values covering every drive, joint (with and without a heat balance), rod and start
    model (each joint's switches drawn independently, a joint with a heat balance fed through a
    hole), with gravity, friction, material damping and the inputs switched on at random; half keep crank.initialSpeed at its start value, so that the
    crank starts at drive.speed; a third load the slider with a table over the crank angle. Six
    more put each joint lubricated by the short film at either edge of its range, one starts the
    crank backwards of zero in a 720° load cycle, two start every joint dry and settled at a crank
    speed of 0.05 rad/s, where the journals slip between the friction law's regularisation speeds,
    and four make every joint rough, lubricated and heated."""
    rng = np.random.default_rng(seed)

    def pick(values):
        return values[rng.integers(len(values))]

    configurations = []
    for i in range(n):
        c = {"drive.mode": pick([1, 2]), "rod.formulation": pick([1, 2, 3]),
             "rod.boundary": pick([1, 2]), "rod.initialState": pick([1, 2]),
             "rod.nElements": pick([2, 4, 8]), "rod.nModes": pick([0, 1, 2, 4]),
             "rod.quadrature": pick([1, 2]), "crank.initialAngle": rng.uniform(0.0, 6.28),
             "drive.speed": rng.uniform(200.0, 600.0), "drive.torque": pick([0.0, 5.0]),
             "slider.force": pick([0.0, -100.0])}
        if i % 2:
            c["crank.initialSpeed"] = rng.uniform(200.0, 600.0)
        for joint in ("joint", "crankPin", "mainBearing"):
            c |= {f"{joint}.model": pick([1, 2, 3]), f"{joint}.initialState": pick([1, 2]),
                  f"{joint}.contactLaw": pick([1, 2, 3]), f"{joint}.friction": pick([0.0, 0.1]),
                  f"{joint}.thermalModel": pick([1, 2])}
            # a joint with a heat balance is fed through a hole: its settled film temperature
            # then reads the supply pressure as it reads the supply temperature
            c[f"{joint}.feed"] = HOLE if c[f"{joint}.thermalModel"] == 2 else 1
        if rng.uniform() < 0.7:
            c |= {"gravity": 9.81, "gravityAngle": rng.uniform(0.0, 6.0)}
        if rng.uniform() < 0.5:
            c["rod.stiffnessDamping"] = 1e-6
        if i % 3 == 0:
            c["slider.forceTable"] = str(dependencies.TABLE)
        configurations.append({k: v.item() if hasattr(v, "item") else v for k, v in c.items()})
    radius = 0.0095  # journalRadius: L/D = 0.5 at a bearing length of 2 · 0.5 · radius
    for joint in ("joint", "crankPin", "mainBearing"):
        for length in (0.995 * radius, 1.005 * radius):
            configurations.append({f"{joint}.model": 3, f"{joint}.filmModel": 1,
                                   f"{joint}.bearingLength": length})
    # a crank starting backwards of zero in a 720° load cycle: its angle within the cycle depends
    # on the table and its period
    configurations.append({"crank.initialAngle": -1.0, "slider.forceTable": str(dependencies.TABLE),
                           "slider.forceTablePeriod": 720, "joint.model": 2, "crankPin.model": 3,
                           "mainBearing.model": 2})
    for angle in (0.7, 2.0):
        slow = {"drive.speed": 0.05, "crank.initialAngle": angle, "gravity": 9.81}
        for joint in ("joint", "crankPin", "mainBearing"):
            slow |= {f"{joint}.model": 2, f"{joint}.friction": 0.1, f"{joint}.initialState": 2}
        configurations.append(slow)
    # rough, fed joints with a heat balance: every joint lubricated in a 20 µm clearance on 1 µm
    # roughness (the asperities touch), fed through a hole, its journal settled, its film
    # temperature settled or at the supply, in either drive
    for drive, thermal_start in ((1, 2), (2, 1), (1, 1), (2, 2)):
        warm = {"drive.mode": drive, "drive.torque": 5.0, "slider.force": -100.0,
                "gravity": 9.81, "oil.supplyTemperature": 330.0}
        for joint in ("joint", "crankPin", "mainBearing"):
            warm |= {f"{joint}.model": 3, f"{joint}.initialState": 2, f"{joint}.clearance": 2e-5,
                     f"{joint}.roughness": 1e-6, f"{joint}.thermalModel": 2, f"{joint}.feed": 2,
                     f"{joint}.thermalStart": thermal_start,
                     f"{joint}.heatTransferCoefficient": 10.0}
        configurations.append(warm)
    return configurations


def test_declared_initial_dependencies_are_the_measured_ones(fmu):
    """ModelStructure/InitialUnknowns declares what each output depends on in initialization mode.
    Perturbing each input and parameter there, over every model: the inputs each output reacts to
    are exactly the declared ones; no output reacts to an undeclared parameter; and the outputs
    with a short list (the crank's prescribed start, the contact stiffness, the warnings, the
    counters, work integrals and dissipated energies, which start at zero) react to every declared
    parameter."""
    measured, n = dependencies.measure(fmu, start_configurations())
    declared = dependencies.declared(fmu)
    assert n >= 150
    assert measured <= declared, sorted(measured - declared)
    md = read_model_description(fmu)
    inputs = {v.name for v in md.modelVariables if v.causality == "input"}
    # A contact flag flips only where a perturbation crosses the contact's threshold: its
    # declared dependencies are those of the penetration it is read from.
    flags = {v.name for v in md.modelVariables if v.type == "Boolean"}
    assert ({p for p in measured if p[1] in inputs} ==
            {p for p in declared if p[1] in inputs and p[0] not in flags})
    parameters = {v.name for v in md.modelVariables if v.causality == "parameter"}
    short = {u for u in {u.variable.name for u in md.initialUnknowns}
             if len({k for w, k in declared if w == u}) < 16}
    assert {"crank.angle", "crank.speed", "joint.contactStiffness", "solver.warnings",
            "solver.steps"} <= short
    assert {p for p in measured if p[0] in short} == {p for p in declared if p[0] in short}
    # Every other output depends on the physical parameters and never on the solver's.
    for u in {u.variable.name for u in md.initialUnknowns} - short - flags:
        reacted = {k for w, k in measured if w == u and k in parameters}
        assert len(reacted) >= 20, (u, sorted(reacted))
        assert not any(k.startswith("solver.") for w, k in declared if w == u)
