#!/usr/bin/env python3
"""compare.py - compares two PPM images pixel by pixel.

Usage: python3 tests/reference/compare.py A.ppm B.ppm [--list N]

Reads P3 or P6 (maxval 255, comments allowed in the header), prints the
number of differing pixels, the largest channel difference and the first
few differing pixels as "x y: (r,g,b) vs (r,g,b)".  Exit status: 0 when the
images are identical, 1 when they differ, 2 when they cannot be compared
(unreadable file, different sizes).  Standard library only.
"""

import sys


def read_ppm(path):
    with open(path, 'rb') as f:
        data = f.read()
    pos = 0
    tokens = []

    def next_token():
        nonlocal pos
        while True:
            while pos < len(data) and data[pos:pos + 1].isspace():
                pos += 1
            if data[pos:pos + 1] == b'#':
                while pos < len(data) and data[pos:pos + 1] not in b'\r\n':
                    pos += 1
                continue
            break
        start = pos
        while pos < len(data) and not data[pos:pos + 1].isspace() \
                and data[pos:pos + 1] != b'#':
            pos += 1
        return data[start:pos]

    magic = next_token()
    if magic not in (b'P3', b'P6'):
        raise ValueError('%s: not a P3/P6 PPM' % path)
    w, h, maxval = int(next_token()), int(next_token()), int(next_token())
    if maxval != 255:
        raise ValueError('%s: maxval %d, expected 255' % (path, maxval))
    if magic == b'P6':
        pos += 1                       # the single white-space character
        pixels = data[pos:pos + 3 * w * h]
        if len(pixels) != 3 * w * h:
            raise ValueError('%s: truncated' % path)
    else:
        pixels = bytes(int(next_token()) for _ in range(3 * w * h))
    return w, h, pixels


def main(argv):
    listed = 10
    args = []
    it = iter(argv[1:])
    for arg in it:
        if arg == '--list':
            listed = int(next(it))
        else:
            args.append(arg)
    if len(args) != 2:
        sys.stderr.write('usage: compare.py A.ppm B.ppm [--list N]\n')
        return 2
    try:
        wa, ha, pa = read_ppm(args[0])
        wb, hb, pb = read_ppm(args[1])
    except (OSError, ValueError) as e:
        sys.stderr.write('compare.py: %s\n' % e)
        return 2
    if (wa, ha) != (wb, hb):
        print('sizes differ: %dx%d vs %dx%d' % (wa, ha, wb, hb))
        return 2
    count, worst, shown = 0, 0, []
    for index in range(wa * ha):
        a = pa[3 * index:3 * index + 3]
        b = pb[3 * index:3 * index + 3]
        if a != b:
            count += 1
            worst = max(worst, max(abs(x - y) for x, y in zip(a, b)))
            if len(shown) < listed:
                shown.append('  %d %d: (%d,%d,%d) vs (%d,%d,%d)'
                             % ((index % wa, index // wa) + tuple(a)
                                + tuple(b)))
    print('%d differing pixels of %d, max channel difference %d'
          % (count, wa * ha, worst))
    for line in shown:
        print(line)
    return 0 if count == 0 else 1


if __name__ == '__main__':
    sys.exit(main(sys.argv))
