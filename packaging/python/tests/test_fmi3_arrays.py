"""The FMI 3.0 slider-crank's rod.section arrays through fmpy: sized by the structural parameter
rod.nSections (set in Configuration Mode), their middle section the scalar mid-span outputs, and
their ends carrying the pin forces."""
import zipfile

import numpy as np
import pytest
from fmpy import extract, read_model_description, simulate_fmu
from fmpy.fmi1 import FMICallException
from fmpy.fmi3 import FMU3Slave

ARRAYS = ["rod.section.deflection", "rod.section.axialForce", "rod.section.bendingMoment"]
SCALARS = [
    "rod.midspanDeflection",
    "rod.axialForceMidspan",
    "rod.bendingMomentMidspan",
    "rod.axialForceCrankPin",
    "rod.axialForceSliderPin",
]


@pytest.fixture(scope="module")
def fmu(root):
    return str(root / "target" / "fmu" / "fmi3" / "FlexibleSliderCrank.fmu")


def run(fmu, **start_values):
    return simulate_fmu(fmu, start_values=start_values, output=ARRAYS + SCALARS)


def test_the_arrays_are_sized_by_a_structural_parameter(fmu):
    """rod.nSections is a UInt64 structural parameter; each rod.section array has one
    <Dimension> that names it, so fmpy sizes it from its start value."""
    md = read_model_description(fmu)
    by_name = {v.name: v for v in md.modelVariables}
    n = by_name["rod.nSections"]
    assert (n.type, n.causality, n.variability) == ("UInt64", "structuralParameter", "fixed")
    assert n.start == "11"
    with zipfile.ZipFile(fmu) as z:
        xml = z.read("modelDescription.xml").decode()
    assert 'name="rod.nSections"' in xml and 'start="11" min="2" max="1001"' in xml
    for name in ARRAYS + ["rod.section.position"]:
        v = by_name[name]
        assert v.type == "Float64"
        assert [d.valueReference for d in v.dimensions] == [n.valueReference], name
        assert v.shape == (11,), name
    assert by_name["rod.section.position"].causality == "calculatedParameter"
    assert all(by_name[name].causality == "output" for name in ARRAYS)
    outputs = {u.variable.name for u in md.outputs}
    assert set(ARRAYS) <= outputs


def test_the_middle_section_has_the_midspan_outputs(fmu):
    """Over the DefaultExperiment's impacts, the middle of 11 sections has the mid-span
    deflection, axial force and bending moment of the scalar outputs (the same recovery, to
    round-off), and the deflection from the chord is 0 at both pins."""
    r = run(fmu)
    for array, scalar in zip(ARRAYS, SCALARS):
        middle, value = r[array][:, 5], r[scalar]
        scale = np.abs(value).max()
        assert scale > 0, scalar
        assert np.abs(middle - value).max() <= 1e-12 * scale, array
    ends = r["rod.section.deflection"][:, [0, -1]]
    assert np.all(ends == 0.0)


def test_the_rigid_rods_sections_are_in_equilibrium(fmu):
    """The rigid rod's section forces come from the equilibrium of its parts under the pin
    forces, its weight and its inertia: the moment vanishes at both pins (the pins carry none),
    the axial force at the ends is the shank's at each pin, with and without eye masses."""
    for eyes in [{}, {"rod.crankEndMass": 0.1, "rod.sliderEndMass": 0.05}]:
        r = run(fmu, **{"rod.formulation": 1}, **eyes)
        moment, axial = r["rod.section.bendingMoment"], r["rod.section.axialForce"]
        m_max, n_max = np.abs(moment).max(), np.abs(axial).max()
        assert m_max > 1.0 and n_max > 100.0
        assert np.abs(moment[:, [0, -1]]).max() <= 1e-12 * m_max, eyes
        assert np.abs(axial[:, 0] - r["rod.axialForceCrankPin"]).max() <= 1e-12 * n_max
        assert np.abs(axial[:, -1] - r["rod.axialForceSliderPin"]).max() <= 1e-12 * n_max
        assert np.all(r["rod.section.deflection"] == 0.0)


@pytest.mark.parametrize(
    "start_values",
    [
        {},
        {"rod.formulation": 2},
        {"rod.nModes": 2},
        {"rod.crankEndMass": 0.1, "rod.sliderEndMass": 0.05, "gravity": 9.81},
        {"crankPin.model": 3, "joint.model": 3},
        {"rod.formulation": 1, "crankPin.model": 3},
    ],
    ids=["4 modes", "full rod", "2 modes", "eyes and gravity", "lubricated pins", "rigid rod, lubricated crank pin"],
)
def test_the_rods_ends_carry_the_pin_forces(fmu, start_values):
    """One number per force: through the DefaultExperiment's impacts and free flights, whatever
    the rod (modes, full, rigid, with eye masses), its end sections carry the pin forces, the axial force at each
    end the pin's (rod.axialForceCrankPin, rod.axialForceSliderPin) to round-off; the moment at
    the slider end the rod-slider joint's friction moment (joint.frictionTorque), at the crank end
    the crank pin's friction moment less its force's lever about the eye's centre, e x F (0 for a
    pin without friction). The resultants come from the equilibrium of the rod's parts under its
    inertia, which the reduced rod carries exactly (measured: 1e-13 N m; the rigid rod 1e-5 N m)."""
    r = simulate_fmu(fmu, start_values=start_values, output=ARRAYS + SCALARS + [
        "joint.frictionTorque", "crankPin.frictionTorque", "crankPin.forceX", "crankPin.forceY",
        "crankPin.eccentricityX", "crankPin.eccentricityY", "joint.force"])
    moment, axial = r["rod.section.bendingMoment"], r["rod.section.axialForce"]
    largest = np.abs(r["joint.force"]).max()
    assert largest > 1e3
    pins = np.stack([r["rod.axialForceCrankPin"], r["rod.axialForceSliderPin"]], axis=1)
    assert np.abs(axial[:, [0, -1]] - pins).max() <= 1e-9 * largest
    lever = (r["crankPin.eccentricityX"] * r["crankPin.forceY"]
             - r["crankPin.eccentricityY"] * r["crankPin.forceX"])
    ends = np.stack([r["crankPin.frictionTorque"] - lever, r["joint.frictionTorque"]], axis=1)
    assert np.abs(moment[:, [0, -1]] - ends).max() <= 1e-6 * largest * 0.12
    assert np.all(r["rod.section.deflection"][:, [0, -1]] == 0.0)


def test_configuration_mode_sets_the_number_of_sections(fmu):
    """A master that enters Configuration Mode sets rod.nSections (only there, only inside its
    range) and reads arrays of that size; the DC motor has no structural parameters and refuses
    Configuration Mode with the reason."""
    md = read_model_description(fmu)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    messages = []

    def logger(environment, status, category, message):
        messages.append(message.decode())

    slave = FMU3Slave(
        guid=md.guid,
        unzipDirectory=extract(fmu),
        modelIdentifier=md.coSimulation.modelIdentifier,
        instanceName="sections",
    )
    slave.instantiate(logMessage=logger)
    slave.enterConfigurationMode()
    with pytest.raises(FMICallException):
        slave.setUInt64([vr["rod.nSections"]], [1002])
    assert "rod.nSections = 1002 is outside the allowed range [2, 1001]" in messages[-1]
    slave.reset()
    slave.enterConfigurationMode()
    slave.setUInt64([vr["rod.nSections"]], [5])
    slave.exitConfigurationMode()
    slave.enterInitializationMode(startTime=0.0)
    slave.exitInitializationMode()
    for k in range(10):
        slave.doStep(k * 1e-4, 1e-4)
    assert slave.getUInt64([vr["rod.nSections"]]) == [5]
    length = slave.getFloat64([vr["rod.length"]])[0]
    positions = slave.getFloat64([vr["rod.section.position"]], 5)
    assert positions == [k * length / 4 for k in range(5)]
    moments = slave.getFloat64([vr["rod.section.bendingMoment"]], 5)
    midspan = slave.getFloat64([vr["rod.bendingMomentMidspan"]])[0]
    assert abs(moments[2] - midspan) <= 1e-12 * abs(midspan) and midspan != 0.0
    slave.terminate()
    slave.freeInstance()


def test_the_motor_has_no_configuration_mode(root):
    fmu = str(root / "target" / "fmu" / "fmi3" / "DcMotor.fmu")
    md = read_model_description(fmu)
    messages = []
    slave = FMU3Slave(
        guid=md.guid,
        unzipDirectory=extract(fmu),
        modelIdentifier=md.coSimulation.modelIdentifier,
        instanceName="motor",
    )
    slave.instantiate(logMessage=lambda env, status, category, m: messages.append(m.decode()))
    with pytest.raises(FMICallException):
        slave.enterConfigurationMode()
    assert "the FMU has no structural parameters" in messages[-1]
    slave.freeInstance()
