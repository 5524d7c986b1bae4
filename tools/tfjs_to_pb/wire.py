"""Protocol-buffer wire encoding of the few TensorFlow messages a frozen graph needs.

Hand-written so the converter needs no protoc and no generated code, and so the bytes depend on
nothing but the input: fields are written in field-number order, map entries (NodeDef.attr) in
key order, packed repeated scalars as one length-delimited field. Field numbers are those of
tensorflow/core/framework/{graph,node_def,attr_value,tensor,tensor_shape,types,versions}.proto.
"""

import struct

# tensorflow.DataType (types.proto)
DTYPES = {
    "DT_INVALID": 0, "DT_FLOAT": 1, "DT_DOUBLE": 2, "DT_INT32": 3, "DT_UINT8": 4, "DT_INT16": 5,
    "DT_INT8": 6, "DT_STRING": 7, "DT_COMPLEX64": 8, "DT_INT64": 9, "DT_BOOL": 10, "DT_QINT8": 11,
    "DT_QUINT8": 12, "DT_QINT32": 13, "DT_BFLOAT16": 14, "DT_QINT16": 15, "DT_QUINT16": 16,
    "DT_UINT16": 17, "DT_COMPLEX128": 18, "DT_HALF": 19, "DT_RESOURCE": 20, "DT_VARIANT": 21,
    "DT_UINT32": 22, "DT_UINT64": 23,
}

VARINT, FIXED64, BYTES, FIXED32 = 0, 1, 2, 5


def varint(value: int) -> bytes:
    """Base-128 varint; negative numbers as their 64-bit two's complement (int64 semantics)."""
    if value < 0:
        value += 1 << 64
    out = bytearray()
    while True:
        low = value & 0x7F
        value >>= 7
        if value:
            out.append(low | 0x80)
        else:
            out.append(low)
            return bytes(out)


def key(field: int, wire_type: int) -> bytes:
    return varint((field << 3) | wire_type)


def f_varint(field: int, value: int) -> bytes:
    return key(field, VARINT) + varint(int(value))


def f_bytes(field: int, data: bytes) -> bytes:
    return key(field, BYTES) + varint(len(data)) + data


def f_str(field: int, text: str) -> bytes:
    return f_bytes(field, text.encode("utf-8"))


def f_float(field: int, value: float) -> bytes:
    return key(field, FIXED32) + struct.pack("<f", value)


def packed_varints(field: int, values) -> bytes:
    return f_bytes(field, b"".join(varint(int(v)) for v in values)) if values else b""


def packed_floats(field: int, values) -> bytes:
    return f_bytes(field, b"".join(struct.pack("<f", float(v)) for v in values)) if values else b""


def dtype_enum(name) -> int:
    if isinstance(name, int):
        return name
    if name not in DTYPES:
        raise ValueError(f"unknown TensorFlow data type {name!r}")
    return DTYPES[name]


# TensorShapeProto: dim = 2 (Dim: size = 1, name = 2), unknown_rank = 3
def shape(dims, unknown_rank: bool = False) -> bytes:
    out = b"".join(f_bytes(2, f_varint(1, d) if d != 0 else b"") for d in dims)
    if unknown_rank:
        out += f_varint(3, 1)
    return out


# TensorProto: dtype = 1, tensor_shape = 2, tensor_content = 4, float_val = 5, int_val = 7,
# string_val = 8, int64_val = 10, bool_val = 11
def tensor(dtype, dims, content: bytes = b"", string_val=(), float_val=(), int_val=(),
           int64_val=(), bool_val=()) -> bytes:
    out = f_varint(1, dtype_enum(dtype)) + f_bytes(2, shape(dims))
    if content:
        out += f_bytes(4, content)
    out += packed_floats(5, list(float_val))
    out += packed_varints(7, list(int_val))
    for s in string_val:
        out += f_bytes(8, s)
    out += packed_varints(10, list(int64_val))
    out += packed_varints(11, [1 if b else 0 for b in bool_val])
    return out


# AttrValue: list = 1, s = 2, i = 3, f = 4, b = 5, type = 6, shape = 7, tensor = 8
# AttrValue.ListValue: s = 2, i = 3, f = 4, b = 5, type = 6, shape = 7, tensor = 8
class Attr:
    """An AttrValue already encoded; build with the class methods."""

    def __init__(self, encoded: bytes):
        self.encoded = encoded

    @classmethod
    def s(cls, data):
        return cls(f_bytes(2, data.encode() if isinstance(data, str) else data))

    @classmethod
    def i(cls, value):
        return cls(f_varint(3, value))

    @classmethod
    def f(cls, value):
        return cls(f_float(4, value))

    @classmethod
    def b(cls, value):
        return cls(f_varint(5, 1 if value else 0))

    @classmethod
    def type(cls, dtype):
        return cls(f_varint(6, dtype_enum(dtype)))

    @classmethod
    def shape(cls, dims, unknown_rank=False):
        return cls(f_bytes(7, shape(dims, unknown_rank)))

    @classmethod
    def tensor(cls, encoded_tensor: bytes):
        return cls(f_bytes(8, encoded_tensor))

    @classmethod
    def list(cls, s=(), i=(), f=(), b=(), type=(), shapes=(), tensors=()):
        body = b"".join(f_bytes(2, x) for x in s)
        body += packed_varints(3, list(i))
        body += packed_floats(4, list(f))
        body += packed_varints(5, [1 if x else 0 for x in b])
        body += packed_varints(6, [dtype_enum(t) for t in type])
        body += b"".join(f_bytes(7, x) for x in shapes)
        body += b"".join(f_bytes(8, x) for x in tensors)
        return cls(f_bytes(1, body))


# NodeDef: name = 1, op = 2, input = 3, device = 4, attr = 5 (map entry: key = 1, value = 2)
def node(name: str, op: str, inputs, attrs: dict) -> bytes:
    out = f_str(1, name) + f_str(2, op)
    for inp in inputs:
        out += f_str(3, inp)
    for k in sorted(attrs):
        out += f_bytes(5, f_str(1, k) + f_bytes(2, attrs[k].encoded))
    return out


# GraphDef: node = 1, versions = 4 (VersionDef: producer = 1)
def graph(encoded_nodes, producer: int) -> bytes:
    return b"".join(f_bytes(1, n) for n in encoded_nodes) + f_bytes(4, f_varint(1, producer))
