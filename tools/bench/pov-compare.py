#!/usr/bin/env python3
"""pov-compare - our picture of a scene against POV-Ray 3.7's, pixel by pixel
(docs/shading.md).

    pov-compare.py BUILD_DIR SCENE... [--size WxH] [--depth N] [--out DIR]
                   [--threshold T] [--povray PROGRAM]

Each SCENE (any of our formats) is first written as an extended .scn by
`BUILD_DIR/apps/rt-convert --extended`, so both renderers see the same
triangles; rt-export renders that .scn (2 threads), tools/bench/scn2pov.py
writes it for POV-Ray, which renders it at the same size without
anti-aliasing and with File_Gamma=1.  A pixel AGREES when each of its three
channels is within 2 levels of ours.

Agreement is given overall and AWAY FROM THE TERMINATORS, where the two
models are meant to be the same.  Masked out are the pixels where, for any
light L,
  - our N·S_L (rt-export --view ns=L, N the shading normal) is in
    (0, T) (default T = 0.15): the terminator, where POV-Ray's shadow ray
    from the hit point is caught by the neighbouring facets and ours from
    Hanika's shading point is not;
  - the shadow test differs between the scene and the same scene without
    its vertex normals (--view shadow=L of both): where our shading point
    and N_s decide E and POV-Ray's hit point and the facet would not.
For every scene, DIR (default pov-compare.out) receives NAME-ours.png,
NAME-pov.png, NAME-diff.png (|ours - POV-Ray| per channel times 8) and
NAME-mask.png (masked pixels white).  A table in Markdown goes to stdout.
"""
import argparse
import os
import subprocess
import sys
import tempfile

import scnstrip

HERE = os.path.dirname(os.path.abspath(__file__))


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    # P6, then width, height, maxval, one white-space byte
    fields = []
    pos = 2
    while len(fields) < 3:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            while data[pos:pos + 1] not in (b"\n", b""):
                pos += 1
            continue
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(int(data[start:pos]))
    assert data[:2] == b"P6" and fields[2] == 255, path
    w, h = fields[0], fields[1]
    return w, h, data[pos + 1:pos + 1 + 3 * w * h]


def write_ppm(path, w, h, pixels):
    with open(path, "wb") as f:
        f.write(b"P6\n%d %d\n255\n" % (w, h))
        f.write(bytes(pixels))


def to_png(ppm, png):
    subprocess.run(["convert", ppm, png], check=True)


def run(cmd):
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def lights_of(scn):
    """The number of lights of an extended .scn."""
    lines = []
    with open(scn, encoding="utf-8-sig") as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                lines.append(line)
    n = int(float(lines[2]))
    m = int(float(lines[3 + n]))
    return len(lines) - (4 + n + m) - 1


def compare(args, scene, tmp):
    name = os.path.splitext(os.path.basename(scene))[0]
    w, h = args.size
    scn = os.path.join(tmp, name + ".scn")
    if scene.endswith(".scn"):
        subprocess.run(["cp", scene, scn], check=True)
    else:
        run([os.path.join(args.build, "apps", "rt-convert"), "--extended",
             scene, scn])
    export = [os.path.join(args.build, "apps", "rt-export"), "-q", "-j2",
              "--size", "%dx%d" % (w, h), "--depth", str(args.depth)]
    ours = os.path.join(tmp, name + "-ours.ppm")
    run(export + [scn, "-o", ours])
    pov = os.path.join(tmp, name + ".pov")
    with open(pov, "w") as f:
        subprocess.run([sys.executable, os.path.join(HERE, "scn2pov.py"), scn,
                        str(args.depth), str(w), str(h)], check=True,
                       stdout=f)
    povpng = os.path.join(tmp, name + "-pov.png")
    subprocess.run([args.povray, "+I" + pov, "+O" + povpng, "+W%d" % w,
                    "+H%d" % h, "-D", "-A", "+WT2", "+FN8", "File_Gamma=1.0",
                    "Display_Gamma=1.0"], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    povppm = os.path.join(tmp, name + "-pov.ppm")
    # POV-Ray marks its PNG as linear (gAMA 1); the values are ours already
    subprocess.run(["convert", povpng, "-set", "colorspace", "sRGB",
                    "-depth", "8", povppm], check=True)
    _, _, a = read_ppm(ours)
    _, _, b = read_ppm(povppm)

    flat = os.path.join(tmp, name + "-flat.scn")
    scnstrip.strip(scn, flat, normals=True, highlights=False)
    mask = bytearray(w * h)
    threshold = round(255 * args.threshold)
    for light in range(lights_of(scn)):
        v = os.path.join(tmp, "view.ppm")
        run(export + ["--view", "ns=%d" % light, scn, "-o", v])
        _, _, ns = read_ppm(v)
        for i in range(w * h):
            if 0 < ns[3 * i] < threshold:
                mask[i] = 1
        run(export + ["--view", "shadow=%d" % light, scn, "-o", v])
        _, _, s1 = read_ppm(v)
        run(export + ["--view", "shadow=%d" % light, flat, "-o", v])
        _, _, s2 = read_ppm(v)
        for i in range(w * h):
            if s1[3 * i:3 * i + 3] != s2[3 * i:3 * i + 3]:
                mask[i] = 1

    agree = kept = kept_agree = 0
    diff = bytearray(3 * w * h)
    worst = 0
    for i in range(w * h):
        d = [abs(a[3 * i + c] - b[3 * i + c]) for c in range(3)]
        for c in range(3):
            diff[3 * i + c] = min(255, 8 * d[c])
        ok = max(d) <= 2
        agree += ok
        if not mask[i]:
            kept += 1
            kept_agree += ok
            worst = max(worst, max(d))
    os.makedirs(args.out, exist_ok=True)
    base = os.path.join(args.out, name)
    to_png(ours, base + "-ours.png")
    to_png(povppm, base + "-pov.png")
    write_ppm(os.path.join(tmp, "d.ppm"), w, h, diff)
    to_png(os.path.join(tmp, "d.ppm"), base + "-diff.png")
    write_ppm(os.path.join(tmp, "m.ppm"), w, h,
              bytes(255 * mask[i // 3] for i in range(3 * w * h)))
    to_png(os.path.join(tmp, "m.ppm"), base + "-mask.png")
    total = w * h
    return (name, total, 100.0 * agree / total, total - agree,
            100.0 * (total - kept) / total,
            100.0 * kept_agree / kept if kept else 100.0, kept - kept_agree,
            worst)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("build")
    p.add_argument("scenes", nargs="+")
    p.add_argument("--size", default="320x240")
    p.add_argument("--depth", type=int, default=5)
    p.add_argument("--out", default="pov-compare.out")
    p.add_argument("--threshold", type=float, default=0.15)
    p.add_argument("--povray", default="povray")
    args = p.parse_args()
    args.size = tuple(int(x) for x in args.size.split("x"))
    print("| scene (%dx%d) | pixels | agree overall | differ | masked | "
          "agree away from terminators | differ there | largest difference "
          "there |" % args.size)
    print("|---|--:|--:|--:|--:|--:|--:|--:|")
    with tempfile.TemporaryDirectory() as tmp:
        for scene in args.scenes:
            r = compare(args, scene, tmp)
            print("| %s | %d | %.2f %% | %d | %.2f %% | %.2f %% | %d | %d |"
                  % r)
            sys.stdout.flush()


if __name__ == "__main__":
    main()
