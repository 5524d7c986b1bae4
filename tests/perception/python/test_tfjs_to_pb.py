"""tools/tfjs_to_pb on a tiny TF.js graph model made here (float32, float16 and uint8-quantised
weights, two shards, fused ops, a feed and a cut): OpenCV 4.6 loads the .pb and gives numpy's
answer; the output is byte-for-byte reproducible; bad input is refused. Label unit."""

import pathlib
import subprocess
import sys
import tempfile
import unittest

from tfjs_fixture import CONVERTER, need_numpy_cv2, reference_forward, write_tiny_model

need_numpy_cv2()
import cv2  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(CONVERTER.parent))
import tfjs_to_pb  # noqa: E402

CUT = ["--feed", "pre", "--feed-shape", "1,8,8,3", "--outputs", "out"]


def run(*args):
    return subprocess.run([sys.executable, str(CONVERTER), *map(str, args)], capture_output=True, text=True)


class TinyGraph(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.tmp.name)
        self.weights = write_tiny_model(self.dir, np.random.default_rng(7))
        self.model = self.dir / "model.json"

    def tearDown(self):
        self.tmp.cleanup()

    def test_opencv_gives_the_reference_output(self):
        pb = self.dir / "tiny.pb"
        r = run(self.model, pb, *CUT)
        self.assertEqual(r.returncode, 0, r.stderr)
        net = cv2.dnn.readNetFromTensorflow(str(pb))
        x = np.random.default_rng(1).uniform(0, 1, (1, 8, 8, 3)).astype(np.float32)
        net.setInput(x.transpose(0, 3, 1, 2).copy())  # OpenCV takes NCHW
        got = net.forward("out")
        want = reference_forward(x, self.weights).transpose(0, 3, 1, 2)
        self.assertEqual(got.shape, (1, 4, 6, 6))
        self.assertLess(float(np.abs(got - want).max()), 1e-5)

    def test_output_is_deterministic(self):
        a, b = self.dir / "a.pb", self.dir / "b.pb"
        self.assertEqual(run(self.model, a, *CUT).returncode, 0)
        self.assertEqual(run(self.model, b, *CUT).returncode, 0)
        self.assertEqual(a.read_bytes(), b.read_bytes())

    def test_weights_are_dequantised(self):
        import json
        model = json.loads(self.model.read_text())
        values = tfjs_to_pb.read_weights(self.model, model["weightsManifest"])
        self.assertEqual(values["w1"].dtype, np.float32)
        np.testing.assert_array_equal(values["w1"], self.weights["w1"])  # float16 → float32 exactly
        np.testing.assert_allclose(values["dw"], self.weights["dw"], rtol=0, atol=1e-7)
        self.assertEqual(int(values["post/axis"]), 3)

    def test_fused_ops_are_split_and_the_cut_drops_what_opencv_cannot_read(self):
        model = __import__("json").loads(self.model.read_text())
        kept = tfjs_to_pb.rewrite(model["modelTopology"]["node"], {"pre": [1, 8, 8, 3]}, ["out"])
        names = {n["name"]: n["op"] for n in kept}
        self.assertEqual(names["conv1/Relu/_base"], "Conv2D")
        self.assertEqual(names["conv1/Relu/_bias"], "BiasAdd")
        self.assertEqual(names["conv1/Relu"], "Relu")
        self.assertEqual(names["dw/Relu6/_base"], "DepthwiseConv2dNative")
        self.assertEqual(names["pre"], "Placeholder")
        for gone in ("post", "cast", "input", "pre/y"):
            self.assertNotIn(gone, names)
        self.assertFalse(any(i.startswith("^") for n in kept for i in n["input"]))

    def test_bad_input_is_refused(self):
        r = run(self.model, self.dir / "x.pb", "--outputs", "no_such_node")
        self.assertEqual(r.returncode, 1)
        self.assertIn("no_such_node", r.stderr)
        (self.dir / "group1-shard2of2.bin").write_bytes(b"\0" * 3)  # truncated shard
        r = run(self.model, self.dir / "y.pb", *CUT)
        self.assertEqual(r.returncode, 1)
        self.assertIn("shards", r.stderr)
        self.assertFalse((self.dir / "y.pb").exists())


if __name__ == "__main__":
    unittest.main()
