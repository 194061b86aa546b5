"""Interactive 3-D views of paths and trajectories, written as one HTML page."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

import mit_star
from conftest import REPOSITORY

LIMITS = REPOSITORY / "robot" / "data" / "panda" / "joint_limits.yaml"


def _document(page: str) -> dict:
    data = re.search(
        r'<script type="application/json" id="mit-star-view-data">(.*?)</script>', page, re.S
    )
    assert data, "the page embeds its document"
    return json.loads(data.group(1).replace("<\\/", "</"))


def test_an_arm_plan_and_its_trajectory(box_panda, tmp_path) -> None:
    problem = mit_star.Problem.mbm(box_panda, 1)
    result = mit_star.RrtConnect(problem, seed=4).solve(time=1.0)
    assert result.solved
    timed = mit_star.time_parameterise(problem, result.path, joint_limits=LIMITS)
    page = tmp_path / "plan.html"
    size = mit_star.write_view(
        problem, page, result.path, trajectory=timed, title="RRT-Connect on box"
    )
    text = page.read_text()
    assert size == len(text.encode())
    document = _document(text)
    assert document["title"] == "RRT-Connect on box"
    assert document["kind"] == "arm"
    assert [m["label"] for m in document["motions"]] == ["path", "trajectory"]
    assert document["motions"][0]["colliding"] == []
    assert document["motions"][1]["times"][-1] == pytest.approx(timed["duration"])


def test_a_box_world_with_several_paths_marks_collisions(tmp_path) -> None:
    problem = mit_star.Problem("wall-gap", 2)
    through = np.array([problem.start, problem.goals[0]])
    page = tmp_path / "world.html"
    mit_star.write_view(problem, page, paths={"straight": through, "again": through.tolist()})
    document = _document(page.read_text())
    assert document["kind"] == "world2d"
    assert len(document["motions"]) == 2
    assert document["motions"][0]["colliding"], "the straight line crosses the wall"


def test_bad_views_raise() -> None:
    problem = mit_star.Problem("wall-gap", 2)
    with pytest.raises(ValueError, match="html"):
        mit_star.write_view(problem, "plan.png", [[0.0, 0.0], [1.0, 1.0]])
    with pytest.raises(ValueError, match="coordinates"):
        mit_star.write_view(problem, "/tmp/x.html", [[0.0, 0.0, 0.0]])
    with pytest.raises(ValueError, match="dimensions"):
        mit_star.write_view(mit_star.Problem("obstacle-free", 4), "/tmp/x.html")
