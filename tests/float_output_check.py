#!/usr/bin/env python3
"""rt-export's PFM read with Python's struct against its PPM.

Usage: float_output_check.py RT_EXPORT SCENES_DIR.  For each scene, renders
-o x.pfm and -o x.ppm in a temporary folder and checks that every float,
times 255, rounded as the renderer rounds (clamped to 0..255, halves away
from zero), is the PPM's byte, and that the teapot's highlights exceed 1.0.
Exits 0, or 1 with the first difference.
"""
import os
import struct
import subprocess
import sys
import tempfile


def read_pfm(path):
    data = open(path, "rb").read()
    magic, size, scale, rest = data.split(b"\n", 3)
    assert magic == b"PF", magic
    width, height = map(int, size.split())
    assert float(scale) < 0, "not little-endian"
    values = struct.unpack("<%df" % (width * height * 3), rest)
    rows = [values[(height - 1 - y) * width * 3:(height - y) * width * 3]
            for y in range(height)]          # bottom row first in the file
    return width, height, [v for row in rows for v in row]


def read_ppm(path):
    data = open(path, "rb").read()
    magic, size, maxval, rest = data.split(b"\n", 3)
    assert magic == b"P6" and maxval == b"255"
    width, height = map(int, size.split())
    return width, height, rest


def to_byte(value):
    if not value > 0.0:
        return 0
    if value >= 255.0:
        return 255
    return int(value + 0.5)


def main():
    program, scenes = sys.argv[1], sys.argv[2]
    above = {}
    with tempfile.TemporaryDirectory() as folder:
        for scene in ("cubes.scn", "teapot.scn", "glass.scn"):
            for ext in ("pfm", "ppm"):
                subprocess.run([program, "-q", os.path.join(scenes, scene),
                                "-o", os.path.join(folder, "x." + ext)],
                               check=True, stdout=subprocess.DEVNULL)
            w, h, floats = read_pfm(os.path.join(folder, "x.pfm"))
            pw, ph, data = read_ppm(os.path.join(folder, "x.ppm"))
            assert (w, h) == (pw, ph), (scene, w, h, pw, ph)
            for i, value in enumerate(floats):
                if to_byte(255.0 * value) != data[i]:
                    print("%s: value %d: %.9g rounds to %d, the PPM has %d"
                          % (scene, i, value, to_byte(255.0 * value),
                             data[i]))
                    return 1
            above[scene] = sum(1 for v in floats if v > 1.0)
            print("%s: %d x %d, %d values above 1.0" % (scene, w, h,
                                                         above[scene]))
    if above["teapot.scn"] == 0:
        print("teapot.scn: no value above 1.0 (clamped?)")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
