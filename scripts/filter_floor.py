#!/usr/bin/env python3
"""The speed error the tracker's constant-velocity Kalman filter reaches on a simulated sequence
when it is fed the *true* centres of the people plus white noise, and nothing else: a reference
for `dynanav eval-objects`' speed RMSE (docs/tracking.md "Session 27"). Not a strict bound: the
tracker also hears its points' rigid motion and the floor (no vertical velocity), and its centres'
errors are not white, so it can do better (crossing does); what the reference shows is what
centres alone of that accuracy allow.

It reads the ground truth the simulator writes (objects_gt.jsonl), scores the frames
`eval-objects` scores (people at least --min-visible in view), and filters each person's centre
from its first scored frame: state [p, v], continuous white-noise acceleration of density
accel^2 discretised as `KalmanCv::processNoise` does, isotropic centre noise sigma. The first frame's velocity is the
truth plus noise of --start-velocity-sigma (0: known exactly; 1: a new track's prior, unknown).
Frames where the truth stands still score 0 error (a perfect stop detector, which the tracker's
static rule approximates), so the figure is the filter's lag and noise while people move.
With --range-beyond-m D, a person farther than D from the camera (the depth sensor's range: the
simulator's is 4.5 m) is placed as the tracker places it there, by its height in the image: its
centre gets extra noise along the viewing ray of sigma = sqrt(2) * px * r^2 / (f * H) (both ends
of the silhouette read to px pixels, an H m tall person at range r, focal length f from the
sequence's camera.yaml; docs/tracking.md step 6), and the filter is told so. The camera centre of
each frame comes from the sequence's groundtruth.txt.

Usage: scripts/filter_floor.py [--centre-sigma-m 0.01] [--accel-mps2 0.5]
                               [--start-velocity-sigma-mps 0.3] [--noise-seeds 5]
                               [--range-beyond-m 4.5 [--silhouette-px 1.5] [--stature-m 1.70]]
                               GT.jsonl...
"""
import argparse
import json
import math
import os
import statistics
import sys

import numpy as np


def load(path):
    try:
        with open(path) as f:
            return [json.loads(line) for line in f if line.strip()]
    except (OSError, json.JSONDecodeError) as e:
        sys.exit(f"filter_floor: cannot read {path}: {e}")


def camera_centres(gt_path):
    """Per frame, the camera centre (world) from groundtruth.txt beside objects_gt.jsonl."""
    path = os.path.join(os.path.dirname(gt_path) or ".", "groundtruth.txt")
    try:
        with open(path) as f:
            rows = [line.split() for line in f if line.strip() and not line.startswith("#")]
        return [np.array([float(r[1]), float(r[2]), float(r[3])]) for r in rows]
    except (OSError, ValueError, IndexError) as e:
        sys.exit(f"filter_floor: --range-beyond-m needs {path}: {e}")


def focal_px(gt_path):
    path = os.path.join(os.path.dirname(gt_path) or ".", "camera.yaml")
    try:
        with open(path) as f:
            for line in f:
                if line.startswith("fx:"):
                    return float(line.split(":")[1])
    except (OSError, ValueError) as e:
        sys.exit(f"filter_floor: --range-beyond-m needs {path}: {e}")
    sys.exit(f"filter_floor: no fx in {path}")


def speed_rmse(frames, sigma_m, accel, start_sigma, min_visible, seed, ranging=None,
               dt_s=1.0 / 30.0):
    """ranging: None, or (beyond_m, centres, focal_px, silhouette_px, stature_m)."""
    rng = np.random.default_rng(seed)
    tracks = {}
    squared, scored = 0.0, 0
    H = np.hstack([np.eye(3), np.zeros((3, 3))])
    for index, frame in enumerate(frames):
        for o in frame.get("objects", []):
            if o.get("class") != "person" or o.get("in_view", 0.0) < min_visible:
                continue
            p = np.array(o["position_world"])
            v = np.array(o["velocity_world"])
            z = p + rng.normal(0.0, sigma_m, 3)
            R = sigma_m**2 * np.eye(3)
            if ranging and index < len(ranging[1]):
                beyond_m, centres, f_px, px, stature_m = ranging
                ray = p - centres[index]
                r = np.linalg.norm(ray)
                if r > beyond_m:
                    ray /= r
                    sigma_r = math.sqrt(2.0) * px * r * r / (f_px * stature_m)
                    z = z + rng.normal(0.0, sigma_r) * ray
                    R = R + sigma_r**2 * np.outer(ray, ray)
            if o["id"] not in tracks:
                x = np.concatenate([z, v + rng.normal(0.0, start_sigma, 3)])
                P = np.zeros((6, 6))
                P[:3, :3] = R + 1e-12 * np.eye(3)
                P[3:, 3:] = max(start_sigma, 1e-3) ** 2 * np.eye(3)
            else:
                x, P, last = tracks[o["id"]]
                dt = (index - last) * dt_s
                F = np.eye(6)
                F[:3, 3:] = dt * np.eye(3)
                # Continuous white-noise acceleration, discretised as KalmanCv::processNoise does.
                Q = accel**2 * np.block([[dt**3 / 3 * np.eye(3), dt**2 / 2 * np.eye(3)],
                                         [dt**2 / 2 * np.eye(3), dt * np.eye(3)]])
                x = F @ x
                P = F @ P @ F.T + Q
                S = H @ P @ H.T + R + 1e-12 * np.eye(3)
                K = P @ H.T @ np.linalg.inv(S)
                x = x + K @ (z - H @ x)
                P = (np.eye(6) - K @ H) @ P
            tracks[o["id"]] = (x, P, index)
            truth = o["speed"]
            error = 0.0 if truth == 0.0 else np.linalg.norm(x[3:]) - truth
            squared += error * error
            scored += 1
    return math.sqrt(squared / scored) if scored else float("nan"), scored


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("gt", nargs="+", help="objects_gt.jsonl of simulated sequences")
    ap.add_argument("--centre-sigma-m", type=float, default=0.01)
    ap.add_argument("--accel-mps2", type=float, default=0.5)
    ap.add_argument("--start-velocity-sigma-mps", type=float, default=0.3)
    ap.add_argument("--noise-seeds", type=int, default=5)
    ap.add_argument("--min-visible", type=float, default=0.3)
    ap.add_argument("--range-beyond-m", type=float, default=0.0,
                    help="people farther than this are ranged by their height (0: never)")
    ap.add_argument("--silhouette-px", type=float, default=1.5)
    ap.add_argument("--stature-m", type=float, default=1.70)
    a = ap.parse_args()
    if a.centre_sigma_m < 0 or a.accel_mps2 <= 0 or a.noise_seeds < 1:
        sys.exit("filter_floor: sigma >= 0, accel > 0 and noise seeds >= 1 are required")
    for path in a.gt:
        frames = load(path)
        ranging = None
        if a.range_beyond_m > 0:
            ranging = (a.range_beyond_m, camera_centres(path), focal_px(path), a.silhouette_px,
                       a.stature_m)
        runs = [speed_rmse(frames, a.centre_sigma_m, a.accel_mps2, a.start_velocity_sigma_mps,
                           a.min_visible, seed, ranging) for seed in range(1, a.noise_seeds + 1)]
        rmses = [r for r, _ in runs]
        print(f"{path}: speed RMSE {statistics.median(rmses):.3f} m/s (median of "
              f"{a.noise_seeds} noise seeds, {min(rmses):.3f}-{max(rmses):.3f}; {runs[0][1]} "
              f"scored person-frames; centre sigma {a.centre_sigma_m} m, accel "
              f"{a.accel_mps2} m/s^2, start velocity sigma {a.start_velocity_sigma_mps} m/s"
              + (f", ranged beyond {a.range_beyond_m} m" if ranging else "") + ")")


if __name__ == "__main__":
    main()
