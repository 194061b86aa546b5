"""Every Python example and benchmark script says how to install what it imports: each
third-party module it imports is installed by `pip install ./python` (the package's own
dependencies), or named by a `pip install` line in the script's docstring (an extra of the
package, such as `./python[examples]`, or another distribution)."""

from __future__ import annotations

import ast
import re
import sys
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SCRIPTS = sorted(
    [*ROOT.joinpath("examples", "python").glob("*.py"), *ROOT.joinpath("python", "benchmarks").glob("*.py")]
)
# The import name of a distribution where the two differ.
IMPORT_NAMES = {"pyyaml": "yaml", "pin": "pinocchio", "mit-star": "mit_star"}


def distribution_modules(requirements: list[str]) -> set[str]:
    names = set()
    for requirement in requirements:
        name = re.split(r"[<>=!~\[; ]", requirement.strip(), maxsplit=1)[0].lower()
        names.add(IMPORT_NAMES.get(name, name.replace("-", "_")))
    return names


def project() -> dict:
    return tomllib.loads(ROOT.joinpath("python", "pyproject.toml").read_text())["project"]


def installed_by(line: str) -> set[str]:
    """The modules a `pip install …` line installs: the package (with its dependencies and the
    extras it names) and any other distribution it names."""
    table = project()
    modules = {"mit_star"} | distribution_modules(table["dependencies"])
    for word in line.split()[2:]:
        word = word.strip("\"'")
        if word.startswith("-"):
            continue
        package = re.fullmatch(r"\./python(?:\[([\w,-]+)\])?", word)
        if package:
            for extra in (package.group(1) or "").split(","):
                if extra:
                    modules |= distribution_modules(table["optional-dependencies"][extra])
        else:
            modules |= distribution_modules([word])
    return modules


def third_party_imports(path: Path) -> set[str]:
    local = {p.stem for p in path.parent.glob("*.py")}
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            found |= {alias.name.split(".")[0] for alias in node.names}
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            found.add(node.module.split(".")[0])
    return {m for m in found if m not in sys.stdlib_module_names and m not in local and m != "__future__"}


@pytest.mark.parametrize("path", SCRIPTS, ids=lambda p: str(p.relative_to(ROOT)))
def test_a_script_says_how_to_install_what_it_imports(path: Path) -> None:
    docstring = ast.get_docstring(ast.parse(path.read_text())) or ""
    lines = [line.strip() for line in docstring.splitlines() if line.strip().startswith("pip install ")]
    provided = installed_by("pip install ./python")
    for line in lines:
        provided |= installed_by(line)
    missing = third_party_imports(path) - provided
    assert not missing, (
        f"{path.relative_to(ROOT)} imports {sorted(missing)}, which `pip install ./python` does not "
        f"install and no `pip install` line of its docstring names"
    )


def test_the_checker_finds_a_missing_install_line(tmp_path: Path) -> None:
    script = tmp_path / "plot.py"
    script.write_text('"""Plots.\n\n    python plot.py\n"""\nimport matplotlib\nimport numpy\nimport mit_star\n')
    assert third_party_imports(script) == {"matplotlib", "numpy", "mit_star"}
    assert "matplotlib" not in installed_by("pip install ./python")
    assert "matplotlib" in installed_by('pip install "./python[examples]"')
    assert "ompl" in installed_by("pip install ompl")


def test_there_are_scripts_to_check() -> None:
    assert len(SCRIPTS) >= 5, SCRIPTS
