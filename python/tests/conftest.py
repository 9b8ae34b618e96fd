"""Fixtures: the packaged FMU (built and copied into the package by `make fmu` before pytest runs), unpacked once
per session."""

import fmpy
import pytest

from pistonslap.fmu import fmu_path


@pytest.fixture(scope="session")
def fmu_file():
    # a missing FMU raises, a failure, not a skip: CI must never pass without testing it
    return str(fmu_path())


@pytest.fixture(scope="session")
def unpacked_fmu(fmu_file, tmp_path_factory):
    """(unzip directory, model description), shared by the call-by-call tests."""
    unzipdir = fmpy.extract(fmu_file, unzipdir=tmp_path_factory.mktemp("fmu"))
    return str(unzipdir), fmpy.read_model_description(fmu_file)
