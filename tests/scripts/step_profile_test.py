#!/usr/bin/env python3
"""Tests for scripts/step_profile.py on a hand-made step profile summary.

Run:  /usr/bin/python3 tests/scripts/step_profile_test.py
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "step_profile.py")


def state(ticks, steps, limiting):
    return {"ticks": ticks, "steps": steps, "steps_per_tick": {"mean": steps / max(1, ticks), "median": 7.0},
            "error_test_failures": 2 * ticks, "nonlinear_failures": ticks, "step": {"mean": 0.0005},
            "limiting": limiting, "pair_switches": {"per_tick": 0.25}, "spring_switches": {"per_tick": 1.5},
            "stop_switches": {"per_tick": 0.125}}


class StepProfileTable(unittest.TestCase):
    def test_one_row_per_state_with_ticks_and_the_top_three_limits(self):
        summary = {"all": {}, "DS": state(10, 300, {"v_hip_l": 60, "q_x": 20, "v_x": 10, "v_y": 10}),
                   "LS": state(0, 0, {}), "RS": state(4, 400, {"v_ankle_l": 400})}
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "walker.json")
            with open(path, "w") as f:
                json.dump(summary, f)
            out = subprocess.run([sys.executable, SCRIPT, path], capture_output=True, text=True)
            self.assertEqual(out.returncode, 0, out.stderr)
            rows = [line for line in out.stdout.splitlines() if line.startswith("| walker")]
            self.assertEqual(len(rows), 2)  # LS has no ticks
            self.assertEqual(rows[0], "| walker | DS | 10 | 30 | 7 | 2.0 | 1.0 | 0.500 | v_hip_l 60 %, q_x 20 %, "
                                      "v_x 10 % | 0.25 | 1.5 | 0.12 |")
            self.assertIn("| RS | 4 | 100 |", rows[1])
            self.assertIn("v_ankle_l 100 %", rows[1])
            with open(path, "w") as f:
                json.dump({"DS": {}}, f)
            bad = subprocess.run([sys.executable, SCRIPT, path], capture_output=True, text=True)
            self.assertEqual(bad.returncode, 2)
            self.assertIn("walker.json", bad.stderr)


if __name__ == "__main__":
    unittest.main()
