"""scripts/filter_floor.py on hand-made ground truth: a quiet filter follows a straight walk and
lags a sudden set-off, noisier centres and ranging beyond the depth range raise the floor,
standing frames score no error, and bad input is a clear message with a nonzero exit.
Label unit."""

import json
import math
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import unittest

try:
    import numpy  # noqa: F401  (the script needs it)
except ImportError:
    sys.exit(77)

REPO = pathlib.Path(__file__).resolve().parents[3]
SCRIPT = REPO / "scripts" / "filter_floor.py"
PYTHON = os.environ.get("DYNANAV_PYTHON3", sys.executable)
DT = 1.0 / 30.0


def write_sequence(folder, positions_velocities, camera=(0.0, 0.0, 0.0)):
    """objects_gt.jsonl with one person (position, velocity per frame), a still camera."""
    folder.mkdir(parents=True, exist_ok=True)
    with open(folder / "objects_gt.jsonl", "w") as f:
        for p, v in positions_velocities:
            o = {"id": 1, "class": "person", "in_view": 1.0, "position_world": list(p),
                 "velocity_world": list(v), "speed": math.hypot(*v)}
            f.write(json.dumps({"objects": [o]}) + "\n")
    with open(folder / "groundtruth.txt", "w") as f:
        f.write("# timestamp tx ty tz qx qy qz qw\n")
        for k in range(len(positions_velocities)):
            f.write(f"{k * DT:.6f} {camera[0]} {camera[1]} {camera[2]} 0 0 0 1\n")
    (folder / "camera.yaml").write_text("fx: 525\nfy: 525\n")
    return folder / "objects_gt.jsonl"


def walk(frames, start, velocity, set_off_frame=0):
    out, p = [], list(start)
    for k in range(frames):
        v = velocity if k >= set_off_frame else (0.0, 0.0, 0.0)
        if k > 0:
            p = [p[i] + v[i] * DT for i in range(3)]
        out.append((tuple(p), v))
    return out


def floor(gt, *args):
    r = subprocess.run([PYTHON, str(SCRIPT), *map(str, args), str(gt)], capture_output=True,
                       text=True, timeout=120)
    m = re.search(r"speed RMSE ([0-9.]+) m/s", r.stdout)
    return r, (float(m.group(1)) if m else None)


class FilterFloor(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def test_a_straight_walk_wants_a_quiet_filter_and_a_set_off_an_agile_one(self):
        # The filter's acceleration noise trades lag against noise: a constant walk is followed
        # best by a quiet filter, a sudden set-off (1 m/s in one frame) lags behind it.
        straight = write_sequence(self.dir / "straight", walk(120, (0, 0, 3), (1.0, 0.0, 0.0)))
        set_off = write_sequence(self.dir / "set_off", walk(120, (0, 0, 3), (1.0, 0.0, 0.0), 30))
        known = ("--centre-sigma-m", 0.01, "--start-velocity-sigma-mps", 0)
        _, straight_quiet = floor(straight, "--accel-mps2", 0.05, *known)
        _, straight_agile = floor(straight, "--accel-mps2", 0.5, *known)
        _, set_off_quiet = floor(set_off, "--accel-mps2", 0.05, *known)
        _, set_off_agile = floor(set_off, "--accel-mps2", 0.5, *known)
        self.assertLess(straight_quiet, 0.5 * straight_agile)
        self.assertGreater(set_off_quiet, 1.5 * set_off_agile)
        self.assertGreater(set_off_quiet, 5 * straight_quiet)

    def test_noisier_centres_raise_the_floor(self):
        # Long enough for the filter's steady state, where the velocity's error grows with the
        # centres' noise (about as its square root: 10x the noise, about 2x here).
        gt = write_sequence(self.dir / "walk", walk(600, (0, 0, 3), (0.8, 0.0, 0.6)))
        _, fine = floor(gt, "--centre-sigma-m", 0.005)
        _, coarse = floor(gt, "--centre-sigma-m", 0.05)
        self.assertGreater(coarse, 1.5 * fine)

    def test_ranging_beyond_the_depth_range_raises_the_floor(self):
        gt = write_sequence(self.dir / "far", walk(120, (0, 0, 11), (0.0, 0.0, -1.0)))
        _, near_depth = floor(gt, "--centre-sigma-m", 0.01)
        r, ranged = floor(gt, "--centre-sigma-m", 0.01, "--range-beyond-m", 4.5)
        self.assertIn("ranged beyond 4.5 m", r.stdout)
        self.assertGreater(ranged, 2 * near_depth)

    def test_standing_frames_score_no_error(self):
        gt = write_sequence(self.dir / "still", walk(60, (0, 0, 3), (1.0, 0.0, 0.0), 1000))
        _, rmse = floor(gt, "--centre-sigma-m", 0.05)
        self.assertEqual(rmse, 0.0)

    def test_bad_input_is_a_clear_message(self):
        r, _ = floor(self.dir / "missing.jsonl")
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("cannot read", r.stderr)
        gt = write_sequence(self.dir / "walk", walk(10, (0, 0, 3), (1.0, 0.0, 0.0)))
        (self.dir / "walk" / "groundtruth.txt").unlink()
        r, _ = floor(gt, "--range-beyond-m", 4.5)
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("groundtruth.txt", r.stderr)
        r, _ = floor(gt, "--accel-mps2", 0)
        self.assertNotEqual(r.returncode, 0)


if __name__ == "__main__":
    unittest.main()
