#!/usr/bin/env python3
"""Writes shard_outputs.jsonl for shard_cases.jsonl: the shadow matrix M = (P.L) I - L P^T of
every case evaluated naively in float32 (each product and difference rounded to float), so near
a parallel light it loses accuracy, plus two planted defects: case 8 (regular) has a NaN entry and case 13 (near-degenerate)
its entry (0,0) replaced by 1000 ulps more. Lines are written
in a shuffled order (fixed seed): graders must not depend on the order of the answers."""
import json
import math
import random
import struct
import sys


def f32(x):
    try:
        return struct.unpack("f", struct.pack("f", x))[0]
    except OverflowError:  # beyond the largest float: rounds to infinity
        return math.copysign(math.inf, x)


def next_up(x, n):
    bits = struct.unpack("I", struct.pack("f", x))[0]
    return struct.unpack("f", struct.pack("I", bits + n if x >= 0 else bits - n))[0]


def token(v):
    if v != v:
        return '"nan"'
    if v in (float("inf"), float("-inf")):
        return '"inf"' if v > 0 else '"-inf"'
    return repr(v)


lines = []
for text in open(sys.argv[1]):
    case = json.loads(text)
    p = [float.fromhex(v) for v in case["plane"]]
    l = [float.fromhex(v) for v in case["light"]]
    s = f32(f32(f32(f32(p[0] * l[0]) + f32(p[1] * l[1])) + f32(p[2] * l[2])) + f32(p[3] * l[3]))
    m = [f32((s if i == j else 0.0) - f32(l[i] * p[j])) for i in range(4) for j in range(4)]
    if case["id"] == 8:
        m[5] = float("nan")
    if case["id"] == 13:
        m[0] = next_up(m[0], 1000)
    lines.append('{"id": %d, "output": [%s]}' % (case["id"], ", ".join(token(v) for v in m)))
random.Random(4).shuffle(lines)
print("\n".join(lines))
