#!/usr/bin/env python3
"""How far a nearer walker's motion leaks into the shared dense flow of the walker behind it
(docs/tracking.md "Session 31"), on a simulated sequence with two people and exact ground truth.

The flow is computed as FramePrep computes the shared flow (OpenCV's DIS, ultrafast preset,
half-size greyscale images, finest scale 1, 8 px patches). For each listed frame t and the next,
every third pixel of the farther person's mask with depth (the person with the larger median
depth) gets its true image motion from the camera poses (groundtruth.txt), its depth and the
person's true velocity (objects_gt.jsonl), and the flow there; the nearer person's flow is read at
its mask pixel nearest to that one. Printed per band of distance to the nearer person's mask
(medians, px per frame): flow - truth, flow - the nearer person's flow there, truth - the nearer
person's flow. Expects the simulator's pinhole camera without distortion (camera.yaml).

Usage: dynanav simulate --scenario head-turns-walkers --seed 1 --out SEQ
       python3 scripts/flow_leak.py SEQ 2.133333,2.166667,2.2,2.233333,2.266667,2.3,2.333333
"""
import json
import sys

import cv2
import numpy as np


def read_camera(seq):
    values = {}
    for line in open(seq + '/camera.yaml'):
        key, _, value = line.partition(':')
        values[key.strip()] = value.split('#')[0].strip()
    return (float(values['fx']), float(values['fy']), float(values['cx']), float(values['cy']),
            float(values.get('depth_factor', 5000)))


def read_poses(seq):
    poses = {}
    for line in open(seq + '/groundtruth.txt'):
        if line.startswith('#') or not line.strip():
            continue
        v = [float(x) for x in line.split()]
        tx, ty, tz, qx, qy, qz, qw = v[1:8]
        R = np.array([[1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
                      [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
                      [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)]])
        T = np.eye(4)
        T[:3, :3] = R
        T[:3, 3] = [tx, ty, tz]
        poses[v[0]] = T
    return poses


def read_objects(seq):
    """objects_gt.jsonl as {stamp: {id: object}}."""
    objects = {}
    for line in open(seq + '/objects_gt.jsonl'):
        d = json.loads(line)
        objects[d['t']] = {o['id']: o for o in d['objects']}
    return objects


def nearest(stamped, t):
    return stamped[min(stamped, key=lambda s: abs(s - t))]


def image_name(seq, folder, t):
    # The simulator names frames by their stamp at 30 frames per second.
    return '%s/%s/%.6f.png' % (seq, folder, round(t * 30) / 30)


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    seq, stamps = sys.argv[1], [float(x) for x in sys.argv[2].split(',')]
    fx, fy, cx, cy, depth_factor = read_camera(seq)
    poses = read_poses(seq)
    objects = read_objects(seq)
    dis = cv2.DISOpticalFlow_create(cv2.DISOpticalFlow_PRESET_ULTRAFAST)
    dis.setFinestScale(1)
    dis.setPatchSize(8)
    bands = [0, 8, 16, 24, 32, 48, 64, 100000]
    rows = {b: [] for b in bands[:-1]}
    for t0 in stamps:
        t1 = t0 + 1.0 / 30.0
        grey = [cv2.cvtColor(cv2.imread(image_name(seq, 'rgb', t)), cv2.COLOR_BGR2GRAY) for t in (t0, t1)]
        half = [cv2.resize(g, None, fx=0.5, fy=0.5, interpolation=cv2.INTER_AREA) for g in grey]
        flow = dis.calc(half[0], half[1], None)
        labels = cv2.imread(image_name(seq, 'masks', t0), cv2.IMREAD_UNCHANGED)
        depth = cv2.imread(image_name(seq, 'depth', t0), cv2.IMREAD_UNCHANGED).astype(np.float64) / depth_factor
        ids = [i for i in np.unique(labels) if i != 0 and ((labels == i) & (depth > 0)).sum() > 50]
        if len(ids) < 2:
            continue
        median_z = {i: np.median(depth[(labels == i) & (depth > 0)]) for i in ids}
        far, near = sorted(ids, key=lambda i: -median_z[i])[:2]
        distance, label = cv2.distanceTransformWithLabels((labels != near).astype(np.uint8), cv2.DIST_L2, 5,
                                                          labelType=cv2.DIST_LABEL_PIXEL)
        pixel_of_label = {label[y, x]: (y, x) for (y, x) in np.argwhere(labels == near)}
        T_world_cam0 = nearest(poses, t0)
        T_cam1_world = np.linalg.inv(nearest(poses, t1))
        velocity = np.array(nearest(objects, t0)[int(far)]['velocity_world'])

        def flow_at(y, x):
            return 2.0 * flow[min(y // 2, flow.shape[0] - 1), min(x // 2, flow.shape[1] - 1)]

        ys, xs = np.nonzero((labels == far) & (depth > 0))
        for y, x in zip(ys[::3], xs[::3]):
            z = depth[y, x]
            p_world = T_world_cam0 @ np.array([(x - cx) / fx * z, (y - cy) / fy * z, z, 1.0])
            p_world[:3] += velocity / 30.0
            q = T_cam1_world @ p_world
            truth = np.array([fx * q[0] / q[2] + cx - x, fy * q[1] / q[2] + cy - y])
            f = flow_at(y, x)
            f_near = flow_at(*pixel_of_label.get(label[y, x], (y, x)))
            for low, high in zip(bands[:-1], bands[1:]):
                if low <= distance[y, x] < high:
                    rows[low].append((np.linalg.norm(f - truth), np.linalg.norm(f - f_near),
                                      np.linalg.norm(truth - f_near)))
    print('| distance to the nearer person | points | flow - truth | flow - nearer flow | truth - nearer flow |')
    print('|---|---|---|---|---|')
    for low, high in zip(bands[:-1], bands[1:]):
        v = np.array(rows[low])
        if len(v):
            band = '%d-%d px' % (low, high) if high < 100000 else 'beyond %d px' % low
            print('| %s | %d | %.2f | %.2f | %.2f |' % (band, len(v), *np.median(v, axis=0)))
    return 0


if __name__ == '__main__':
    sys.exit(main())
