"""Fixtures: the packaged FMU (built by `make fmu` before pytest runs), unpacked once per session."""

import fmpy
import pytest

from pistonslap.fmu import fmu_path


@pytest.fixture(scope="session")
def fmu_file():
    path = fmu_path()
    # a missing FMU is a failure, not a skip: CI must never pass without testing it
    assert path.is_file(), f"{path} is missing: run `make fmu` (or `make test`) first"
    return str(path)


@pytest.fixture(scope="session")
def unpacked_fmu(fmu_file, tmp_path_factory):
    """(unzip directory, model description), shared by the call-by-call tests."""
    unzipdir = fmpy.extract(fmu_file, unzipdir=tmp_path_factory.mktemp("fmu"))
    return str(unzipdir), fmpy.read_model_description(fmu_file)
