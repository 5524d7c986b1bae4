#!/usr/bin/env python3
"""Converts a TF.js graph model (model.json + .bin shards) to a frozen TensorFlow GraphDef (.pb)
that OpenCV 4.6's DNN module reads (cv::dnn::readNetFromTensorflow).

    tfjs_to_pb.py MODEL_JSON OUT_PB [--feed NODE --feed-shape N,H,W,C] [--outputs A,B,...]

What it does to the graph, nothing more:
  * Const nodes get their values from the weight shards; quantised weights (float16, or uint8 /
    uint16 with min and scale) become float32 (OpenCV reads float32 weights best).
  * TF.js's fused ops (_FusedConv2D, FusedDepthwiseConv2dNative, _FusedMatMul) are split back
    into TensorFlow's plain ops: the convolution is named "<node>/_base", a BiasAdd followed by an
    activation "<node>/_bias", and the last op of the chain keeps "<node>" so consumers stay wired.
  * --feed replaces a node by a float Placeholder (cuts off in-graph pre-processing OpenCV cannot
    import); --outputs keeps only what the named nodes need (cuts off post-processing). Control
    inputs ("^node") are dropped: a frozen inference graph does not need them.
Output bytes depend only on the input files and arguments (see wire.py), so a SHA-256 can be pinned.
Needs only Python 3 and numpy (Debian: python3-numpy).
"""

import argparse
import base64
import json
import math
import pathlib
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import wire  # noqa: E402

NP_DTYPES = {"float32": np.float32, "int32": np.int32, "bool": np.bool_, "uint8": np.uint8,
             "int64": np.int64, "float16": np.float16, "uint16": np.uint16}
DT_OF = {"float32": "DT_FLOAT", "int32": "DT_INT32", "bool": "DT_BOOL", "uint8": "DT_UINT8",
         "int64": "DT_INT64", "string": "DT_STRING", "float16": "DT_HALF", "uint16": "DT_UINT16"}


class ConversionError(Exception):
    pass


# ---------------------------------------------------------------------------------------------
# Weights


def read_weights(model_json: pathlib.Path, manifest) -> dict:
    """name -> numpy array (or list of bytes for strings), de-quantised to the original dtype."""
    values = {}
    for group in manifest:
        data = b"".join((model_json.parent / p).read_bytes() for p in group["paths"])
        offset = 0
        for w in group["weights"]:
            dims = [int(d) for d in w["shape"]]
            count = int(np.prod(dims)) if dims else 1
            q = w.get("quantization")
            if w["dtype"] == "string":
                strings = []
                for _ in range(count):
                    (n,) = np.frombuffer(data, "<u4", 1, offset)
                    strings.append(data[offset + 4:offset + 4 + int(n)])
                    offset += 4 + int(n)
                values[w["name"]] = strings
                continue
            stored = np.dtype(NP_DTYPES[q["dtype"] if q else w["dtype"]]).newbyteorder("<")
            if offset + count * stored.itemsize > len(data):
                raise ConversionError(f"weight {w['name']} runs past the end of the shards {group['paths']}")
            if q:
                raw = np.frombuffer(data, stored, count, offset)
                offset += count * stored.itemsize
                if q["dtype"] == "float16":
                    arr = raw.astype(np.float32)
                else:  # affine uint8 / uint16: value = q * scale + min
                    arr = (raw.astype(np.float32) * np.float32(q["scale"]) +
                           np.float32(q["min"])).astype(np.float32)
                arr = arr.astype(NP_DTYPES[q.get("original_dtype", w["dtype"])])
            else:
                arr = np.frombuffer(data, stored, count, offset).copy()
                offset += count * stored.itemsize
            values[w["name"]] = arr.reshape(dims)
        if offset != len(data):
            raise ConversionError(f"shards {group['paths']} hold {len(data)} bytes, manifest {offset}")
    return values


# ---------------------------------------------------------------------------------------------
# Graph rewriting (nodes are dicts: name, op, input, attr in TF.js's JSON AttrValue form)

CONV_OF_FUSED = {"_FusedConv2D": "Conv2D", "FusedDepthwiseConv2dNative": "DepthwiseConv2dNative",
                 "_FusedMatMul": "MatMul"}
CONV_ATTRS = {"Conv2D": ("T", "strides", "padding", "data_format", "dilations",
                         "explicit_paddings", "use_cudnn_on_gpu"),
              "DepthwiseConv2dNative": ("T", "strides", "padding", "data_format", "dilations",
                                        "explicit_paddings"),
              "MatMul": ("T", "transpose_a", "transpose_b")}
ACTIVATIONS = ("Relu", "Relu6", "Elu", "Sigmoid", "Tanh", "LeakyRelu")


def unfuse(n) -> list:
    """A fused TF.js node as the chain of plain TensorFlow nodes it stands for."""
    conv_op = CONV_OF_FUSED[n["op"]]
    attr = n.get("attr", {})
    fused = [base64.b64decode(s).decode() for s in attr.get("fused_ops", {}).get("list", {}).get("s", [])]
    num_args = int(attr.get("num_args", {}).get("i", "0"))
    inputs = [i for i in n["input"] if not i.startswith("^")]
    x, weights, args = inputs[0], inputs[1], inputs[2:2 + num_args]
    t = attr.get("T", {"type": "DT_FLOAT"})
    data_format = attr.get("data_format", {"s": base64.b64encode(b"NHWC").decode()})
    name = n["name"]
    chain = [{"name": name + "/_base" if fused else name, "op": conv_op, "input": [x, weights],
              "attr": {k: attr[k] for k in CONV_ATTRS[conv_op] if k in attr}}]
    for k, op in enumerate(fused):
        prev = chain[-1]["name"]
        last = k == len(fused) - 1
        if op == "BiasAdd":
            a = {"T": t} if conv_op == "MatMul" else {"T": t, "data_format": data_format}
            chain.append({"name": name if last else name + "/_bias", "op": "BiasAdd",
                          "input": [prev, args[0]], "attr": a})
        elif op in ("FusedBatchNorm", "FusedBatchNormV3"):
            if len(args) < 4:
                raise ConversionError(f"{name}: FusedBatchNorm needs 4 arguments, has {len(args)}")
            chain.append({"name": name if last else name + "/_bn", "op": "FusedBatchNormV3",
                          "input": [prev] + args[:4],
                          "attr": {"T": t, "U": {"type": "DT_FLOAT"}, "data_format": data_format,
                                   "epsilon": attr.get("epsilon", {"f": 0.001}),
                                   "is_training": {"b": False}}})
        elif op in ACTIVATIONS:
            a = {"T": t}
            if op == "LeakyRelu":
                a["alpha"] = attr.get("leakyrelu_alpha", {"f": 0.2})
            chain.append({"name": name if last else f"{name}/_{op.lower()}", "op": op,
                          "input": [prev], "attr": a})
        else:
            raise ConversionError(f"{name}: fused op {op!r} is not supported")
    return chain


def base_name(inp: str) -> str:
    return inp.lstrip("^").split(":")[0]


def rewrite(nodes, feeds, outputs):
    """Unfuse, apply feeds, drop control inputs, keep only what `outputs` need (in file order)."""
    plain = []
    for n in nodes:
        plain.extend(unfuse(n) if n["op"] in CONV_OF_FUSED else [dict(n)])
    by_name = {n["name"]: n for n in plain}
    for name, dims in feeds.items():
        if name not in by_name:
            raise ConversionError(f"--feed {name}: no such node")
        by_name[name].update(op="Placeholder", input=[],
                             attr={"dtype": {"type": "DT_FLOAT"},
                                   "shape": {"shape": {"dim": [{"size": str(d)} for d in dims]}}})
    for n in plain:
        n["input"] = [i for i in n.get("input", []) if not i.startswith("^")]
    missing = [o for o in outputs if o not in by_name]
    if missing:
        raise ConversionError(f"--outputs: no node named {', '.join(missing)}")
    needed, stack = set(), list(outputs)
    while stack:
        name = stack.pop()
        if name in needed:
            continue
        needed.add(name)
        if name not in by_name:
            raise ConversionError(f"node {name} is used but not defined")
        stack.extend(base_name(i) for i in by_name[name]["input"])
    return [n for n in plain if n["name"] in needed]


def default_outputs(model, nodes):
    sig = model.get("signature", {}).get("outputs", {})
    if sig:
        return sorted({base_name(v.get("name", k)) for k, v in sig.items()})
    used = {base_name(i) for n in nodes for i in n.get("input", [])}
    return [n["name"] for n in nodes if n["name"] not in used and n["op"] != "Const"]


# ---------------------------------------------------------------------------------------------
# Encoding


def json_shape(s):
    dims = [int(d.get("size", "0")) for d in s.get("dim", [])]
    return wire.shape(dims, bool(s.get("unknownRank", False)))


def json_float(v) -> float:
    return {"NaN": math.nan, "Infinity": math.inf, "-Infinity": -math.inf}.get(v, v) \
        if isinstance(v, str) else float(v)


def const_tensor(name, attr_json, values):
    """Encoded TensorProto of a Const: from the weights, else from values written in the JSON."""
    t = attr_json.get("tensor", {})
    if name in values:
        v = values[name]
        if isinstance(v, list):  # strings
            return "DT_STRING", wire.tensor("DT_STRING", [len(v)] if len(v) != 1 else [], string_val=v)
        dt = DT_OF[str(v.dtype)]
        if dt == "DT_INT32" and v.size == 1:
            # As TensorFlow itself writes small constants; OpenCV reads e.g. ConcatV2's axis
            # only from int_val (an empty int_val crashes its importer).
            return dt, wire.tensor(dt, list(v.shape), int_val=[int(v.ravel()[0])])
        return dt, wire.tensor(dt, list(v.shape), content=v.astype(v.dtype.newbyteorder("<")).tobytes())
    dims = [int(d.get("size", "0")) for d in t.get("tensorShape", {}).get("dim", [])]
    return t.get("dtype", "DT_FLOAT"), wire.tensor(
        t.get("dtype", "DT_FLOAT"), dims,
        content=base64.b64decode(t.get("tensorContent", "")),
        float_val=[json_float(f) for f in t.get("floatVal", [])],
        int_val=[int(i) for i in t.get("intVal", [])],
        int64_val=[int(i) for i in t.get("int64Val", [])],
        bool_val=t.get("boolVal", []),
        string_val=[base64.b64decode(s) for s in t.get("stringVal", [])])


def encode_attr(a) -> wire.Attr:
    if "list" in a:
        lst = a["list"]
        return wire.Attr.list(s=[base64.b64decode(x) for x in lst.get("s", [])],
                              i=[int(x) for x in lst.get("i", [])],
                              f=[json_float(x) for x in lst.get("f", [])],
                              b=lst.get("b", []), type=lst.get("type", []),
                              shapes=[json_shape(x) for x in lst.get("shape", [])])
    if "s" in a:
        return wire.Attr.s(base64.b64decode(a["s"]))
    if "i" in a:
        return wire.Attr.i(int(a["i"]))
    if "f" in a:
        return wire.Attr.f(json_float(a["f"]))
    if "b" in a:
        return wire.Attr.b(bool(a["b"]))
    if "type" in a:
        return wire.Attr.type(a["type"])
    if "shape" in a:
        return wire.Attr(wire.f_bytes(7, json_shape(a["shape"])))
    if not a:  # an empty AttrValue (e.g. an empty list written as {})
        return wire.Attr(b"")
    raise ConversionError(f"attribute kind {sorted(a)} is not supported")


def encode_node(n, values) -> bytes:
    attrs = {}
    for k, a in n.get("attr", {}).items():
        if n["op"] == "Const" and k == "value":
            dt, enc = const_tensor(n["name"], a, values)
            attrs["value"] = wire.Attr.tensor(enc)
            attrs["dtype"] = wire.Attr.type(dt)
        elif not (n["op"] == "Const" and k == "dtype"):
            attrs[k] = encode_attr(a)
    return wire.node(n["name"], n["op"], n["input"], attrs)


def convert(model_json, feeds=None, outputs=None) -> bytes:
    model_json = pathlib.Path(model_json)
    model = json.loads(model_json.read_text())
    if model.get("format") not in (None, "graph-model"):
        raise ConversionError(f"{model_json}: format {model.get('format')!r} is not a graph model")
    topology = model["modelTopology"]
    if topology.get("library", {}).get("function"):
        raise ConversionError(f"{model_json}: graphs with functions (control flow) are not supported")
    values = read_weights(model_json, model["weightsManifest"])
    nodes = topology["node"]
    outputs = outputs or default_outputs(model, nodes)
    kept = rewrite(nodes, feeds or {}, outputs)
    producer = int(topology.get("versions", {}).get("producer", 1))
    return wire.graph([encode_node(n, values) for n in kept], producer)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("model_json")
    p.add_argument("out_pb")
    p.add_argument("--feed", action="append", default=[], help="node to replace by a Placeholder")
    p.add_argument("--feed-shape", action="append", default=[], help="its shape, e.g. 1,192,192,3")
    p.add_argument("--outputs", default="", help="comma-separated output nodes (default: signature)")
    args = p.parse_args(argv)
    if len(args.feed) != len(args.feed_shape):
        p.error("give one --feed-shape per --feed")
    feeds = {f: [int(d) for d in s.split(",")] for f, s in zip(args.feed, args.feed_shape)}
    outputs = [o for o in args.outputs.split(",") if o]
    try:
        data = convert(args.model_json, feeds, outputs)
    except (ConversionError, OSError, KeyError, ValueError) as e:
        print(f"tfjs_to_pb: {e}", file=sys.stderr)
        return 1
    out = pathlib.Path(args.out_pb)
    tmp = out.with_name(out.name + ".tmp")
    tmp.write_bytes(data)
    tmp.replace(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
