"""The FMI 3.0 FMUs through fmpy's FMI 3 master: valid, bit-identical to their FMI 2 twins at the
DefaultExperiment and in the motor-crank system, and, with early return allowed (and event mode),
returning at the slider-crank's contact onsets without changing what the run computes."""
import re
import zipfile
from pathlib import Path

import numpy as np
import pytest
from fmpy import read_model_description, simulate_fmu
from fmpy.validation import validate_fmu

MODELS = ["FlexibleSliderCrank", "DcMotor", "LubricationCircuit"]


def fmi2_fmu(root, model):
    return str(root / "target" / "fmu" / f"{model}.fmu")


def fmi3_fmu(root, model):
    return str(root / "target" / "fmu" / "fmi3" / f"{model}.fmu")


@pytest.mark.parametrize("model", MODELS)
def test_fmi3_fmus_are_valid(root, model):
    """fmpy's validation (schema and rules) reports nothing."""
    assert validate_fmu(fmi3_fmu(root, model)) == []


@pytest.mark.parametrize("model", MODELS)
def test_fmi3_declares_its_capabilities(root, model):
    """Co-simulation only; early return, event mode and intermediate update where the model has
    events and internal steps worth reading (the slider-crank); the same variables as FMI 2, the
    switches as Enumerations, the binary in FMI 3's platform folder, and an instantiation token of its
    own (its description's hash, not the FMI 2 GUID)."""
    md3 = read_model_description(fmi3_fmu(root, model))
    md2 = read_model_description(fmi2_fmu(root, model))
    assert md3.fmiVersion == "3.0" and md3.modelExchange is None
    cs = md3.coSimulation
    crank = model == "FlexibleSliderCrank"
    assert cs.mightReturnEarlyFromDoStep == crank and cs.hasEventMode == crank
    assert cs.providesIntermediateUpdate == crank
    assert cs.canReturnEarlyAfterIntermediateUpdate == crank
    assert cs.canGetAndSetFMUstate and cs.canSerializeFMUstate
    assert md3.instantiationToken != md2.guid
    assert re.fullmatch(r"\{[0-9a-f]{8}(-[0-9a-f]{4}){3}-[0-9a-f]{12}\}", md3.instantiationToken)
    (time,) = [v for v in md3.modelVariables if v.causality == "independent"]
    assert time.name == "time" and time.type == "Float64"
    # (the structural parameter and the arrays are FMI 3's own: tests/test_fmi3_arrays.py)
    variables3 = [
        v
        for v in md3.modelVariables
        if v.causality not in ("independent", "structuralParameter") and not v.dimensions
        and v.derivative is None
    ]
    assert [v.name for v in variables3] == [v.name for v in md2.modelVariables]
    # FMI 3 has no fmi3SetInputDerivatives: the input derivatives are inputs of their own, each
    # naming the variable it derives
    derivatives = {v.name: v for v in md3.modelVariables if v.derivative is not None}
    inputs = [v for v in md2.modelVariables if v.causality == "input"]
    assert md2.coSimulation.canInterpolateInputs
    assert len(derivatives) == 2 * len(inputs)
    for u in inputs:
        first, second = derivatives[f"der({u.name})"], derivatives[f"der({u.name},2)"]
        assert first.causality == second.causality == "input" and first.start == "0"
        assert first.derivative.name == u.name and second.derivative is first
    # The outputs' dependencies are FMI 2's, by value reference, and der(drive.speed) where an
    # output reads that input's rate
    dependencies2 = {u.variable.name: [d.name for d in u.dependencies] for u in md2.outputs}
    outputs3 = [u for u in md3.outputs if not u.variable.dimensions]
    assert [u.variable.name for u in outputs3] == list(dependencies2)
    rate_readers = 0
    for u in outputs3:
        expected = dependencies2[u.variable.name]
        if crank and "drive.speed" in expected:
            expected = expected + ["der(drive.speed)"]
            rate_readers += 1
        assert [d.name for d in u.dependencies] == expected, u.variable.name
    assert (rate_readers > 0) == crank
    for v2, v3 in zip(md2.modelVariables, variables3):
        assert v3.valueReference == v2.valueReference
        expected = {"Real": "Float64", "Integer": "Int32"}.get(v2.type, v2.type)
        if v2.declaredType is not None and v2.type == "Integer":
            expected = "Enumeration"
        assert v3.type == expected, v2.name
    with zipfile.ZipFile(fmi3_fmu(root, model)) as z:
        assert f"binaries/x86_64-linux/{model}.so" in z.namelist()
        xml = z.read("modelDescription.xml").decode()
    # (fmpy reads FMI 2's spelling of this attribute only)
    assert 'providesDirectionalDerivatives="true"' in xml


@pytest.mark.parametrize("model", MODELS)
def test_fmi3_default_experiment_is_bit_identical_to_fmi2(root, model):
    """The DefaultExperiment through fmpy gives the same numbers at every output and every
    communication point in FMI 3 as in FMI 2 (whose outputs are FMI 3's but the arrays)."""
    r2 = simulate_fmu(fmi2_fmu(root, model))
    r3 = simulate_fmu(fmi3_fmu(root, model))
    arrays = [name for name in r3.dtype.names if r3[name].ndim > 1]
    assert arrays == (
        ["rod.section.deflection", "rod.section.axialForce", "rod.section.bendingMoment"]
        if model == "FlexibleSliderCrank"
        else []
    )
    assert r2.dtype.names == tuple(name for name in r3.dtype.names if name not in arrays)
    for name in r2.dtype.names:
        assert np.array_equal(r2[name], r3[name]), name


def test_early_return_at_contact_onsets(root):
    """With early return allowed the slider-crank returns at its contact onsets (more
    communication points than the fixed grid), at the grid points the motion is the same bit for
    bit, and the run ends with the same onset count and the same peaks (within 0.5 %; the peak
    holds of an interval cut at an onset add up to the same maxima)."""
    fmu = fmi3_fmu(root, "FlexibleSliderCrank")
    grid = simulate_fmu(fmu)
    early = simulate_fmu(fmu, early_return_allowed=True)
    onsets = int(early["joint.contactOnsetsTotal"][-1])
    assert onsets > 10
    assert len(early) > len(grid) + onsets // 2
    assert early["joint.contactOnsetsTotal"][-1] == grid["joint.contactOnsetsTotal"][-1]
    on_grid = early[np.isin(early["time"], grid["time"])]
    assert len(on_grid) == len(grid)
    for name in ["crank.angle", "slider.position", "slider.velocity", "joint.force"]:
        assert np.array_equal(on_grid[name], grid[name]), name
    for name in ["joint.forcePeak", "slider.accelerationPeak", "rod.stressPeak"]:
        a, b = np.max(grid[name]), np.max(early[name])
        assert abs(b - a) <= 0.005 * a, (name, a, b)


def test_event_mode_at_contact_onsets(root):
    """fmpy's FMI 3 master with event mode and early return enters Event Mode at every contact
    onset (it records the point before and after); the points after equal those before (the
    onset is settled where it happens), and without the repeats the run is the one with early
    return alone, bit for bit, at every output and array."""
    fmu = fmi3_fmu(root, "FlexibleSliderCrank")
    early = simulate_fmu(fmu, early_return_allowed=True)
    events = simulate_fmu(fmu, early_return_allowed=True, use_event_mode=True)
    onsets = int(early["joint.contactOnsetsTotal"][-1])
    repeated = events["time"][1:] == events["time"][:-1]
    assert np.sum(repeated) == onsets > 10
    first = np.concatenate([[True], ~repeated])
    for name in early.dtype.names:
        assert np.array_equal(events[name][first], early[name]), name
        assert np.array_equal(events[name][1:][repeated], events[name][:-1][repeated]), name


def test_intermediate_update_reads_every_internal_step(root):
    """fmpy's FMU3Slave with an intermediate-update callback: the callback reads the joint force
    and the rod stress after every internal step (thousands in the DefaultExperiment's 24 ms, 241
    communication points); their largest values lie within 1 % below the peak holds (which also
    sample inside the steps); the outputs and peaks at every communication point are those of the
    run without callback, bit for bit."""
    from fmpy import extract
    from fmpy.fmi3 import FMU3Slave

    path = fmi3_fmu(root, "FlexibleSliderCrank")
    md = read_model_description(path)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    outputs = [v.valueReference for v in md.modelVariables
               if v.causality == "output" and v.type == "Float64" and not v.dimensions]
    unzipped = extract(path)

    def run(with_update):
        slave = FMU3Slave(guid=md.guid, unzipDirectory=unzipped,
                          modelIdentifier="FlexibleSliderCrank", instanceName="update")
        reads = []

        def update(environment, time, set_requested, get_allowed, finished, can_return,
                   early_return_requested, early_return_time):
            assert get_allowed and not set_requested
            reads.append([time] + slave.getFloat64([vr["joint.force"], vr["rod.stress"]]))

        slave.instantiate(intermediateUpdate=update if with_update else None)
        slave.enterInitializationMode(startTime=0.0)
        slave.exitInitializationMode()
        points, t = [], 0.0
        for k in range(1, 241):
            slave.doStep(t, k * 1e-4 - t)
            t = k * 1e-4
            points.append(slave.getFloat64(outputs))
        slave.terminate()
        slave.freeInstance()
        return np.array(reads), np.array(points)

    reads, points = run(True)
    _, plain = run(False)
    assert np.array_equal(points, plain)
    assert len(reads) > 10 * 240
    assert np.all(np.diff(reads[:, 0]) > 0)
    for column, peak in [(1, "joint.forcePeak"), (2, "rod.stressPeak")]:
        held = plain[:, outputs.index(vr[peak])].max()
        assert 0.99 * held <= reads[:, column].max() <= held, peak


def test_terminals_connect_the_motor_to_the_crank(root):
    """Both FMI 3 FMUs carry terminalsAndIcons.xml, valid against the FMI 3 schema, every member a
    variable of the FMU; the crank's flange and the motor's shaft share the members w and tau,
    each an output on one side and an input on the other (what the motor-crank system connects);
    the slider's flange groups its position, velocity and force."""
    from lxml import etree
    import fmpy

    schema = etree.XMLSchema(file=str(Path(fmpy.__file__).parent / "schema" / "fmi3"
                                      / "fmi3TerminalsAndIcons.xsd"))
    members = {}
    for model in ["FlexibleSliderCrank", "DcMotor"]:
        with zipfile.ZipFile(fmi3_fmu(root, model)) as z:
            doc = etree.fromstring(z.read("terminalsAndIcons/terminalsAndIcons.xml"))
        assert schema.validate(doc), schema.error_log
        causality = {v.name: v.causality for v in read_model_description(fmi3_fmu(root, model)).modelVariables}
        for terminal in doc.iter("Terminal"):
            assert terminal.get("matchingRule") == "bus"
            members[terminal.get("name")] = {
                m.get("memberName"): causality[m.get("variableName")]
                for m in terminal.iter("TerminalMemberVariable")}
    crank, shaft = members["crankFlange"], members["shaftFlange"]
    assert set(shaft) == {"w", "tau"} <= set(crank)
    for name in shaft:
        assert {crank[name], shaft[name]} == {"input", "output"}, name
    assert set(members["sliderFlange"]) == {"s", "v", "f"}


def test_motor_has_no_event_mode(root):
    """The motor has no events: a master that asks for event mode is refused at instantiation,
    with the reason."""
    from fmpy import extract
    from fmpy.fmi3 import FMU3Slave

    fmu = fmi3_fmu(root, "DcMotor")
    md = read_model_description(fmu)
    messages = []
    slave = FMU3Slave(guid=md.guid, unzipDirectory=extract(fmu),
                      modelIdentifier="DcMotor", instanceName="motor")
    with pytest.raises(Exception):
        slave.instantiate(eventModeUsed=True,
                          logMessage=lambda env, status, category, m: messages.append(m.decode()))
    assert "hasEventMode = false" in messages[-1]


def test_motor_crank_system_in_fmi3_equals_fmi2():
    """The motor-crank system through the package's own master (a Jacobi loop, held inputs) gives
    the same speeds and torques bit for bit with the FMI 3.0 FMUs as with the FMI 2.0 ones."""
    from fsc import system

    outputs = ("crank.speed", "shaft.torque", "joint.force")
    fmi2 = system.run(1e-4, 0.01, outputs=outputs)
    fmi3 = system.run(1e-4, 0.01, outputs=outputs, fmi3=True)
    assert len(fmi3) == 100
    assert fmi3 == fmi2
    with pytest.raises(ValueError, match="no input derivatives"):
        system.run(1e-4, 1e-3, scheme="order 1", fmi3=True)
