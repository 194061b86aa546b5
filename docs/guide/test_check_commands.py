#!/usr/bin/env python3
"""Tests of check_commands.py's comparison rule, annotations and --update.

Run: python3 docs/guide/test_check_commands.py   (standard library only)
"""

import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from check_commands import Tolerance, compare, parse_directives, update  # noqa: E402

PRINTED = [
    "MIT* on dividing-walls R^2 (seed 0, budget 0.5 s)",
    "  solved; path validated independently (41 segments, 0.0277 ms apart from planning)",
    "  initial solution: 9.40e-4 s, cost 1.4368",
    "  final cost: 0.9260 after 28 improvements",
    "  picture: results/plan/dividing-walls-n2-mit-star-seed0.png",
]
TIMING = Tolerance(10.0)


class Compare(unittest.TestCase):
    def test_identical_output_matches(self):
        self.assertIsNone(compare(PRINTED, PRINTED))

    def test_a_changed_word_fails(self):
        shown = list(PRINTED)
        shown[3] = "  final cost: 0.9260 after 28 refinements"
        message = compare(shown, PRINTED, TIMING)
        self.assertIsNotNone(message)
        self.assertIn("shown line 4", message)
        self.assertIn("after 28 improvements", message)

    def test_a_changed_path_fails_even_with_timing(self):
        shown = list(PRINTED)
        shown[4] = "  picture: results/plan/dividing-walls-n2-mit-star-seed1.png"
        self.assertIsNotNone(compare(shown, PRINTED, TIMING))

    def test_a_timing_figure_within_the_tolerance_passes(self):
        shown = list(PRINTED)
        shown[2] = "  initial solution: 2.10e-3 s, cost 1.4368"
        shown[1] = "  solved; path validated independently (41 segments, 0.0031 ms apart from planning)"
        self.assertIsNone(compare(shown, PRINTED, TIMING))
        self.assertIsNotNone(compare(shown, PRINTED, Tolerance(3.0)))  # 0.0031 against 0.0277

    def test_a_timing_figure_outside_the_tolerance_fails(self):
        shown = list(PRINTED)
        shown[2] = "  initial solution: 2.10e-3 s, cost 1.4368"
        message = compare(shown, PRINTED, Tolerance(2.0))
        self.assertIn("not within ×2", message)

    def test_without_timing_a_changed_figure_fails(self):
        shown = list(PRINTED)
        shown[2] = "  initial solution: 9.41e-4 s, cost 1.4368"
        self.assertIsNotNone(compare(shown, PRINTED))

    def test_integers_stay_exact_unless_counts(self):
        shown = list(PRINTED)
        shown[3] = "  final cost: 0.9260 after 30 improvements"
        self.assertIsNotNone(compare(shown, PRINTED, TIMING))
        self.assertIsNone(compare(shown, PRINTED, Tolerance(10.0, counts=True)))

    def test_a_decimal_zero_matches_only_zero(self):
        self.assertIsNotNone(compare(["cost 0.0"], ["cost 0.5"], Tolerance(10.0)))
        self.assertIsNone(compare(["cost 0.0"], ["cost 0"], Tolerance(10.0)))

    def test_a_zero_count_matches_small_counts(self):
        counts = Tolerance(10.0, counts=True)
        self.assertIsNone(compare(["0 stops"], ["3 stops"], counts))
        self.assertIsNotNone(compare(["0 stops"], ["11 stops"], counts))
        self.assertIsNotNone(compare(["0 stops"], ["3 stops"], Tolerance(10.0)))

    def test_ellipsis_lines_and_inline_ellipsis(self):
        shown = [PRINTED[0], "…", "  final cost: … after 28 improvements", "…"]
        self.assertIsNone(compare(shown, PRINTED))
        self.assertIsNotNone(compare([PRINTED[0], "…", "  final cost: … after 29 improvements", "…"], PRINTED))

    def test_a_block_without_closing_ellipsis_must_reach_the_end(self):
        message = compare(PRINTED[:3], PRINTED)
        self.assertIn("printed more", message)
        self.assertIsNone(compare(PRINTED[:3] + ["…"], PRINTED))

    def test_a_block_starts_at_the_first_printed_line_unless_it_opens_with_an_ellipsis(self):
        self.assertIsNotNone(compare(PRINTED[1:], PRINTED))
        self.assertIsNone(compare(["…"] + PRINTED[1:], PRINTED))

    def test_whitespace_runs_are_one_space(self):
        self.assertIsNone(compare(["iterations    625359"], ["iterations 625359"]))


class Update(unittest.TestCase):
    def test_rewrites_the_stretches_and_keeps_the_gaps(self):
        shown = [PRINTED[0], "  solved; path validated (…)", "…", "  final cost: 0.9 after 2 improvements", "…"]
        new = update(shown, PRINTED)
        self.assertEqual(new[0], PRINTED[0])
        self.assertEqual(new[2], "…")
        self.assertEqual(new[3], PRINTED[3])
        self.assertIsNone(compare(new, PRINTED))

    def test_a_block_without_gaps_becomes_the_output(self):
        self.assertEqual(update(["something else"], PRINTED), PRINTED)


class Directives(unittest.TestCase):
    def test_parses_one_line_and_several_lines(self):
        d = parse_directives(" timing x3 counts; exit 2")
        self.assertEqual(d["timing"], Tolerance(3.0, counts=True))
        self.assertEqual(d["exit"], 2)
        d = parse_directives("\nreplace: --instances 1-100 => --instances 1-3\nskip: needs a GPU; really\n")
        self.assertEqual(d["replace"], [("--instances 1-100", "--instances 1-3")])
        self.assertEqual(d["skip"], "needs a GPU; really")

    def test_vary_makes_machine_text_a_wildcard(self):
        d = parse_directives("vary: on `\\w+`")
        shown = ["Started on `vm` with 2 runs"]
        self.assertIsNone(compare(shown, ["Started on `ci-box` with 2 runs"], d["timing"]))
        self.assertIsNotNone(compare(shown, ["Started on `ci-box` with 3 runs"], d["timing"]))

    def test_refuses_unknown_directives(self):
        with self.assertRaises(ValueError):
            parse_directives("timng")
        with self.assertRaises(ValueError):
            parse_directives("replace: no arrow")


if __name__ == "__main__":
    unittest.main()
