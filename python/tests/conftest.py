"""Shared fixtures: small problems and an extracted MotionBenchMaker scene."""

from __future__ import annotations

import tarfile
from pathlib import Path

import pytest

import mit_star

REPOSITORY = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def walls4() -> mit_star.Problem:
    """PDT's dividing walls in R^4 at a coarse resolution (quick tests)."""
    return mit_star.Problem("dividing-walls", 4, resolution=1e-4)


@pytest.fixture(scope="session")
def box_panda(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The `box_panda` MotionBenchMaker scene, extracted from the shipped archive."""
    target = tmp_path_factory.mktemp("mbm")
    archive = REPOSITORY / "robot" / "data" / "panda" / "mbm_problems.tar.bz2"
    with tarfile.open(archive) as tar:
        members = [m for m in tar.getmembers() if m.name.startswith("box_panda/")]
        tar.extractall(target, members=members, filter="data")
    return target / "box_panda"
