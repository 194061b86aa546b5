#!/usr/bin/env python3
"""Runs the command blocks of the guide's task pages and checks the outputs they show.

Every fenced ```sh block (also bash, shell, console) of a task page is run with bash from the
root of the repository, in page order (a block sees the files its predecessors wrote), with
the installed `mit-star` first on PATH (--bin) and the Python virtual environment's `bin`
folder next (--venv), and must exit with 0. A ```text block whose first line starts with `$ `
is a transcript: each `$ ` line is run and the lines after it are its output. A ```python block
(python.md) runs in one Python interpreter per page (--venv), blocks sharing their variables.
Every other ```text block is the output of the latest command block above it (stdout and
stderr together, cargo's own `Compiling`/`Finished`/`Running` lines left out), unless
annotated otherwise.

How a shown output is compared with the printed one:

- whitespace: leading and trailing whitespace is ignored, and a run of spaces inside a line
  is one space (aligned columns may realign);
- a line that is only `…` stands for any number of printed lines, none included; otherwise the
  shown lines are consecutive printed lines, the first shown line is the first printed one and
  the last the last (a block that shows part of the output begins or ends with a `…` line);
- a `…` inside a line stands for any text within that line;
- everything else is compared exactly: words, names, paths, units and numbers, unless the
  block is annotated `timing` (below).

Annotations are HTML comments on the line just before a block's opening fence (mdBook drops
them from the page). One directive a line; on a one-line comment, directives are separated by
`; ` (except `run:`, `before:`, `replace:`, `skip:`, `not-output:` and `write:`, which take the
rest of their line):

    <!-- check: timing -->                        decimal figures (times, costs, clearances)
                                                  match within a factor of 10 either way
    <!-- check: timing x3 -->                     ... within a factor of 3
    <!-- check: timing counts -->                 integers loose too (the counters, segments
                                                  and improvements of a run cut short by its
                                                  time budget), 0 counting as 1 (0 matches 0 to
                                                  10); a decimal zero matches only zero
    <!-- check: exit 2 -->                        the block must exit with 2, not 0
    <!-- check: replace: --instances 1-100 => --instances 1-3 -->
                                                  the reduced form that runs in CI (repeatable;
                                                  the runner prints it); the shown output is then
                                                  compared with the reduced run's
    <!-- check: before: SCRIPT -->                a setup script run (silently) before the block
    <!-- check: skip: REASON -->                  not run; the runner prints the reason and
                                                  counts it. Only for what CI cannot have (a GPU,
                                                  a peer planner's build, a package index)
    <!-- check: not-output: REASON -->            a text block that is not a command's output
                                                  (a file format, an excerpt of a library error)
    <!-- check: file: PATH -->                    a text block showing the file PATH (a glob: the
                                                  first match in sorted order) as the commands
                                                  above left it
    <!-- check: run: SCRIPT -->                   a text block showing the output of SCRIPT (a
                                                  command the prose describes but does not show)
    <!-- check: vary: REGEX -->                   the text of a shown line that REGEX matches is
                                                  machine-dependent (a host, a CPU, a date) and
                                                  matches any text, as an in-line `…` (repeatable)
    <!-- check: write: PATH -->                   a toml/text block that the reader saves as PATH
                                                  before the next command; the runner writes it

Usage: python3 docs/guide/check_commands.py [--bin DIR] [--venv DIR] [--page NAME]...
           [--update] [--list] [--timeout SECONDS]

--update rewrites every shown output that does not match with what the command printed,
keeping its `…` lines (and in-line `…` where they still match), and leaves matching blocks
alone. Prints a summary per page; exits with 1 when a block failed, naming the page, the block
and the line that differs. Standard library only.
"""

import argparse
import dataclasses
import difflib
import glob
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SRC = os.path.join(HERE, "src")

# The task pages, in the order of SUMMARY.md. Every other top-level page must be listed in
# OTHER_PAGES, so that a new page is classified rather than silently left out.
TASK_PAGES = [
    "install-and-first-plan.md",
    "planning-for-an-arm.md",
    "point-clouds.md",
    "pose-to-trajectory.md",
    "seeing-a-plan.md",
    "your-own-robot.md",
    "running-experiments.md",
    "reading-results.md",
    "python.md",
    "composing-a-planner.md",
    "performance-switches.md",
]
OTHER_PAGES = ["SUMMARY.md", "introduction.md", "faithfulness.md", "ablation-findings.md"]

COMMAND_LANGS = {"sh", "bash", "shell", "console"}
ELLIPSIS = "…"
DEFAULT_FACTOR = 10.0
# A number: not glued to a word before it (`seed0`, `n7-i3` stay text), a unit may follow (`4x`).
NUMBER = re.compile(r"(?<![\w.])[-+]?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?(?!\d|\.\d)")
ANY_NUMBER = r"([-+]?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?)"
CARGO_LINE = re.compile(
    r"^\s*(Compiling|Finished|Running|Blocking|Updating|Downloading|Downloaded|Locking|"
    r"Adding|Fresh|Checking|Building|Installing|Installed|Replacing|Replaced|Ignored)\b"
)
REST_OF_LINE = ("run", "before", "replace", "skip", "not-output", "write", "file", "vary")


# ---------------------------------------------------------------------------------------------
# Comparison


@dataclasses.dataclass
class Tolerance:
    """How loosely a block compares: its numbers (`None` factor: exactly) and the patterns of
    its machine-dependent text (`vary`)."""

    factor: float | None = None
    counts: bool = False
    vary: tuple = ()


def _normalise(line):
    return " ".join(line.split())


def _is_decimal(token):
    return "." in token or "e" in token or "E" in token


class LinePattern:
    """One shown line, as a regular expression over a printed line plus loose numbers."""

    def __init__(self, shown, tolerance):
        self.shown = shown
        self.tolerance = tolerance
        self.numbers = []  # the shown values of the loose numbers, in order
        text = _normalise(shown)
        for pattern in tolerance.vary:
            text = re.sub(pattern, ELLIPSIS, text)
        parts = []
        pos = 0
        for piece in re.split(f"({re.escape(ELLIPSIS)})", text):
            if piece == ELLIPSIS:
                parts.append(".*?")
                continue
            pos = 0
            for m in NUMBER.finditer(piece) if tolerance.factor else ():
                token = m.group(0)
                if not (tolerance.counts or _is_decimal(token)):
                    continue
                parts.append(re.escape(piece[pos : m.start()]))
                parts.append(ANY_NUMBER)
                self.numbers.append((float(token), not _is_decimal(token)))
                pos = m.end()
            parts.append(re.escape(piece[pos:]))
        self.regex = re.compile("".join(parts))

    def why_not(self, printed):
        """None when `printed` matches this line, or the reason it does not."""
        m = self.regex.fullmatch(_normalise(printed))
        if not m:
            return "differs"
        for (shown, integer), token in zip(self.numbers, m.groups()):
            value = float(token)
            integers = integer and not _is_decimal(token)
            if not _close(shown, value, self.tolerance.factor, integers):
                return f"{token} is not within ×{self.tolerance.factor:g} of the shown {shown:g}"
        return None


def _close(shown, printed, factor, integers=False):
    """Within `factor` either way, of the same sign. A decimal zero matches only zero; an
    integer (a count) is at least 1 for the ratio, so 0 and 3 match within a factor of 10."""
    if shown == printed:
        return True
    if (shown < 0) != (printed < 0):
        return False
    a, b = abs(shown), abs(printed)
    if integers:
        a, b = max(a, 1), max(b, 1)
    if a == 0 or b == 0:
        return False
    return 1 / factor <= b / a <= factor


def _items(shown_lines, tolerance):
    return [None if l.strip() == ELLIPSIS else LinePattern(l, tolerance) for l in shown_lines]


def compare(shown_lines, printed_lines, tolerance=Tolerance()):
    """None when the shown lines match the printed ones, or a message naming the first shown
    line that could not be matched and the printed line nearest to it."""
    items = _items(shown_lines, tolerance)
    printed = printed_lines
    m, n = len(items), len(printed)
    cache = {}

    def ok(i, j):
        key = (i, j)
        if key not in cache:
            cache[key] = items[i].why_not(printed[j]) is None
        return cache[key]

    # reach[i] = the printed positions j where shown[:i] can end (forward, for the message);
    # done = whether the whole block matches with the last shown line at the end.
    reach = [set() for _ in range(m + 1)]
    reach[0].add(0)
    for i, item in enumerate(items):
        if not reach[i]:
            break
        if item is None:
            start = min(reach[i])
            reach[i + 1].update(range(start, n + 1))
        else:
            reach[i + 1].update(j + 1 for j in reach[i] if j < n and ok(i, j))
    if n in reach[m] or (m > 0 and items[-1] is None and reach[m]):
        return None
    if m == 0:
        return "the block is empty but the command printed:\n    " + "\n    ".join(printed[:5])
    failed = next((i for i in range(m) if not reach[i + 1]), m)
    if failed == m:
        last = printed[max(reach[m]) :] if reach[m] else printed
        return "the command printed more after the last shown line (end the block with `…`):\n" + (
            "    " + "\n    ".join(last[:3])
        )
    item = items[failed]
    candidates = sorted(j for j in reach[failed] if j < n)
    if not candidates:
        return f"shown line {failed + 1} `{item.shown.strip()}`: the command printed nothing more"
    pool = range(candidates[0], n) if failed > 0 and items[failed - 1] is None else candidates
    pool = list(pool) or candidates
    best = max(pool, key=lambda j: difflib.SequenceMatcher(None, item.shown, printed[j]).ratio())
    reason = item.why_not(printed[best])
    return (
        f"shown line {failed + 1} does not match ({reason}):\n"
        f"    shown:   {item.shown.strip()}\n"
        f"    printed: {printed[best].strip()}"
    )


def update(shown_lines, printed_lines, tolerance=Tolerance()):
    """The shown lines rewritten from the printed ones: each stretch between `…` lines is
    replaced by the printed lines where it fits best (a shown line with an in-line `…` kept
    where it still matches), the `…` lines kept."""
    items = _items(shown_lines, tolerance)
    if all(item is not None for item in items):
        return list(printed_lines)
    out = []
    gaps = [k for k, item in enumerate(items) if item is None]
    cursor = 0
    n = len(printed_lines)
    segments = []
    i = 0
    while i < len(items):
        if items[i] is None:
            segments.append(None)
            i += 1
            continue
        j = i
        while j < len(items) and items[j] is not None:
            j += 1
        segments.append((i, j))
        i = j
    for k, seg in enumerate(segments):
        if seg is None:
            out.append(shown_lines[gaps.pop(0)])
            continue
        i, j = seg
        length = j - i
        anchored_start = k == 0
        anchored_end = k == len(segments) - 1
        if anchored_start:
            positions = [0]
        else:
            positions = range(cursor, max(cursor, n - length) + 1)

        def score(p):
            return sum(
                difflib.SequenceMatcher(None, items[i + d].shown, printed_lines[p + d]).ratio()
                for d in range(length)
                if p + d < n
            )

        p = max(positions, key=score)
        if anchored_end:  # the block ends where the output ends
            take = printed_lines[p:]
        else:
            take = printed_lines[p : p + length]
        for d, line in enumerate(take):
            shown = items[i + d] if d < length else None
            keep = shown and ELLIPSIS in shown.shown and shown.why_not(line) is None
            out.append(shown.shown if keep else line)
        cursor = p + len(take)
    return out


# ---------------------------------------------------------------------------------------------
# Pages


@dataclasses.dataclass
class Block:
    """A fenced block of a page: its language, first line number, lines and directives."""

    page: str
    lang: str
    line: int  # 1-based line of the opening fence
    body: list
    body_start: int  # 0-based index of the first body line in the page
    directives: dict
    indent: str = ""

    @property
    def where(self):
        return f"{self.page}:{self.line}"


def _split_replace(value):
    """`OLD => NEW` (NEW may be empty) as (OLD, "=>", NEW), or (value, "", "")."""
    m = re.fullmatch(r"(.*?)\s=>(?:\s(.*))?", value)
    return (m.group(1), "=>", m.group(2) or "") if m else (value, "", "")


def parse_directives(comment):
    """The directives of a `<!-- check: ... -->` comment's text (after `check`)."""
    directives = {"replace": []}
    vary = []
    pieces = []
    for raw in comment.splitlines():
        raw = raw.strip()
        while raw:
            if raw.split()[0].rstrip(":") in REST_OF_LINE:
                pieces.append(raw)
                break
            head, _, raw = raw.partition("; ")
            pieces.append(head.strip())
            raw = raw.strip()
    for piece in pieces:
        word = piece.split()[0]
        name, value = word.rstrip(":"), piece[len(word) :].strip()
        if name == "timing":
            tolerance = Tolerance(DEFAULT_FACTOR)
            for option in value.split():
                if option == "counts":
                    tolerance.counts = True
                elif re.fullmatch(r"x\d+(\.\d+)?", option):
                    tolerance.factor = float(option[1:])
                else:
                    raise ValueError(f"unknown timing option `{option}`")
            directives["timing"] = tolerance
        elif name == "exit" and value.isdigit():
            directives["exit"] = int(value)
        elif name == "replace":
            old, arrow, new = _split_replace(value)
            if not arrow or not old:
                raise ValueError(f"`replace: {value}` is not `replace: OLD => NEW`")
            directives["replace"].append((old, new))
        elif name == "vary":
            try:
                re.compile(value)
            except re.error as e:
                raise ValueError(f"`vary: {value}` is not a regular expression: {e}")
            vary.append(value)
        elif name in REST_OF_LINE:
            if not value:
                raise ValueError(f"`{name}:` needs a value")
            directives[name] = value
        else:
            raise ValueError(f"unknown directive `{piece}`")
    if vary:
        tolerance = directives.get("timing", Tolerance())
        directives["timing"] = dataclasses.replace(tolerance, vary=tuple(vary))
    return directives


def parse_page(name):
    """The fenced blocks of a page, with their annotations."""
    with open(os.path.join(SRC, name), encoding="utf-8") as f:
        lines = f.read().split("\n")
    blocks = []
    i = 0
    while i < len(lines):
        m = re.match(r"^(\s*)(```+)\s*([\w,+-]*)", lines[i])
        if not m:
            i += 1
            continue
        indent, fence, lang = m.group(1), m.group(2), m.group(3).split(",")[0]
        j = i + 1
        while j < len(lines) and not lines[j].strip().startswith(fence):
            j += 1
        body = [l[len(indent) :] if l.startswith(indent) else l.lstrip() for l in lines[i + 1 : j]]
        directives = {"replace": []}
        k = i - 1
        if k >= 0 and lines[k].strip().endswith("-->"):
            start = k
            while start >= 0 and "<!--" not in lines[start]:
                start -= 1
            comment = "\n".join(lines[start : k + 1]).strip()
            cm = re.fullmatch(r"<!--\s*check\b:?(.*?)-->", comment, re.S)
            if cm:
                try:
                    directives = parse_directives(cm.group(1))
                except ValueError as e:
                    raise SystemExit(f"{name}:{k + 1}: {e}")
        blocks.append(Block(name, lang, i + 1, body, i + 1, directives, indent))
        i = j + 1
    return blocks, lines


# ---------------------------------------------------------------------------------------------
# Running


class Runner:
    """Runs the blocks of the task pages and collects the results."""

    def __init__(self, args):
        self.args = args
        self.env = dict(os.environ)
        paths = []
        if args.bin:
            paths.append(os.path.abspath(args.bin))
        if args.venv:
            paths.append(os.path.join(os.path.abspath(args.venv), "bin"))
            self.env["VIRTUAL_ENV"] = os.path.abspath(args.venv)
        self.env["PATH"] = os.pathsep.join(paths + [self.env.get("PATH", "")])
        self.env["CARGO_TERM_QUIET"] = "true"
        self.env["CARGO_TERM_COLOR"] = "never"
        self.failures = []
        self.skips = []
        self.reduced = []
        self.totals = {"run": 0, "compared": 0, "passed": 0, "skipped": 0, "files": 0}

    def fail(self, block, message):
        self.failures.append(f"{block.where}: {message}")
        print(f"  FAIL {block.where}: {message}", flush=True)

    def shell(self, script, block):
        start = time.monotonic()
        proc = subprocess.Popen(
            ["bash", "-e", "-o", "pipefail", "-c", script],
            cwd=ROOT,
            env=self.env,
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            start_new_session=True,  # its own process group: a timeout ends all of it
        )
        try:
            out, _ = proc.communicate(timeout=self.args.timeout)
            code = proc.returncode
        except subprocess.TimeoutExpired:
            code = None
        finally:
            if proc.poll() is None:
                os.killpg(proc.pid, signal.SIGKILL)
                out, _ = proc.communicate()
        output = out.decode("utf-8", "replace")
        elapsed = time.monotonic() - start
        lines = [l.rstrip() for l in output.split("\n") if not CARGO_LINE.match(l)]
        while lines and not lines[-1]:
            lines.pop()
        return lines, code, elapsed

    def check_exit(self, block, code, expected, lines):
        if code == expected:
            return True
        tail = "\n    ".join(lines[-8:])
        what = "timed out" if code is None else f"exited with {code}"
        self.fail(block, f"{what}, expected {expected}; its last lines:\n    {tail}")
        return False

    def run_page(self, name):
        blocks, page_lines = parse_page(name)
        stats = {"run": 0, "reduced": 0, "skipped": 0, "compared": 0, "passed": 0, "code": 0, "t": 0.0}
        last_output = None  # printed lines of the latest command block, or None if skipped
        last_block = None
        python = None
        edits = []  # (block, new body lines) for --update
        for block in blocks:
            d = block.directives
            if "skip" in d:
                stats["skipped"] += 1
                self.skips.append((block.where, d["skip"]))
                print(f"  skip {block.where}: {d['skip']}", flush=True)
                if block.lang in COMMAND_LANGS or block.lang == "python":
                    last_output, last_block = None, block
                continue
            if "write" in d:
                path = os.path.join(ROOT, d["write"])
                os.makedirs(os.path.dirname(path), exist_ok=True)
                with open(path, "w", encoding="utf-8") as f:
                    f.write("\n".join(block.body) + "\n")
                self.totals["files"] += 1
                continue
            is_transcript = block.lang == "text" and block.body and block.body[0].startswith("$ ")
            if block.lang in COMMAND_LANGS or is_transcript or (
                block.lang == "python" and name == "python.md"
            ):
                script = "\n".join(block.body)
                for old, new in d["replace"]:
                    if old not in script:
                        self.fail(block, f"`replace: {old}` does not occur in the block")
                    script = script.replace(old, new)
                if d["replace"]:
                    stats["reduced"] += 1
                    self.reduced.append((block.where, d["replace"]))
                if "before" in d:
                    _, code, _ = self.shell(d["before"], block)
                    if code != 0:
                        self.fail(block, f"its `before:` script exited with {code}")
                        continue
                stats["run"] += 1
                if block.lang == "python":
                    if python is None:
                        python = PythonSession(self)
                    lines, code, elapsed = python.run(script, block)
                    stats["t"] += elapsed
                    ok = self.check_exit(block, code, d.get("exit", 0), lines)
                    last_output, last_block = (lines if ok else None), block
                elif is_transcript:
                    stats["t"] += self.run_transcript(block, script, stats, edits)
                    last_output, last_block = None, block
                else:
                    lines, code, elapsed = self.shell(script, block)
                    stats["t"] += elapsed
                    print(f"  ran  {block.where} in {elapsed:.1f} s", flush=True)
                    ok = self.check_exit(block, code, d.get("exit", 0), lines)
                    last_output, last_block = (lines if ok else None), block
                continue
            if block.lang != "text":
                stats["code"] += 1  # rust, toml, python outside python.md: code, not commands
                continue
            if "not-output" in d:
                continue
            if "run" in d:
                printed, code, elapsed = self.shell(d["run"], block)
                stats["t"] += elapsed
                if not self.check_exit(block, code, d.get("exit", 0), printed):
                    continue
            elif "file" in d:
                matches = sorted(glob.glob(os.path.join(ROOT, d["file"])))
                if not matches:
                    self.fail(block, f"no file `{d['file']}`")
                    continue
                with open(matches[0], encoding="utf-8", errors="replace") as f:
                    printed = [l.rstrip() for l in f.read().rstrip("\n").split("\n")]
            elif last_block is None:
                self.fail(block, "a text block with no command block above it (annotate it)")
                continue
            elif last_output is None:
                stats["skipped"] += 1
                self.skips.append((block.where, f"output of the skipped or failed {last_block.where}"))
                continue
            else:
                printed = last_output
            self.compare_block(block, block.body, printed, stats, edits)
        if python is not None:
            python.close()
        if edits and self.args.update:
            rewrite(name, page_lines, edits)
        return stats

    def compare_block(self, block, shown, printed, stats, edits, offset=0):
        stats["compared"] += 1
        tolerance = block.directives.get("timing", Tolerance())
        message = compare(shown, printed, tolerance)
        if message is None:
            stats["passed"] += 1
            return
        self.fail(block, message)
        new = [block.indent + line if line else line for line in update(shown, printed, tolerance)]
        edits.append((block.body_start + offset, len(shown), new))

    def run_transcript(self, block, script, stats, edits):
        """A `$ command` transcript: every command's shown lines compared with its output."""
        lines = script.split("\n")
        elapsed = 0.0
        i = 0
        while i < len(lines):
            if not lines[i].startswith("$ "):
                i += 1
                continue
            command = lines[i][2:]
            j = i + 1
            while j < len(lines) and not lines[j].startswith("$ "):
                j += 1
            shown = lines[i + 1 : j]
            while shown and not shown[-1].strip():
                shown.pop()
            printed, code, t = self.shell(command, block)
            elapsed += t
            expected = block.directives.get("exit", 0)
            if code != 0 and code != expected:
                self.check_exit(block, code, expected, printed)
            self.compare_block(block, shown, printed, stats, edits, offset=i + 1)
            i = j
        print(f"  ran  {block.where} (transcript) in {elapsed:.1f} s", flush=True)
        return elapsed


def rewrite(name, page_lines, edits):
    """Replaces the shown outputs of a page by their updates (from the bottom up)."""
    for start, length, new in sorted(edits, key=lambda e: -e[0]):
        page_lines[start : start + length] = new
    with open(os.path.join(SRC, name), "w", encoding="utf-8") as f:
        f.write("\n".join(page_lines))
    print(f"  updated {len(edits)} output block(s) of {name}")


_DRIVER = r"""
import contextlib, json, os, sys, tempfile, traceback
channel = os.fdopen(os.dup(1), "w")
namespace = {"__name__": "__main__"}
for request in sys.stdin:
    request = json.loads(request)
    with tempfile.TemporaryFile() as capture:
        sys.stdout.flush(); sys.stderr.flush()
        saved = os.dup(1), os.dup(2)
        os.dup2(capture.fileno(), 1); os.dup2(capture.fileno(), 2)
        code = 0
        try:
            exec(compile(request["code"], request["where"], "exec"), namespace)
        except SystemExit as e:
            code = e.code if isinstance(e.code, int) else 1
        except BaseException:
            traceback.print_exc()
            code = 1
        sys.stdout.flush(); sys.stderr.flush()
        os.dup2(saved[0], 1); os.dup2(saved[1], 2)
        os.close(saved[0]); os.close(saved[1])
        capture.seek(0)
        output = capture.read().decode("utf-8", "replace")
    channel.write(json.dumps({"output": output, "code": code}) + "\n")
    channel.flush()
"""


class PythonSession:
    """One Python interpreter for the python blocks of a page, their variables shared."""

    def __init__(self, runner):
        python = os.path.join(runner.args.venv or sys.prefix, "bin", "python")
        self.proc = subprocess.Popen(
            [python, "-c", _DRIVER],
            cwd=ROOT,
            env=runner.env,
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
        )

    def run(self, code, block):
        start = time.monotonic()
        self.proc.stdin.write(json.dumps({"code": code, "where": block.where}) + "\n")
        self.proc.stdin.flush()
        reply = self.proc.stdout.readline()
        elapsed = time.monotonic() - start
        print(f"  ran  {block.where} (python) in {elapsed:.1f} s", flush=True)
        if not reply:
            return ["the Python interpreter ended"], 1, elapsed
        reply = json.loads(reply)
        lines = [l.rstrip() for l in reply["output"].split("\n")]
        while lines and not lines[-1]:
            lines.pop()
        return lines, reply["code"], elapsed

    def close(self):
        self.proc.stdin.close()
        self.proc.wait()


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bin", help="folder of the installed `mit-star`, first on PATH")
    parser.add_argument("--venv", help="the Python virtual environment (python.md, `python`)")
    parser.add_argument("--page", action="append", help="only this page (repeatable)")
    parser.add_argument("--update", action="store_true", help="rewrite outputs that differ")
    parser.add_argument("--list", action="store_true", help="list the blocks and directives")
    parser.add_argument("--timeout", type=float, default=600, help="seconds a block may take")
    args = parser.parse_args(argv[1:])

    on_disk = sorted(f for f in os.listdir(SRC) if f.endswith(".md"))
    unknown = [f for f in on_disk if f not in TASK_PAGES + OTHER_PAGES]
    if unknown:
        print(f"pages neither task pages nor listed as others: {', '.join(unknown)}", file=sys.stderr)
        return 2
    pages = TASK_PAGES
    if args.page:
        pages = [p if p.endswith(".md") else p + ".md" for p in args.page]
        missing = [p for p in pages if p not in TASK_PAGES]
        if missing:
            print(f"not task pages: {', '.join(missing)}", file=sys.stderr)
            return 2
    if args.list:
        for page in pages:
            blocks, _ = parse_page(page)
            for b in blocks:
                d = {k: v for k, v in b.directives.items() if v}
                print(f"{b.where} {b.lang} {d if d else ''} {b.body[0][:70] if b.body else ''}")
        return 0

    # A SIGTERM unwinds (SystemExit), so the running block's process group is ended too.
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))
    runner = Runner(args)
    start = time.monotonic()
    summary = []
    for page in pages:
        print(f"== {page}", flush=True)
        stats = runner.run_page(page)
        summary.append((page, stats))
    wall = time.monotonic() - start
    print("\n== summary")
    print(f"{'page':<28} {'run':>4} {'reduced':>7} {'skipped':>7} {'compared':>8} {'passed':>6} {'time [s]':>8}")
    totals = {"run": 0, "reduced": 0, "skipped": 0, "compared": 0, "passed": 0, "code": 0, "t": 0.0}
    for page, s in summary:
        for key in totals:
            totals[key] += s[key]
        print(
            f"{page:<28} {s['run']:>4} {s['reduced']:>7} {s['skipped']:>7} {s['compared']:>8}"
            f" {s['passed']:>6} {s['t']:>8.1f}"
        )
    t = totals
    print(
        f"{'all':<28} {t['run']:>4} {t['reduced']:>7} {t['skipped']:>7} {t['compared']:>8}"
        f" {t['passed']:>6} {t['t']:>8.1f}"
    )
    print(
        f"{runner.totals['files']} file(s) written from the pages; {t['code']} code block(s)"
        f" (Rust, TOML, Python outside python.md) not run; wall time {wall:.0f} s"
    )
    if runner.reduced:
        print(f"\n{len(runner.reduced)} block(s) ran in a reduced form:")
        for where, replaces in runner.reduced:
            print(f"  {where}: " + ", ".join(f"`{o}` -> `{n}`" for o, n in replaces))
    if runner.skips:
        print(f"\n{len(runner.skips)} block(s) skipped:")
        for where, reason in runner.skips:
            print(f"  {where}: {reason}")
    if runner.failures:
        print(f"\n{len(runner.failures)} failure(s):")
        for failure in runner.failures:
            print(f"  {failure}")
        return 1
    print("\nevery command block ran and every shown output matched")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
