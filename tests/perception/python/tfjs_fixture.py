"""Helpers of the Python tests: a tiny TF.js graph model written by the test itself, and skips."""

import base64
import json
import os
import pathlib
import sys

SKIP = 77  # ctest SKIP_RETURN_CODE

REPO = pathlib.Path(__file__).resolve().parents[3]
CONVERTER = REPO / "tools" / "tfjs_to_pb" / "tfjs_to_pb.py"


def skip(why: str):
    print(f"SKIPPED: {why}")
    sys.exit(SKIP)


def need_numpy_cv2():
    try:
        import cv2  # noqa: F401
        import numpy  # noqa: F401
    except ImportError as e:
        skip(f"{e.name} is missing (Debian: python3-numpy python3-opencv)")


def shared_dir() -> pathlib.Path:
    return pathlib.Path(os.environ.get("DYNANAV_SHARED_DIR", REPO.parent / "shared"))


def b64(text: str) -> str:
    return base64.b64encode(text.encode()).decode()


def ints(values):
    return {"list": {"i": [str(v) for v in values]}}


def write_tiny_model(folder: pathlib.Path, rng):
    """Writes model.json + two .bin shards; returns the float32 weights the graph should use.

    int32 input → Cast → Mul(1/255) "pre" → _FusedConv2D 3x3 SAME (+BiasAdd, Relu; float16
    weights) → FusedDepthwiseConv2dNative 3x3 VALID (+BiasAdd, Relu6; uint8-quantised weights)
    → Mul per channel → Sigmoid "out" → ArgMax "post" (which OpenCV cannot import).
    """
    import numpy as np

    w1 = rng.normal(0, 0.5, (3, 3, 3, 4)).astype(np.float16)
    b1 = rng.normal(0, 0.1, 4).astype(np.float32)
    dw_q = rng.integers(0, 256, (3, 3, 4, 1)).astype(np.uint8)
    dw_min, dw_scale = -0.6, 1.2 / 255
    b2 = rng.normal(0, 0.1, 4).astype(np.float16)
    gain = np.array([0.5, 1.0, 1.5, -2.0], np.float32)
    weights = [  # name, array as stored, dtype, quantization
        ("pre/y", np.array(1 / 255, np.float32), "float32", None),
        ("w1", w1, "float32", {"dtype": "float16", "original_dtype": "float32"}),
        ("b1", b1, "float32", None),
        ("dw", dw_q, "float32", {"dtype": "uint8", "min": dw_min, "scale": dw_scale,
                                 "original_dtype": "float32"}),
        ("b2", b2, "float32", {"dtype": "float16", "original_dtype": "float32"}),
        ("gain", gain, "float32", None),
        ("post/axis", np.array(3, np.int32), "int32", None),
    ]
    data = b"".join(a.tobytes() for _, a, _, _ in weights)
    cut = len(data) // 2  # two shards, split mid-weight on purpose
    (folder / "group1-shard1of2.bin").write_bytes(data[:cut])
    (folder / "group1-shard2of2.bin").write_bytes(data[cut:])
    manifest = [{"paths": ["group1-shard1of2.bin", "group1-shard2of2.bin"], "weights": [
        dict({"name": n, "shape": list(a.shape), "dtype": dt}, **({"quantization": q} if q else {}))
        for n, a, dt, q in weights]}]

    def const(name, dtype):
        return {"name": name, "op": "Const",
                "attr": {"dtype": {"type": dtype}, "value": {"tensor": {"dtype": dtype}}}}

    f32 = {"type": "DT_FLOAT"}
    conv_attr = {"T": f32, "strides": ints([1, 1, 1, 1]), "dilations": ints([1, 1, 1, 1]),
                 "data_format": {"s": b64("NHWC")}, "num_args": {"i": "1"}, "epsilon": {"f": 0},
                 "explicit_paddings": {"list": {}}}
    nodes = [
        {"name": "input", "op": "Placeholder", "attr": {
            "dtype": {"type": "DT_INT32"},
            "shape": {"shape": {"dim": [{"size": "1"}, {"size": "8"}, {"size": "8"}, {"size": "3"}]}}}},
        {"name": "cast", "op": "Cast", "input": ["input"],
         "attr": {"SrcT": {"type": "DT_INT32"}, "DstT": f32, "Truncate": {"b": False}}},
        const("pre/y", "DT_FLOAT"),
        {"name": "pre", "op": "Mul", "input": ["cast", "pre/y"], "attr": {"T": f32}},
        const("w1", "DT_FLOAT"), const("b1", "DT_FLOAT"),
        {"name": "conv1/Relu", "op": "_FusedConv2D", "input": ["pre", "w1", "b1"],
         "attr": dict(conv_attr, padding={"s": b64("SAME")}, use_cudnn_on_gpu={"b": True},
                      fused_ops={"list": {"s": [b64("BiasAdd"), b64("Relu")]}})},
        const("dw", "DT_FLOAT"), const("b2", "DT_FLOAT"),
        {"name": "dw/Relu6", "op": "FusedDepthwiseConv2dNative", "input": ["conv1/Relu", "dw", "b2", "^pre"],
         "attr": dict(conv_attr, padding={"s": b64("VALID")},
                      fused_ops={"list": {"s": [b64("BiasAdd"), b64("Relu6")]}})},
        const("gain", "DT_FLOAT"),
        {"name": "scaled", "op": "Mul", "input": ["dw/Relu6", "gain"], "attr": {"T": f32}},
        {"name": "out", "op": "Sigmoid", "input": ["scaled"], "attr": {"T": f32}},
        const("post/axis", "DT_INT32"),
        {"name": "post", "op": "ArgMax", "input": ["out", "post/axis"],
         "attr": {"T": f32, "Tidx": {"type": "DT_INT32"}, "output_type": {"type": "DT_INT64"}}},
    ]
    model = {"format": "graph-model", "generatedBy": "dynanav test", "convertedBy": "hand",
             "signature": {"outputs": {"post:0": {"name": "post:0"}}},
             "modelTopology": {"node": nodes, "library": {}, "versions": {"producer": 1}},
             "weightsManifest": manifest}
    (folder / "model.json").write_text(json.dumps(model))
    dw = (dw_q.astype(np.float32) * np.float32(dw_scale) + np.float32(dw_min)).astype(np.float32)
    return {"w1": w1.astype(np.float32), "b1": b1, "dw": dw, "b2": b2.astype(np.float32), "gain": gain}


def reference_forward(x, w):
    """numpy forward of the tiny graph on float NHWC input x (after "pre")."""
    import numpy as np

    def conv(inp, k, depthwise=False):
        kh, kw = k.shape[:2]
        n, h, wd, c = inp.shape
        oh, ow = h - kh + 1, wd - kw + 1
        out = np.zeros((n, oh, ow, k.shape[2] if depthwise else k.shape[3]), np.float64)
        for dy in range(kh):
            for dx in range(kw):
                patch = inp[:, dy:dy + oh, dx:dx + ow, :].astype(np.float64)
                out += patch * k[dy, dx, :, 0] if depthwise else patch @ k[dy, dx].astype(np.float64)
        return out

    y = conv(np.pad(x, ((0, 0), (1, 1), (1, 1), (0, 0))), w["w1"]) + w["b1"]
    y = np.maximum(y, 0)
    y = np.clip(conv(y, w["dw"], depthwise=True) + w["b2"], 0, 6) * w["gain"]
    return 1 / (1 + np.exp(-y))
