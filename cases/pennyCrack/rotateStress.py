#!/usr/bin/python3
"""Prints the remote stress of the rotated penny case: sigma' = R sigma R^T.

Usage: rotateStress.py RX RY RZ [sxx syy szz sxy syz sxz]
RX RY RZ [deg]: the rotation of constant/mesh/pennyCrack.geo (about x, then y, then z:
R = Rz Ry Rx), the six components [Pa] default to the case's constant/effects. Prints the
six rotated components in the order of constant/effects' `stress (sxx syy szz sxy syz sxz)`.
For the invariance check: ./Allmesh -rx RX -ry RY -rz RZ, put the printed stress into
constant/effects, run; the slip vectors are R times the unrotated case's (pennyError.py
prints the same errors).
"""
import math
import sys

import numpy as np

if len(sys.argv) not in (4, 10):
    print(__doc__, file=sys.stderr)
    sys.exit(2)
try:
    rx, ry, rz = (math.radians(float(v)) for v in sys.argv[1:4])
    s = [float(v) for v in sys.argv[4:]] or [-12e6, -8e6, -10e6, 1e6, 3.6e6, 4.8e6]
except ValueError as e:
    print(f"rotateStress.py: {e}", file=sys.stderr)
    sys.exit(2)


def rot(axis, t):
    c, s_ = math.cos(t), math.sin(t)
    i, j = [(1, 2), (2, 0), (0, 1)][axis]
    R = np.eye(3)
    R[i, i], R[i, j], R[j, i], R[j, j] = c, -s_, s_, c
    return R


R = rot(2, rz) @ rot(1, ry) @ rot(0, rx)
S = np.array([[s[0], s[3], s[5]], [s[3], s[1], s[4]], [s[5], s[4], s[2]]])
Sr = R @ S @ R.T
print("stress  (" + " ".join(f"{v:.17g}" for v in
                             (Sr[0, 0], Sr[1, 1], Sr[2, 2], Sr[0, 1], Sr[1, 2], Sr[0, 2])) + ");")
