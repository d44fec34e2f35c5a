"""Fixtures the tests share: the repository, the packaged FMU (`cargo run --release -p packaging`;
the test command puts the release build's there) and its model description."""
from pathlib import Path

import pytest
from fmpy import read_model_description

ROOT = Path(__file__).resolve().parents[3]


@pytest.fixture(scope="session")
def root() -> Path:
    """The repository's root directory."""
    return ROOT


@pytest.fixture(scope="session")
def fmu() -> str:
    """The packaged FlexibleSliderCrank FMU (this machine's binary)."""
    return str(ROOT / "target" / "fmu" / "FlexibleSliderCrank.fmu")


@pytest.fixture(scope="session")
def model_description(fmu):
    """The FMU's model description, as fmpy reads it."""
    return read_model_description(fmu)


@pytest.fixture(scope="session")
def value_references(model_description) -> dict:
    """Value reference of every variable, by name."""
    return {v.name: v.valueReference for v in model_description.modelVariables}


@pytest.fixture(autouse=True, scope="session")
def packaged_fmus():
    """Points the systems' masters at this clone's packaged FMUs, wherever pytest runs from."""
    from fsc import lube_system, system
    system.FMU_DIR = lube_system.FMU_DIR = ROOT / "target" / "fmu"
