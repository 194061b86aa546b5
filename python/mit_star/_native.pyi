"""Type stubs of ``mit_star._native``, the Rust half of ``mit_star``."""

from collections.abc import Callable, Sequence
from os import PathLike
from typing import Any, Optional, Union

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]
ArrayLike = npt.ArrayLike
StrPath = Union[str, PathLike[str]]

class PlanningError(Exception):
    """A query the planner refuses (start or goal invalid, out of bounds, of the wrong
    dimension), or a planner or experiment that failed while running."""

class Problem:
    """A planning problem: bounds, a start, goals, a resolution and a built-in checker."""

    def __init__(
        self,
        name: str,
        dim: Optional[int] = None,
        *,
        instance: Optional[int] = None,
        resolution: Optional[float] = None,
        robot: Optional[str] = None,
        group: Optional[str] = None,
        strict_robot: bool = False,
        allow_coarse_step: bool = False,
    ) -> None:
        """A PDT family in ``dim`` dimensions, a TOML problem file or ``mbm:FOLDER``, as
        ``mit-star plan --problem NAME --dim DIM`` resolves it."""
    @staticmethod
    def from_file(
        path: StrPath, *, resolution: Optional[float] = None, allow_coarse_step: bool = False
    ) -> Problem:
        """A TOML problem file."""
    @staticmethod
    def mbm(
        folder: StrPath,
        instance: Optional[int] = None,
        *,
        robot: Optional[str] = None,
        group: Optional[str] = None,
        strict_robot: bool = False,
        resolution: Optional[float] = None,
        cloud: Optional[ArrayLike] = None,
        cloud_files: Optional[Sequence[StrPath]] = None,
        sensor_pose: Optional[Sequence[float]] = None,
        scene_as_cloud: Optional[int] = None,
        point_radius: Optional[float] = None,
        crop_reach: bool = False,
        remove_robot: Optional[float] = None,
        voxel: Optional[float] = None,
        min_distance: Optional[float] = None,
        drop_primitives: bool = False,
        save_cloud: Optional[StrPath] = None,
    ) -> Problem:
        """Problem ``instance`` (1-based) of a MotionBenchMaker folder, for ``robot`` (a shipped
        name or a folder with one URDF and one SRDF; default the Panda), planning its SRDF group
        ``group`` (default every moving joint).

        Point clouds join the scene's obstacles: ``cloud``, an (N, 3) array or list of numbers
        (copied; NaN rows dropped), ``cloud_files`` (PLY, PCD, ``.npy``), ``sensor_pose``
        (x, y, z, roll, pitch, yaw of the sensor in the base frame), ``scene_as_cloud`` (N
        points sampled on each primitive, which the cloud replaces), ``point_radius`` (metres,
        default 0.0025), and the filters ``crop_reach``, ``remove_robot`` (padding, at the
        start), ``voxel``, ``min_distance`` (metres); ``drop_primitives`` plans among the clouds
        alone, ``save_cloud`` writes the filtered cloud (``.ply`` or ``.npy``)."""
    @staticmethod
    def boxes(
        lower: ArrayLike,
        upper: ArrayLike,
        start: ArrayLike,
        goal: ArrayLike,
        *,
        centers: Optional[ArrayLike] = None,
        widths: Optional[ArrayLike] = None,
        free_centers: Optional[ArrayLike] = None,
        free_widths: Optional[ArrayLike] = None,
        resolution: Optional[float] = None,
        name: str = "boxes",
        allow_coarse_step: bool = False,
    ) -> Problem:
        """A box world: obstacles (and anti-obstacles) as (m, d) centres and full widths."""
    @property
    def id(self) -> str: ...
    @property
    def name(self) -> str: ...
    @property
    def dimension(self) -> int: ...
    @property
    def start(self) -> FloatArray: ...
    @property
    def goals(self) -> FloatArray: ...
    @property
    def bounds(self) -> tuple[FloatArray, FloatArray]: ...
    @property
    def resolution(self) -> float: ...
    @property
    def step(self) -> float: ...
    @property
    def optimum(self) -> Optional[float]: ...
    @property
    def is_arm(self) -> bool: ...
    def is_valid(self, state: ArrayLike) -> bool:
        """Whether ``state`` is valid for the problem's built-in checker."""
    def describe(self) -> str:
        """The problem as a TOML problem file (box worlds) or a description (arms)."""
    def with_goal_pose(
        self,
        link: str,
        pose: Optional[Union[str, ArrayLike]] = None,
        *,
        tool: Optional[Sequence[float]] = None,
        position_tolerance: Optional[Union[float, Sequence[float]]] = None,
        orientation_tolerance: Optional[str] = None,
        ik_goals: int = 8,
        ik_initial_goals: int = 1,
    ) -> "Problem":
        """The same arm problem with a pose of ``link`` as its goal (inverse kinematics draws goal configurations while planning)."""

class SolveResult:
    """What ``Planner.solve`` returned."""

    @property
    def solved(self) -> bool: ...
    @property
    def path(self) -> Optional[FloatArray]:
        """The path, shape (n, d), start first; ``None`` without a solution."""
    @property
    def cost(self) -> float:
        """The path's cost; ``inf`` without a solution."""
    @property
    def trace(self) -> list[tuple[float, float]]:
        """``(seconds, cost)`` of every improvement since the planner was built or cleared."""
    @property
    def counters(self) -> dict[str, Any]:
        """The planner's work counters."""
    @property
    def elapsed(self) -> float:
        """Wall-clock seconds of this ``solve`` call."""
    @property
    def planner(self) -> str: ...

class Planner:
    """A planner by configuration name (``mit_star.planners()``) with keyword parameters."""

    def __init__(
        self,
        configuration: str,
        problem: Problem,
        *,
        seed: int = 0,
        validity: Optional[Callable[[FloatArray], bool]] = None,
        vectorized: Optional[Callable[[FloatArray], ArrayLike]] = None,
        batch: int = 64,
        **params: Union[bool, int, float, str, None],
    ) -> None: ...
    def solve(
        self,
        time: Optional[float] = None,
        *,
        first_solution: bool = False,
        iterations: Optional[int] = None,
        cost: Optional[float] = None,
    ) -> SolveResult:
        """Plans until one condition holds; Ctrl-C raises ``KeyboardInterrupt``."""
    def clear(self) -> None:
        """Forgets everything: the next ``solve`` is a fresh run."""
    @property
    def name(self) -> str: ...
    @property
    def configuration(self) -> str: ...
    @property
    def best_cost(self) -> float: ...
    @property
    def trace(self) -> list[tuple[float, float]]: ...
    @property
    def counters(self) -> dict[str, Any]: ...
    @property
    def settings(self) -> list[tuple[str, str]]: ...

class ExperimentResults:
    """Every finished run of an experiment."""

    def records(self, *, paths: bool = False) -> list[dict[str, Any]]:
        """One flat dict per run (pandas: ``DataFrame(results.records())``), with
        ``validation_seconds``, the independent check's own time apart from ``run_time``;
        with ``paths=True`` also ``path`` and, for an arm, ``joints`` (the joint each coordinate
        is, in order) and ``wrapping`` (``True`` for a continuous joint: the short way round)."""
    def table(self, *, paths: bool = False) -> dict[str, list[Any]]:
        """The runs as a dict of columns (pandas: ``DataFrame(results.table())``)."""
    def kpi_markdown(self) -> str:
        """The paper's KPI table as Markdown."""
    @property
    def name(self) -> str: ...
    @property
    def planners(self) -> list[str]: ...
    @property
    def instances(self) -> list[str]: ...
    @property
    def run_count(self) -> int: ...
    @property
    def total_time(self) -> float: ...
    @property
    def interrupted(self) -> bool: ...

__version__: str

def planners() -> list[str]:
    """The configuration names, MIT* first."""

def planner_parameters(name: str) -> list[tuple[str, str]]:
    """The parameters configuration ``name`` reads, with their defaults as text."""

def problem_families() -> list[tuple[str, str]]:
    """The built-in problem families as ``(name, description)``."""

def robots() -> list[str]:
    """The shipped robots."""

def experiments() -> list[tuple[str, str]]:
    """The shipped experiments as ``(name, summary)``."""

def run_experiment(
    experiment: str,
    *,
    runs: Optional[int] = None,
    seed: Optional[int] = None,
    threads: int = 1,
    output: Optional[StrPath] = None,
    plots: bool = False,
    **params: Union[bool, int, float, str, None],
) -> ExperimentResults:
    """Runs a shipped experiment or an experiment file."""

def read_results(folder: StrPath) -> ExperimentResults:
    """The runs of a results folder written by ``mit-star bench`` or ``run_experiment``."""

def time_parameterise(
    problem: Problem,
    path: ArrayLike,
    *,
    corners: str = "blend",
    joint_limits: Optional[StrPath] = None,
    max_acceleration: Optional[float] = None,
    velocity_scaling: float = 1.0,
    acceleration_scaling: float = 1.0,
    sample_period: Optional[float] = None,
) -> dict[str, Any]:
    """``path`` of an arm problem timed under the robot's limits: ``time``, ``position``,
    ``velocity``, ``acceleration`` arrays, ``joints``, ``duration``, ``corners``."""

def write_view(
    problem: Problem,
    file: StrPath,
    path: Optional[ArrayLike] = None,
    *,
    paths: Optional[dict[str, ArrayLike]] = None,
    trajectory: Optional[dict[str, Any]] = None,
    title: Optional[str] = None,
) -> int:
    """An interactive 3-D view of ``problem`` with ``path``, ``paths`` (label to path) and a
    ``trajectory`` from ``time_parameterise``, written to the HTML page ``file``; its size in
    bytes. Configurations in collision are drawn in red."""
