"""Compatibility information of the FMUs, written by the packaging step: the FMI cross-check
folders under target/fmu/compatibility/ and the FMI-LS-REF files inside each FMU, checked against
a fresh fmpy run."""
import zipfile
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from fmpy import simulate_fmu
from fmpy.cross_check.validate_vendor_repo import validate_test_fmu
from fmpy.util import read_csv, read_ref_opt_file
from fmpy.validation import validate_fmu

ROOT = Path(__file__).resolve().parents[3]
FMUS = ROOT / "target" / "fmu"
MODELS = ["FlexibleSliderCrank", "DcMotor", "LubricationCircuit"]
EXTRA = "extra/org.fmi-standard.fmi-ls-ref"
LS = "{http://fmi-standard.org/fmi-ls-manifest}"


def cross_check_folder(model):
    folders = list((FMUS / "compatibility" / "2.0" / "cs" / "linux64").glob(f"*/*/{model}"))
    assert len(folders) == 1, folders
    return folders[0]


@pytest.mark.parametrize("model", MODELS)
def test_cross_check_folder_passes_fmpy_validation(model):
    folder = cross_check_folder(model)
    assert validate_test_fmu(str(folder)) == []
    assert (folder / f"{model}.fmu").read_bytes() == (FMUS / f"{model}.fmu").read_bytes()
    assert (folder / "README.md").read_text().startswith(f"{model}: reference results")
    assert validate_fmu(str(folder / f"{model}.fmu")) == []


@pytest.mark.parametrize("model", MODELS)
def test_a_fresh_fmpy_run_reproduces_the_reference_results_bit_for_bit(model):
    """fmpy's simulate_fmu with the settings of <model>_ref.opt and the inputs of <model>_in.csv
    gives every output of <model>_ref.csv at every communication point, to the bit."""
    folder = cross_check_folder(model)
    options = read_ref_opt_file(str(folder / f"{model}_ref.opt"))
    reference = read_csv(str(folder / f"{model}_ref.csv"))
    inputs = folder / f"{model}_in.csv"
    result = simulate_fmu(str(folder / f"{model}.fmu"), start_time=options["StartTime"],
                          stop_time=options["StopTime"], output_interval=options["StepSize"],
                          relative_tolerance=options["RelTol"],
                          input=read_csv(str(inputs)) if inputs.exists() else None,
                          output=list(reference.dtype.names[1:]))
    points = round((options["StopTime"] - options["StartTime"]) / options["StepSize"]) + 1
    assert len(result) == len(reference) == points
    for name in reference.dtype.names:
        assert np.array_equal(result[name], reference[name]), name
    # Every Real output is in the reference, and the run moves.
    assert len(reference.dtype.names) > (40 if model == "FlexibleSliderCrank" else 5)
    moving = {"FlexibleSliderCrank": "crank.angle", "DcMotor": "shaft.torque",
              "LubricationCircuit": "sump.temperature"}[model]
    assert np.ptp(reference[moving]) > 0


@pytest.mark.parametrize("model", MODELS)
def test_the_fmu_carries_its_references_with_an_fmi_ls_ref_manifest(model):
    folder = cross_check_folder(model)
    with zipfile.ZipFile(FMUS / f"{model}.fmu") as fmu:
        names = set(fmu.namelist())
        manifest = ET.fromstring(fmu.read(f"{EXTRA}/fmi-ls-manifest.xml"))
        assert manifest.tag == "fmiReferences"
        assert manifest.get(f"{LS}fmi-ls-name") == "org.fmi-standard.fmi-ls-ref"
        assert manifest.get(f"{LS}fmi-ls-version") == "1.0.0-alpha.1"
        related = manifest.findall("Related")
        sources = {r.get("source"): r.get("role") for r in related}
        assert sources[f"{model}_ref.csv"] == "result"
        assert sources[f"{model}_ref.opt"] == "experiment"
        for source in sources:
            assert f"{EXTRA}/{source}" in names
            assert fmu.read(f"{EXTRA}/{source}") == (folder / source).read_bytes()
        assert all(r.get("type") and r.get("description") for r in related)
        assert "documentation/fmi-ls-ref.txt" in names


def test_the_system_reference_is_the_plain_fmpy_masters_run():
    """target/fmu/compatibility/ssp/MotorCrank/: the SSP, its reference results and options; the
    fmpy Jacobi loop of fsc.system (which libcosim matches bit for bit, test_system.py) gives every
    output of both components at every communication point, to the bit."""
    from fsc import system

    folder = FMUS / "compatibility" / "ssp" / "MotorCrank"
    assert (folder / "MotorCrank.ssp").read_bytes() == (FMUS / "MotorCrank.ssp").read_bytes()
    options = read_ref_opt_file(str(folder / "MotorCrank_ref.opt"))
    reference = read_csv(str(folder / "MotorCrank_ref.csv"))
    names = list(reference.dtype.names[1:])
    assert len(reference) == 241 and options["StepSize"] == 1e-4 and options["StopTime"] == 0.024
    assert {n.split(".")[0] for n in names} == {"sliderCrank", "dcMotor"}
    rows = system.run(options["StepSize"], options["StopTime"],
                      outputs=[n.replace(".", "/", 1) for n in names])
    assert len(rows) == 240
    for k, (t, values) in enumerate(rows, start=1):
        assert t == reference["time"][k]
        for n in names:
            assert values[n.replace(".", "/", 1)] == reference[n][k], (t, n)
    assert "Jacobi" in (folder / "README.md").read_text()
