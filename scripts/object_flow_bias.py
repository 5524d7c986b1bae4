#!/usr/bin/env python3
"""How much the shared dense flow under-reads each person's own image motion, and how much a flow
of the person alone does (docs/tracking.md "Session 33"), on a simulated sequence with exact
ground truth.

For every pair of consecutive frames and every person with at least 400 mask pixels with depth,
the pixels of the mask's trunk band (25-55 % of its height from the top, every second one) get
their true image motion from the camera poses (groundtruth.txt), their depth and the person's true
velocity (objects_gt.jsonl: a rigid translation, so a gait's swing is not in it) and the motion
the camera alone would give them; the person's own image motion is the difference, and each
flow's error is measured along it (negative: under-read). Two flows, both as FramePrep computes
the shared one (OpenCV's DIS, ultrafast preset, half-size greyscale images, finest scale 1, 8 px
patches): "shared", the whole images; "own", the whole images with every pixel off the person's
mask in each frame set to one grey 64 levels from the person's mean brightness (the idea of
dynamics/object_flow.hpp, without its crop, shift and nearer surfaces). Pairs where the person's
own motion is under 1 px are skipped. Printed per person: pairs, median own motion (px per frame),
median and mean error along it (px), median error as a share of the own motion. Expects the
simulator's pinhole camera without distortion (camera.yaml).

Usage: dynanav simulate --scenario office --seed 1 --frames 240 --out SEQ
       python3 scripts/object_flow_bias.py SEQ
"""
import os
import sys

import cv2
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from flow_leak import image_name, nearest, read_camera, read_objects, read_poses  # noqa: E402


def shared_flow_dis():
    dis = cv2.DISOpticalFlow_create(cv2.DISOpticalFlow_PRESET_ULTRAFAST)
    dis.setFinestScale(1)
    dis.setPatchSize(8)
    return dis


def half(grey):
    return cv2.resize(grey, None, fx=0.5, fy=0.5, interpolation=cv2.INTER_AREA)


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    seq = sys.argv[1]
    fx, fy, cx, cy, depth_factor = read_camera(seq)
    poses = read_poses(seq)
    objects = read_objects(seq)
    stamps = sorted(objects)

    def load(t):
        grey = cv2.cvtColor(cv2.imread(image_name(seq, 'rgb', t)), cv2.COLOR_BGR2GRAY)
        return grey, cv2.imread(image_name(seq, 'masks', t), cv2.IMREAD_UNCHANGED)

    rows = {'shared': {}, 'own': {}}
    for t0, t1 in zip(stamps[:-1], stamps[1:]):
        g0, m0 = load(t0)
        g1, m1 = load(t1)
        depth = cv2.imread(image_name(seq, 'depth', t0), cv2.IMREAD_UNCHANGED).astype(np.float64) / depth_factor
        ids = [i for i in np.unique(m0) if i != 0 and ((m0 == i) & (depth > 0)).sum() > 400]
        if not ids:
            continue
        T_world_cam0 = nearest(poses, t0)
        T_cam1_world = np.linalg.inv(nearest(poses, t1))
        shared = shared_flow_dis().calc(half(g0), half(g1), None)
        for i in ids:
            if objects[t0].get(int(i), {}).get('class') != 'person':
                continue
            ys, xs = np.nonzero((m0 == i) & (depth > 0))
            top, height = ys.min(), ys.max() - ys.min()
            band = (ys > top + 0.25 * height) & (ys < top + 0.55 * height)
            ys, xs = ys[band][::2], xs[band][::2]
            if len(ys) < 50:
                continue
            z = depth[ys, xs]
            p_world = T_world_cam0 @ np.stack([(xs - cx) / fx * z, (ys - cy) / fy * z, z, np.ones_like(z)])

            def image_motion(p):
                q = T_cam1_world @ p
                return np.stack([fx * q[0] / q[2] + cx - xs, fy * q[1] / q[2] + cy - ys], 1)

            moved = p_world.copy()
            moved[:3] += np.array(objects[t0][int(i)]['velocity_world'])[:, None] / 30.0
            truth = image_motion(moved)
            own_motion = (truth - image_motion(p_world)).mean(0)
            norm = np.linalg.norm(own_motion)
            if norm < 1.0:
                continue
            along = own_motion / norm
            mean = g0[m0 == i].mean()
            fill = mean + 64 if mean < 128 else mean - 64
            a, b = g0.copy(), g1.copy()
            a[m0 != i] = fill
            b[m1 != i] = fill
            flows = {'shared': shared, 'own': shared_flow_dis().calc(half(a), half(b), None)}
            for name, flow in flows.items():
                f = 2.0 * flow[np.minimum(ys // 2, flow.shape[0] - 1), np.minimum(xs // 2, flow.shape[1] - 1)]
                rows[name].setdefault(int(i), []).append((norm, float(((f - truth) @ along).mean())))
    print('| flow | person | pairs | own motion (px) | error along it, median / mean (px) | share |')
    print('|---|---|---|---|---|---|')
    for name in ('shared', 'own'):
        for i, r in sorted(rows[name].items()):
            r = np.array(r)
            print('| %s | %d | %d | %.2f | %+.2f / %+.2f | %+.3f |' % (
                name, i, len(r), np.median(r[:, 0]), np.median(r[:, 1]), r[:, 1].mean(),
                np.median(r[:, 1] / r[:, 0])))
    return 0


if __name__ == '__main__':
    sys.exit(main())
