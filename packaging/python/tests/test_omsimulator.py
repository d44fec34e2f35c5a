"""The FMI 3.0 FMUs in masters with a scalar FMI 3 import (OMSimulator asks each variable it lists for
one value, an array too, and reads value references in `derivative` and `dependencies` as variable
indices): what such a master loads declares only scalars and no input derivatives, and fmpy's run of
the freshly built FMUs equals OMSimulator's recorded run (`python -m fsc.omsimulator OMSIMULATOR`
records it) at every recorded output and point, to the 12 digits OMSimulator writes."""
import csv
import zipfile
from xml.etree import ElementTree

import pytest
from fmpy import read_model_description, simulate_fmu

from fsc.omsimulator import FMUS, RECORDED, record_path

from conftest import ROOT

FMU_DIR = ROOT / "target" / "fmu"


def description(fmu):
    with zipfile.ZipFile(fmu) as z:
        return ElementTree.fromstring(z.read("modelDescription.xml"))


@pytest.mark.parametrize("model", FMUS)
def test_what_scalar_only_masters_load_declares_only_scalars(model):
    """No array (`Dimension`), no structural parameter and no input derivative (`derivative`) in
    the FMI 3.0 FMUs such a master loads, and every value reference its dependencies name is below
    the number of variables (so that read as an index it names a variable too); the FMI 3.0 FMU
    with them has its own instantiation token, and both differ from the FMI 2.0 GUID (each token is
    its description's hash)."""
    root = description(FMU_DIR / FMUS[model])
    variables = list(root.find("ModelVariables"))
    assert len(variables) > 5
    for v in variables:
        assert v.find("Dimension") is None, v.get("name")
        assert v.get("causality") != "structuralParameter", v.get("name")
        assert v.get("derivative") is None, v.get("name")
    for unknown in root.find("ModelStructure"):
        named = [int(r) for r in (unknown.get("dependencies") or "").split()]
        assert all(r < len(variables) for r in named), unknown.get("valueReference")
    tokens = {read_model_description(str(FMU_DIR / path)).guid
              for path in (f"{model}.fmu", f"fmi3/{model}.fmu", FMUS[model])}
    assert len(tokens) == 3


def test_the_fmi3_fmu_with_arrays_declares_them():
    root = description(FMU_DIR / "fmi3" / "FlexibleSliderCrank.fmu")
    arrays = [v.get("name") for v in root.find("ModelVariables") if v.find("Dimension") is not None]
    assert arrays == ["rod.section.position", "rod.section.deflection", "rod.section.axialForce",
                      "rod.section.bendingMoment"]


@pytest.mark.parametrize("model", RECORDED)
def test_fmpy_runs_the_fmus_as_omsimulator_did(model):
    """fmpy's DefaultExperiment (1e-4 s steps) of the FMU a scalar-only master loads equals the
    OMSimulator record at every recorded output and communication point, printed as OMSimulator
    prints (`%.12g`); measured when recorded: all 118 (slider-crank) and 6 (motor) shared outputs
    at all 241 points equal."""
    with open(record_path(model), newline="") as f:
        rows = list(csv.reader(f))
    names = rows[0][1:]
    assert names == RECORDED[model]
    result = simulate_fmu(str(FMU_DIR / FMUS[model]), stop_time=0.024, output_interval=1e-4,
                          output=names)
    assert len(result) == len(rows) - 1 == 241
    differing = []
    for recorded, row in zip(rows[1:], result):
        assert recorded[0] == "%.12g" % row["time"]
        for name, value in zip(names, recorded[1:]):
            if "%.12g" % float(row[name]) != value:
                differing.append((recorded[0], name, "%.12g" % float(row[name]), value))
    assert differing == [], differing[:5]


def test_the_scalar_slider_crank_is_the_one_with_arrays():
    """The FMU without arrays runs the same model: its outputs equal those of the FMU with arrays
    bit for bit over the DefaultExperiment."""
    runs = [simulate_fmu(str(FMU_DIR / path), output_interval=1e-4)
            for path in ("fmi3/FlexibleSliderCrank.fmu", FMUS["FlexibleSliderCrank"])]
    shared = [n for n in runs[1].dtype.names if n in runs[0].dtype.names]
    assert len(shared) > 100
    for name in shared:
        assert (runs[0][name] == runs[1][name]).all(), name
