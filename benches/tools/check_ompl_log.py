#!/usr/bin/env python3
"""Independent check of mit-star's OMPL benchmark logs against its Planner Arena database.

Reads every OMPL benchmark log of a results folder the way OMPL's
`ompl_benchmark_statistics.py` reads logs (same tokens, same optional parts, same column naming,
`; `-separated run values, `,`/`;`-separated progress samples, "", "inf" and "nan" as NULL),
loads them into an in-memory SQLite database with the Planner Arena schema, and compares that
database with the `benchmark.db` mit-star wrote directly: experiments, planner configurations,
enums, the number of runs per planner, every run value and every progress row.

Standard library only (Python >= 3.8).

Usage:
    python3 benches/tools/check_ompl_log.py RESULTS_FOLDER [--database DB] [LOG ...]

Exit status: 0 if everything agrees, 1 on a mismatch or a malformed log, 2 on bad usage.
"""

import argparse
import glob
import math
import os
import sqlite3
import sys

SCHEMA = """
CREATE TABLE IF NOT EXISTS experiments
    (id INTEGER PRIMARY KEY AUTOINCREMENT, name VARCHAR(512),
    totaltime REAL, timelimit REAL, memorylimit REAL, runcount INTEGER,
    version VARCHAR(128), hostname VARCHAR(1024), cpuinfo TEXT,
    date DATETIME, seed VARCHAR(24), setup TEXT);
CREATE TABLE IF NOT EXISTS plannerConfigs
    (id INTEGER PRIMARY KEY AUTOINCREMENT,
    name VARCHAR(512) NOT NULL, settings TEXT);
CREATE TABLE IF NOT EXISTS enums
    (name VARCHAR(512), value INTEGER, description TEXT,
    PRIMARY KEY (name, value));
CREATE TABLE IF NOT EXISTS runs
    (id INTEGER PRIMARY KEY AUTOINCREMENT, experimentid INTEGER, plannerid INTEGER,
    FOREIGN KEY (experimentid) REFERENCES experiments(id) ON DELETE CASCADE,
    FOREIGN KEY (plannerid) REFERENCES plannerConfigs(id) ON DELETE CASCADE);
CREATE TABLE IF NOT EXISTS progress
    (runid INTEGER, time REAL, PRIMARY KEY (runid, time),
    FOREIGN KEY (runid) REFERENCES runs(id) ON DELETE CASCADE);
"""

STANDARD_EXPERIMENT_COLUMNS = [
    "name", "totaltime", "timelimit", "memorylimit", "runcount", "version",
    "hostname", "cpuinfo", "date", "seed", "setup",
]


class LogError(Exception):
    """A log that does not follow the grammar."""


class LogReader:
    """Line reader with look-ahead and line numbers."""

    def __init__(self, path):
        with open(path, "r", encoding="utf-8") as handle:
            self.lines = handle.read().split("\n")
        if self.lines and self.lines[-1] == "":
            self.lines.pop()
        self.position = 0
        self.path = path

    def fail(self, message):
        raise LogError("%s:%d: %s" % (self.path, self.position, message))

    def peek(self):
        if self.position < len(self.lines):
            return self.lines[self.position]
        return None

    def next(self, what):
        line = self.peek()
        if line is None:
            self.fail("the log ends where %s was expected" % what)
        self.position += 1
        return line

    def tokens_match(self, expected):
        """True if the next line's tokens match {index: token}."""
        line = self.peek()
        if line is None:
            return False
        tokens = line.split()
        try:
            return all(tokens[i] == t for i, t in expected.items())
        except IndexError:
            return False

    def value(self, what, index, expected):
        if not self.tokens_match(expected):
            self.fail("expected %s, found %r" % (what, self.peek()))
        return self.next(what).split()[index]

    def multiline(self, what):
        if self.next(what) != "<<<|":
            self.fail("expected <<<| opening %s" % what)
        text = ""
        while True:
            line = self.next("|>>> closing " + what)
            if line.startswith("|>>>"):
                return text
            text += line + "\n"


def null_or(text):
    """OMPL's reader: empty, 'nan' and 'inf' become NULL; everything else is kept as text."""
    text = text.strip()
    if text == "" or text in ("nan", "inf", "-inf", "-nan"):
        return None
    return text


def load_log(connection, path):
    """Parses one log into the database, as ompl_benchmark_statistics.py would."""
    cursor = connection.cursor()
    log = LogReader(path)
    library, version = "OMPL", "0.0.0"
    if log.tokens_match({1: "version"}):
        tokens = log.next("version").split()
        library, version = tokens[0], tokens[-1]
    version = library + " " + version
    name = log.value("`Experiment <name>`", -1, {0: "Experiment"})
    properties = {}
    if log.tokens_match({-2: "experiment", -1: "properties"}):
        count = int(log.next("experiment property count").split()[0])
        for _ in range(count):
            line = log.next("an experiment property").strip()
            if " = " not in line:
                log.fail("experiment property without ' = ': %r" % line)
            left, value = line.split(" = ", 1)
            words = left.split(" ")
            if len(words) < 2:
                log.fail("experiment property without a type: %r" % line)
            column = "".join(words[:-1]).replace("-", "_")
            properties[column] = (value, words[-1])
    cursor.execute("PRAGMA table_info(experiments)")
    existing = [row[1] for row in cursor.fetchall()]
    for column in sorted(properties):
        if column not in existing:
            cursor.execute("ALTER TABLE experiments ADD %s %s" % (column, properties[column][1]))
    hostname = log.value("`Running on <host>`", -1, {0: "Running"})
    line = log.next("`Starting at <date>`")
    if not line.startswith("Starting"):
        log.fail("expected `Starting at <date>`, found %r" % line)
    date = " ".join(line.split()[2:])
    setup = log.multiline("the setup")
    cpuinfo = log.multiline("the cpu info") if log.peek() == "<<<|" else None
    seed = log.value("`<seed> is the random seed`", 0, {-2: "random", -1: "seed"})
    timelimit = float(log.value("`<t> seconds per run`", 0, {-3: "seconds", -2: "per", -1: "run"}))
    memorylimit = float(log.value("`<m> MB per run`", 0, {-3: "MB", -2: "per", -1: "run"}))
    runcount = -1
    if log.tokens_match({-3: "runs", -2: "per", -1: "planner"}):
        runcount = int(log.next("run count").split()[0])
    totaltime = float(log.value("`<t> seconds spent to collect the data`", 0,
                                {-3: "collect", -2: "the", -1: "data"}))
    enum_count = 0
    if log.tokens_match({-2: "enum"}):
        enum_count = int(log.next("enum count").split()[0])
    for _ in range(enum_count):
        parts = log.next("an enum").split("|")
        cursor.execute("SELECT count(*) FROM enums WHERE name = ?", (parts[0],))
        if cursor.fetchone()[0] == 0:
            for value, description in enumerate(parts[1:]):
                cursor.execute("INSERT INTO enums VALUES (?,?,?)", (parts[0], value, description))
    columns = STANDARD_EXPERIMENT_COLUMNS + list(properties)
    values = [name, totaltime, timelimit, memorylimit, runcount, version, hostname, cpuinfo,
              date, seed, setup] + [properties[c][0] for c in properties]
    cursor.execute("INSERT INTO experiments (%s) VALUES (%s)"
                   % (",".join(columns), ",".join("?" * len(values))), values)
    experiment_id = cursor.lastrowid
    planner_count = int(log.value("`<n> planners`", 0, {-1: "planners"}))
    for _ in range(planner_count):
        planner = log.next("a planner name")
        common = int(log.value("`<n> common properties`", 0, {-2: "common", -1: "properties"}))
        settings = ""
        for _ in range(common):
            line = log.next("a common property")
            if " = " not in line:
                log.fail("common property without ' = ': %r" % line)
            settings += line + "\n;"
        cursor.execute("SELECT id FROM plannerConfigs WHERE name = ? AND settings = ?",
                       (planner, settings))
        row = cursor.fetchone()
        if row is None:
            cursor.execute("INSERT INTO plannerConfigs (name, settings) VALUES (?, ?)",
                           (planner, settings))
            planner_id = cursor.lastrowid
        else:
            planner_id = row[0]
        property_count = int(log.value("`<n> properties for each run`", 0,
                                       {-3: "for", -2: "each", -1: "run"}))
        cursor.execute("PRAGMA table_info(runs)")
        existing = [r[1] for r in cursor.fetchall()]
        names = ["experimentid", "plannerid"]
        for _ in range(property_count):
            words = log.next("a run property").split()
            if len(words) < 2 or words[-1] not in ("BOOLEAN", "INTEGER", "REAL", "ENUM", "STRING"):
                log.fail("run property needs `<name> <TYPE>`: %r" % " ".join(words))
            column = "_".join(words[:-1])
            if column not in existing:
                cursor.execute("ALTER TABLE runs ADD %s %s" % (column, words[-1]))
                existing.append(column)
            names.append(column)
        insert_run = "INSERT INTO runs (%s) VALUES (%s)" % (",".join(names), ",".join("?" * len(names)))
        run_count = int(log.value("`<n> runs`", 0, {-1: "runs"}))
        run_ids = []
        for _ in range(run_count):
            line = log.next("a run")
            fields = line.split("; ")
            if fields[-1].strip() != "":
                log.fail("a run line must end with '; ': %r" % line)
            fields = fields[:-1]
            if len(fields) != property_count:
                log.fail("a run has %d values for %d properties" % (len(fields), property_count))
            cursor.execute(insert_run, [experiment_id, planner_id] + [null_or(f) for f in fields])
            run_ids.append(cursor.lastrowid)
        line = log.next("`.` or progress properties").strip()
        if line != ".":
            words = line.split()
            if words[1:] != ["progress", "properties", "for", "each", "run"]:
                log.fail("expected `<n> progress properties for each run`, found %r" % line)
            cursor.execute("PRAGMA table_info(progress)")
            existing = [r[1] for r in cursor.fetchall()]
            progress_names = ["runid"]
            for _ in range(int(words[0])):
                words = log.next("a progress property").split()
                column = "_".join(words[:-1])
                if column not in existing:
                    cursor.execute("ALTER TABLE progress ADD %s %s" % (column, words[-1]))
                    existing.append(column)
                progress_names.append(column)
            insert_progress = "INSERT INTO progress (%s) VALUES (%s)" % (
                ",".join(progress_names), ",".join("?" * len(progress_names)))
            progress_runs = int(log.value("`<n> runs`", 0, {-1: "runs"}))
            if progress_runs != len(run_ids):
                log.fail("%d progress runs for %d runs" % (progress_runs, len(run_ids)))
            for run_id in run_ids:
                line = log.next("a run's progress")
                samples = line.split(";")
                if samples[-1].strip() != "":
                    log.fail("progress samples must end with ';': %r" % line)
                for sample in samples[:-1]:
                    fields = sample.split(",")
                    if fields[-1].strip() != "" or len(fields) - 1 != len(progress_names) - 1:
                        log.fail("malformed progress sample %r" % sample)
                    cursor.execute(insert_progress, [run_id] + [null_or(f) for f in fields[:-1]])
            if log.next("`.`").strip() != ".":
                log.fail("expected `.` closing planner %s" % planner)
    if any(line.strip() for line in log.lines[log.position:]):
        log.fail("unexpected text after the last planner")
    connection.commit()
    return experiment_id


def same(a, b):
    if isinstance(a, float) or isinstance(b, float):
        if a is None or b is None:
            return a is b
        a, b = float(a), float(b)
        return a == b or math.isclose(a, b, rel_tol=1e-12, abs_tol=1e-300)
    return a == b


class Comparison:
    def __init__(self):
        self.errors = []
        self.checked = 0

    def expect(self, ok, message):
        self.checked += 1
        if not ok and len(self.errors) < 50:
            self.errors.append(message)


def rows(connection, sql, args=()):
    cursor = connection.cursor()
    cursor.execute(sql, args)
    names = [d[0] for d in cursor.description]
    return [dict(zip(names, r)) for r in cursor.fetchall()]


def compare(parsed, ours, check):
    """Compares every experiment parsed from the logs with the matching one in our database."""
    ours_experiments = rows(ours, "SELECT * FROM experiments ORDER BY id")
    summary = []
    for experiment in rows(parsed, "SELECT * FROM experiments ORDER BY id"):
        keys = [k for k in experiment if k not in ("id",)]
        matches = [e for e in ours_experiments
                   if e.get("name") == experiment["name"] and e.get("date") == experiment["date"]
                   and all(same(e.get(k), experiment[k]) for k in keys
                           if k not in STANDARD_EXPERIMENT_COLUMNS)]
        label = "%s (%s)" % (experiment["name"], experiment["date"])
        check.expect(len(matches) == 1, "%s: %d matching experiments in the database"
                     % (label, len(matches)))
        if len(matches) != 1:
            continue
        mine = matches[0]
        for k in keys:
            check.expect(same(mine.get(k), experiment[k]),
                         "%s: experiments.%s differs: log %r, database %r"
                         % (label, k, experiment[k], mine.get(k)))
        planners = rows(parsed, "SELECT DISTINCT p.name, p.settings FROM runs r JOIN plannerConfigs p "
                                "ON r.plannerid = p.id WHERE r.experimentid = ?", (experiment["id"],))
        run_total = 0
        for planner in planners:
            select = ("SELECT r.* FROM runs r JOIN plannerConfigs p ON r.plannerid = p.id "
                      "WHERE r.experimentid = ? AND p.name = ? AND p.settings = ? ORDER BY r.id")
            log_runs = rows(parsed, select, (experiment["id"], planner["name"], planner["settings"]))
            db_runs = rows(ours, select, (mine["id"], planner["name"], planner["settings"]))
            check.expect(len(log_runs) == len(db_runs),
                         "%s / %s: %d runs in the log, %d in the database"
                         % (label, planner["name"], len(log_runs), len(db_runs)))
            run_total += len(log_runs)
            for n, (a, b) in enumerate(zip(log_runs, db_runs)):
                for column, value in a.items():
                    if column in ("id", "experimentid", "plannerid"):
                        continue
                    check.expect(column in b and same(b[column], value),
                                 "%s / %s run %d: %s is %r in the log, %r in the database"
                                 % (label, planner["name"], n, column, value, b.get(column)))
                progress_a = rows(parsed, "SELECT * FROM progress WHERE runid = ? ORDER BY time", (a["id"],))
                progress_b = rows(ours, "SELECT * FROM progress WHERE runid = ? ORDER BY time", (b["id"],))
                check.expect(len(progress_a) == len(progress_b),
                             "%s / %s run %d: %d progress rows in the log, %d in the database"
                             % (label, planner["name"], n, len(progress_a), len(progress_b)))
                for pa, pb in zip(progress_a, progress_b):
                    for column, value in pa.items():
                        if column == "runid":
                            continue
                        check.expect(same(pb.get(column), value),
                                     "%s / %s run %d: progress %s %r vs %r"
                                     % (label, planner["name"], n, column, value, pb.get(column)))
        summary.append("%s: %d planners, %d runs" % (label, len(planners), run_total))
    for enum in rows(parsed, "SELECT * FROM enums ORDER BY name, value"):
        found = rows(ours, "SELECT description FROM enums WHERE name = ? AND value = ?",
                     (enum["name"], enum["value"]))
        check.expect(len(found) == 1 and found[0]["description"] == enum["description"],
                     "enum %s value %d differs" % (enum["name"], enum["value"]))
    return summary


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    parser.add_argument("results", help="a mit-star results folder")
    parser.add_argument("--database", help="the database (default RESULTS/benchmark.db)")
    parser.add_argument("logs", nargs="*", help="logs to read (default RESULTS/logs/*.log)")
    args = parser.parse_args()
    database = args.database or os.path.join(args.results, "benchmark.db")
    logs = args.logs or sorted(glob.glob(os.path.join(args.results, "logs", "*.log")))
    if not os.path.isfile(database):
        print("no database at %s" % database, file=sys.stderr)
        return 2
    if not logs:
        print("no logs in %s" % os.path.join(args.results, "logs"), file=sys.stderr)
        return 2
    parsed = sqlite3.connect(":memory:")
    parsed.executescript(SCHEMA)
    try:
        for log in logs:
            load_log(parsed, log)
    except (LogError, ValueError, IndexError) as error:
        print("malformed log: %s" % error, file=sys.stderr)
        return 1
    ours = sqlite3.connect("file:%s?mode=ro" % database, uri=True)
    check = Comparison()
    summary = compare(parsed, ours, check)
    for line in summary:
        print(line)
    if check.errors:
        for error in check.errors:
            print("MISMATCH: " + error, file=sys.stderr)
        print("%d logs: %d checks, %d mismatches" % (len(logs), check.checked, len(check.errors)),
              file=sys.stderr)
        return 1
    print("%d logs agree with %s (%d checks)" % (len(logs), database, check.checked))
    return 0


if __name__ == "__main__":
    sys.exit(main())
